"""Run one step of the Snakemake workflow: a library function called with the rule's files and parameters.

Every computing rule of ``workflow/rules/`` runs ``workflow/scripts/step.py``,
which calls :func:`run_step`.  The rule's ``params.step`` names the function
(``"module:function"``); its named ``input``, ``output`` and ``params`` (except
``step``, the ``library`` input that lists the code the step depends on, and
the ``paper`` input, the paper's printed values, which the step reads as package data)
are passed as keyword arguments of the same names.  So the rule declares
exactly what the step reads and computes with, and Snakemake reruns the step
when any of it changes.

Before the function's module is imported, ``NUMBA_NUM_THREADS`` is set to the
rule's ``threads``.  The step's output (progress, messages) goes to the
rule's log file.  A :class:`~stickslip.errors.StickslipError` (a user's
mistake) ends the step with one line naming the problem and exit code 2.
"""

from __future__ import annotations

import contextlib
import importlib
import os
import sys

#: Named inputs and parameters that are not arguments of the step's function.
NOT_ARGUMENTS = ("library", "paper", "step")


def step_arguments(snakemake) -> dict:
    """The keyword arguments of the step: the rule's named input, output and params."""
    arguments = {}
    for files in (snakemake.input, snakemake.output, snakemake.params):
        arguments.update({name: value for name, value in files.items() if name not in NOT_ARGUMENTS})
    return arguments


def run_step(snakemake) -> None:
    """Call the function named by ``snakemake.params.step`` with :func:`step_arguments`; exit 2 on a user error."""
    os.environ["NUMBA_NUM_THREADS"] = str(max(1, int(snakemake.threads)))
    from stickslip.errors import StickslipError

    module_name, function_name = snakemake.params.step.split(":")
    log = open(snakemake.log[0], "w", encoding="utf-8") if snakemake.log else sys.stderr
    with log, contextlib.redirect_stdout(log), contextlib.redirect_stderr(log):
        try:
            function = getattr(importlib.import_module(module_name), function_name)
            written = function(**step_arguments(snakemake))
        except StickslipError as error:
            print(f"stickslip: error: {error}", file=log)
            print(f"stickslip: error: {error}", file=sys.__stderr__)
            sys.exit(2)
        for path in written if isinstance(written, list) else [written]:
            print(path)
