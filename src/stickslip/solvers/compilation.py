"""Compiling a module's kernels with numba so that they call each other compiled."""

from __future__ import annotations

import types


def compiled_kernels(module, names, **options) -> dict:
    """``numba.njit(**options)`` of each function of ``module`` named in ``names``, by name.

    Each is compiled from a copy of the function whose globals are a copy of
    the module's in which those names are the compiled functions: numba
    resolves a kernel's globals when it compiles it, so the kernels call each
    other compiled while the module's own functions stay plain Python.
    """
    import numba

    namespace = dict(vars(module))
    for name in names:
        function = namespace[name]
        namespace[name] = numba.njit(**options)(
            types.FunctionType(function.__code__, namespace, name, function.__defaults__, function.__closure__)
        )
    return {name: namespace[name] for name in names}
