"""Physical constants fixed by the project (see docs/definitions.md)."""

#: Gravitational acceleration used by the paper and by default here [m/s²].
STANDARD_GRAVITY = 9.81

#: Block mass of the paper's lead block and of its numerical study [kg].
PAPER_BLOCK_MASS = 5.10
