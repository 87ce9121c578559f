"""The record report notebook: rendered as a page, its parameters checked, its title.

The notebook is package data (``stickslip/reports/notebooks/record_report.ipynb``;
``notebooks/record_report.ipynb`` of a checkout links to it), so that an
installed stickslip renders it without the checkout.

:func:`render_record_report` executes the notebook with papermill in a
temporary folder and returns it as one HTML page without code
(:mod:`stickslip.reports.notebook_page`); ``stickslip report`` calls it.
Inside the notebook, a mistake in a parameter is named as the notebook's
parameter (``-p dt``), never as the command line's option (``--dt``), and
shows as one line (:func:`one_line_errors`) instead of a traceback through
the library.
"""

from __future__ import annotations

import logging
import math
import tempfile
from collections.abc import Mapping
from pathlib import Path

from stickslip import errors
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordNotFoundError, StickslipError
from stickslip.grids import COEFFICIENTS, checked_range, positive_increasing, range_values
from stickslip.optimum import DEFAULT_MU, DEFAULT_Q, MIN_RANGE_POINTS, checked_q, checked_reference
from stickslip.records.components import component_label
from stickslip.records.readers import ARGUMENT_IN_MESSAGE
from stickslip.records.record import Record, RecordMeta

#: The notebook, shipped as package data (``notebooks/record_report.ipynb`` of a checkout links to it).
NOTEBOOK = Path(__file__).resolve().parent / "notebooks" / "record_report.ipynb"

#: The report's figures, ``{record}_{name}.png``, and their alternative texts ({record}: the record's name).
#: The notebook shows them with these texts; the workflow's page declaration lists the same figures.
FIGURES = {
    "energy_vs_mu": "{record}: energy dissipated by friction against the friction ratio",
    "displacement_vs_mu": "{record}: stroke and residual displacement against the friction ratio",
    "design_chart": "{record}: design chart over the friction ratio and the model's other design parameter (the "
                    "surface radius of a friction pendulum or an isolated building, a damper's mass ratio): its "
                    "demands, or its objective and stroke, in contours",
    "acceleration": "{record}: ground acceleration and Husid curve against time",
    "response": "{record}: response of block and base against time at the case's friction ratio",
}


#: The figures of the page of a pair of horizontal components (``second``: the friction pendulum in the plane): the
#: record's, the acceleration of each component, and the response with the slider's path in the plane.
PAIR_FIGURES = {**FIGURES,
                "acceleration": "{record}: ground acceleration of each component against time",
                "response": "{record}: displacement of the slider along each component and energies against time, and "
                            "its path in the plane, at the case's friction ratio"}


def figure_alts(record: str, pair: bool = False) -> dict[str, str]:
    """The report's figure file names for ``record`` (its name; with ``pair``, a pair's page) and their
    alternative texts."""
    return {f"{record}_{name}.png": alt.format(record=record) for name, alt in (PAIR_FIGURES if pair else
                                                                                FIGURES).items()}


class ParameterError(StickslipError):
    """A notebook parameter with a value the report cannot use."""


def check_positive(value, name: str) -> float:
    """``value`` as a finite positive float; else a :class:`ParameterError` naming ``name``."""
    number = _number(value, name)
    if not math.isfinite(number) or number <= 0:
        raise ParameterError(f"{name} {value!r}: expected a positive number")
    return number




def report_settings(record, mu_start, mu_stop, mu_step, mu_case, reference_mu, near_optimal_fraction, mass,
                    g, range_points=None, chart_values=None, chart_levels=None, model=None) -> dict:
    """The notebook's parameters checked, with ``stickslip optimum``'s defaults for those left None.

    Returns ``mu`` (the friction grid [1], built from ``mu_start``,
    ``mu_stop`` and ``mu_step`` as ``--mu START:STOP:STEP`` builds it; by
    default :data:`stickslip.optimum.DEFAULT_MU`), ``q`` (default
    :data:`~stickslip.optimum.DEFAULT_Q`), ``reference_mu`` (default
    :data:`~stickslip.grids.COEFFICIENTS`' ``reference``), ``range_points`` (the
    fewest grid values of the near-optimal range, default
    :data:`~stickslip.optimum.MIN_RANGE_POINTS`), ``mu_case`` [1] (None:
    the record's continuous μ_max, which the notebook finds) and
    ``chart_values`` (the values of the design chart's other coordinate
    beside μ, the model's :attr:`~stickslip.models.entry.Model.chart_over`;
    None: the model's own) and ``chart_levels`` (its levels, a
    :class:`~stickslip.reports.isolator_plots.ChartLevels` every step of
    ``chart_levels``, [colours, lines], each in the units of the quantity
    the ``model``'s chart draws, :meth:`~stickslip.models.entry.Model.chart_quantities`;
    None: the round defaults).  A bad one raises :class:`ParameterError` naming
    ``-p <parameter>`` (and, for the levels, the quantities of the ``model`` named).
    """
    if record is None:
        raise ParameterError("no record given: pass -p record PATH (a record file, or a record .nc the workflow wrote)")
    start, stop, step = (DEFAULT_MU[end] if value is None else check_positive(value, f"-p mu_{end}")
                         for end, value in (("start", mu_start), ("stop", mu_stop), ("step", mu_step)))
    for name, value in (("mass", mass), ("g", g)):
        check_positive(value, f"-p {name}")
    try:
        mu = range_values(*checked_range(start, stop, step, f"-p mu_start {start!r}, -p mu_stop {stop!r}, "
                                         f"-p mu_step {step!r}", "friction ratios", min_values=3))
        q = DEFAULT_Q if near_optimal_fraction is None else checked_q(
            _number(near_optimal_fraction, "-p near_optimal_fraction"), "-p near_optimal_fraction")
        reference = COEFFICIENTS["mu"].reference if reference_mu is None else checked_reference(
            _number(reference_mu, "-p reference_mu"), "mu", "-p reference_mu")
    except StickslipError as error:  # the grid's and the optimum's own checks, named as the notebook's parameters
        raise ParameterError(str(error)) from None
    points = MIN_RANGE_POINTS if range_points is None else _number(range_points, "-p range_points")
    if not (points >= 0 and float(points).is_integer()):
        raise ParameterError(f"-p range_points {range_points!r}: expected a whole number of grid values, 0 or more")
    try:
        values = None if chart_values is None else positive_increasing(chart_values, "-p chart_values")
    except StickslipError as error:
        raise ParameterError(str(error)) from None
    return {"mu": mu, "q": q, "reference_mu": reference, "range_points": int(points),
            "mu_case": None if mu_case is None else check_positive(mu_case, "-p mu_case"), "chart_values": values,
            "chart_levels": _chart_levels(chart_levels, model)}


def _chart_levels(steps, model: str | None):
    """The design chart's :class:`~stickslip.reports.isolator_plots.ChartLevels` every ``steps`` (of its colours and
    its lines, in their quantities' units), or the default levels for None; else a :class:`ParameterError` naming
    ``-p chart_levels`` and the quantities of the ``model``'s chart (when it names one that draws a chart)."""
    from stickslip.models import MODELS
    from stickslip.reports.isolator_plots import ChartLevels

    if steps is None:
        return ChartLevels()
    charted = MODELS[model] if model in MODELS and MODELS[model].chart_over else None
    quantities = charted.chart_quantities() if charted else ("colours' quantity", "lines' quantity")
    numbers = [_number(step, "-p chart_levels") for step in steps] if isinstance(steps, (list, tuple)) else []
    if len(numbers) != 2:
        described = (f" of the {model} model's chart: the {quantities[0]}'s and "
                     + (f"the {quantities[1]}'s" if quantities[1] else "none, no lines drawn") if charted else "")
        raise ParameterError(f"-p chart_levels {steps!r}: expected two steps, [colours, lines]{described}")
    try:
        return ChartLevels.every(*numbers, quantities=quantities)
    except StickslipError as error:
        raise ParameterError(f"-p chart_levels {steps!r}: {error}") from None


def _number(value, name: str) -> float:
    """``value`` as a float; else a :class:`ParameterError` naming ``name``."""
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} {value!r}: expected a number") from None


def read_report_record(record: str | Path, format=None, dt=None, units=None, g: float = STANDARD_GRAVITY,
                       accept_zero: bool = False) -> tuple[Record | None, str | None]:
    """The report's record and, for a record the workflow could not obtain, why it is missing.

    ``record`` is a record file (read by :func:`stickslip.read_record` with
    ``format``, ``dt`` [s], ``units``, values in g converted with ``g``
    [m/s²], all zero accepted with ``accept_zero``), a record NetCDF file the
    workflow or ``stickslip records fetch`` wrote among them
    (``results/records/{id}.nc``), which may hold a missing record's status:
    then ``(None, reason)``.  A file that cannot be read raises
    :class:`ParameterError` naming the notebook's parameters.
    """
    from stickslip.records.readers import read_record

    source = Path(record)
    try:
        return read_record(source, format=format, dt=dt, units=units, g=g, accept_zero=accept_zero), None
    except RecordNotFoundError as error:
        return None, str(error)
    except StickslipError as error:
        raise ParameterError(ARGUMENT_IN_MESSAGE.sub(r"-p \1", str(error))) from None


def with_vertical(horizontal: Record, vertical, format=None, dt=None, units=None, positive=None, pad: bool = False,
                  any_vertical: bool = False):
    """``horizontal`` with the vertical component of the file ``vertical`` (read as :func:`read_report_record`
    reads, its sense read from its label unless ``positive`` says; ``any_vertical``: taken although its names say it
    is not the same station's vertical), or ``horizontal`` alone when ``vertical`` is None; a mistake raises
    :class:`ParameterError` naming the notebook's parameters."""
    from stickslip.records.vertical import WithVertical

    if vertical is None:
        return horizontal
    found, missing = read_report_record(vertical, format, dt, units)
    if missing:
        raise ParameterError(f"-p vertical {vertical}: {missing}")
    try:
        return WithVertical.of(horizontal, found, positive, pad=pad, any_vertical=any_vertical)
    except StickslipError as error:
        message = ARGUMENT_IN_MESSAGE.sub(r"-p \1", str(error))
        for option in ("vertical_positive", "any_vertical"):
            message = message.replace(f"--{option.replace('_', '-')}", f"-p {option}")
        raise ParameterError(message) from None


def report_title(record_id: str, meta: RecordMeta | None = None) -> str:
    """The report's title: the record id, and its event, station and component where they are known."""
    described = ", ".join(part for part in (meta.event, " ".join(filter(None, (meta.station,
                                                                            component_label(meta.component)))))
                          if part) if meta else ""
    return f"Record report: {record_id}" + (f" ({described})" if described else "")


def one_line_errors() -> None:
    """In the running IPython kernel, show a :class:`~stickslip.errors.StickslipError` as one line, no traceback.

    The cell still fails (papermill stops and reports it); any other
    exception keeps its traceback.
    """
    from IPython import get_ipython

    def show(shell, kind, value, traceback, tb_offset=None):
        shell._showtraceback(kind, value, [f"{kind.__name__}: {value}"])  # the kernel's hook that reports an error

    get_ipython().set_custom_exc((StickslipError,), show)


def render_record_report(parameters: Mapping) -> str:
    """The record report for the notebook's ``parameters`` (``record``, ``mu_start``, ...) as one HTML page."""
    return render_report(NOTEBOOK, {**parameters, "save_sweep": False})


def render_report(notebook: Path, parameters: Mapping) -> str:
    """The report ``notebook`` (package data) run with ``parameters``, as one HTML page without code.

    The notebook runs with papermill on the Jupyter kernel ``python3`` in a
    temporary folder (its ``output_dir``), which is removed afterwards (its
    figures are embedded in the page), quietly: no progress bar, no kernel
    log (the caller says which page it renders).  A user's mistake that the notebook meets raises
    :class:`~stickslip.errors.StickslipError` with the notebook's one-line
    message; Ctrl-C in the notebook raises :class:`KeyboardInterrupt`;
    anything else is a bug and keeps papermill's report.
    """
    try:
        import papermill
    except ImportError:
        raise StickslipError("the report needs papermill, ipykernel and nbconvert: "
                             "pip install 'stickslip[report]'") from None
    from stickslip.reports.notebook_page import notebook_html

    with tempfile.TemporaryDirectory(prefix="stickslip-report-") as folder:
        try:
            executed = papermill.execute_notebook(
                str(notebook), str(Path(folder) / Path(notebook).name),
                parameters={**parameters, "output_dir": folder}, kernel_name="python3",
                progress_bar=False, request_save_on_cell_execute=False,
                extra_arguments=["--IPKernelApp.log_level=CRITICAL"])  # a cell's error comes as its output
        except papermill.PapermillExecutionError as error:
            if error.ename == "KeyboardInterrupt":
                _quiet_kernel_shutdown()
                raise KeyboardInterrupt from None
            kind = getattr(errors, error.ename, None)
            if isinstance(kind, type) and issubclass(kind, StickslipError):
                raise StickslipError(error.evalue) from None
            raise
        except KeyboardInterrupt:
            _quiet_kernel_shutdown()
            raise
    return notebook_html(executed)


def _quiet_kernel_shutdown() -> None:
    """After Ctrl-C: the interrupted kernel's clean-up prints no messages ("Kernel died", "Task exception was never
    retrieved"), so that the command's one line saying it was interrupted is the last."""
    for name in ("asyncio", "papermill", "nbclient", "traitlets"):
        logging.getLogger(name).setLevel(logging.CRITICAL + 1)
