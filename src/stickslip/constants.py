"""Physical constants fixed by the project (see docs/definitions.md)."""

#: Gravitational acceleration used by the paper and by default here [m/s²].
STANDARD_GRAVITY = 9.81

#: Block mass [kg] when none is given: a unit mass, so that every energy is one per kg of the block (energies scale
#: with the mass; the paper's lead block, 5.1 kg, is the workflow's ``block_mass``).
DEFAULT_BLOCK_MASS = 1.0

#: The damping ratio of response spectra unless one is given [1] (5 % of critical).
DEFAULT_DAMPING = 0.05
