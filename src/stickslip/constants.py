"""Physical constants fixed by the project (see docs/definitions.md)."""

#: Gravitational acceleration used by the paper and by default here [m/s²].
STANDARD_GRAVITY = 9.81

#: Block mass of the paper's lead block and of its numerical study [kg].
PAPER_BLOCK_MASS = 5.10

#: The damping ratio of response spectra unless one is given [1] (5 % of critical).
DEFAULT_DAMPING = 0.05
