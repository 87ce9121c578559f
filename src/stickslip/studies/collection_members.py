"""Which records of a collection study enter its fits and statistics: :mod:`stickslip.collections.members`,
named here too for the study's notebook."""

from stickslip.collections.members import GROUPS, left_out, studied, too_few  # noqa: F401

__all__ = ["GROUPS", "left_out", "studied", "too_few"]
