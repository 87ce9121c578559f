"""Exceptions for mistakes in user input.

Every error that a user can cause (a bad file, an unknown option value, a
record that cannot be found) is raised as a :class:`StickslipError`.  The
command line turns it into one line on stderr and exit code 2; everything
else is a bug and keeps its traceback.
"""

from __future__ import annotations

from pathlib import Path


class StickslipError(Exception):
    """A problem with the user's input, reported without a traceback."""


class RecordError(StickslipError):
    """A ground-motion record file that cannot be read or fails validation.

    Parameters
    ----------
    source:
        The file (or record id) the problem is in.
    problem:
        What is wrong, and where it helps, what was expected.
    """

    def __init__(self, source: str | Path, problem: str):
        self.source = str(source)
        self.problem = problem
        super().__init__(f"{self.source}: {problem}")


class RecordNotFoundError(StickslipError):
    """A record that no acquisition source could provide."""


class StickslipWarning(UserWarning):
    """Input that is readable but unusual (a time step of 1e6 s); the command line prints one line for it."""
