"""What every model's result is: end results with units, histories as a dataset, the energy ledger, whether it slid.

:class:`Result` is the base of every model's result type (the rigid block's
:class:`~stickslip.models.rigid.response.Response`, the flexible block's
:class:`~stickslip.models.layer.result.FlexibleResult`, the planar block's
:class:`~stickslip.models.planar.response.PlanarResponse` …), so that
:func:`stickslip.solve`'s callers, the command line and the reports treat
them alike: :meth:`Result.scalars` with :meth:`Result.scalar_units` from the
one units table (:data:`stickslip.units.UNITS`), :meth:`Result.to_xarray`,
:meth:`Result.energy_ledger` where the scheme keeps one, and
:attr:`Result.never_slides`, why the block did not slide (so that no caller
rebuilds a grid to tell it).

A result *declares* its end results (:attr:`Result.scalar_table`), its
histories (:attr:`Result.history_table`) and its energy ledger's terms
(:attr:`Result.ledger_terms`); from that declaration the base gives
:meth:`Result.scalars` (from a kernel's end results per unit mass),
:meth:`Result.scalar_units`, :meth:`Result.scalar_attrs`,
:meth:`Result.energy_ledger` and :meth:`Result.to_xarray`, so that a model's
result keeps only what is its own: its histories' values, its case in words
and as numbers, and why its block did not slide.
"""

from __future__ import annotations

import numpy as np

from stickslip.checks import whole_count
from stickslip.plumbing.files import provenance
# the codes of a history's ``phase`` that every model shares (the engine's): the block sticks to its base, or (a
# pendulum's slider under a vertical motion) has lifted off its surface; sliding is any other code (±1)
from stickslip.solvers.events import FLIGHT, STICK
from stickslip.units import CF_CONVENTIONS, UNITS


class Result:
    """One solved case of a sliding-block model.

    A subclass provides :attr:`model`, :attr:`method`, :meth:`describe`,
    :meth:`case` and :attr:`never_slides`, and either declares
    :attr:`scalar_table`, :attr:`history_table` and :attr:`ledger_terms` and
    gives :meth:`end_values`, :meth:`histories` and :attr:`time` (the base
    does the rest), or provides :meth:`scalars`, :meth:`to_xarray` and
    :meth:`energy_ledger` itself.
    """

    #: The model solved (``"rigid"``, ``"coupled"`` …) and the scheme that solved it.
    model: str
    method: str

    #: The end results it declares, in order: name -> (unit in UDUNITS spelling, long name).
    scalar_table: dict[str, tuple[str, str]] = {}
    #: The histories it declares: name -> (unit, long name); :meth:`histories` gives their values at the samples.
    history_table: dict[str, tuple[str, str]] = {}
    #: The energy ledger's terms, names of :meth:`histories` in order; none where the scheme keeps no ledger. A term
    #: that :attr:`history_table` does not declare is in the ledger only, not in :meth:`to_xarray`.
    ledger_terms: tuple[str, ...] = ()
    #: Whether :meth:`end_values` gives energies per unit mass (the kernels' own), which :meth:`scalars` multiplies
    #: by :attr:`mass`; False where they are for the mass already.
    per_unit_mass: bool = True
    #: The end results that are whole counts (an int in :meth:`scalars`).
    counts: tuple[str, ...] = ("n_slip_episodes",)
    #: Whether :meth:`to_xarray` keeps the end results as attributes (``name`` and ``name_units``) rather than as
    #: variables.
    scalars_as_attributes: bool = False
    #: The attributes of :meth:`to_xarray`'s ``time`` coordinate.
    time_attrs: dict[str, str] = {"units": UNITS["time"]}
    #: How the record report draws the response: ``"relative"`` (the block's ``relative_displacement`` against
    #: time, sliding shaded where the histories have a ``phase``, over the energy ledger), ``"absolute"`` (the
    #: absolute motion of block and base, the paper's Fig. 3) or ``"path"`` (the displacement along each
    #: ``component`` over the ledger, the path in the plane beside); :attr:`response_panels` where declared instead.
    response_figure: str = "relative"
    #: The record report's response panels, where the result is none of :attr:`response_figure`'s: each
    #: (y label, history names drawn against time); empty: :attr:`response_figure`.
    response_panels: tuple[tuple[str, tuple[str, ...]], ...] = ()
    #: The record report's hysteresis loop beside them: (x history, y history, title); None: none.
    hysteresis: tuple[str, str, str] | None = None

    def end_values(self) -> dict[str, float]:
        """The end results by the names of :attr:`scalar_table` (all but ``balance_residual``, which
        :meth:`scalars` takes from the ledger): the kernel's, energies per unit mass unless :attr:`per_unit_mass`
        is False."""
        raise NotImplementedError

    def histories(self) -> dict[str, np.ndarray]:
        """The values of :attr:`history_table`'s histories at the samples (energies for :attr:`mass`), on ``time``
        or, a vector's two components, on ``time`` and ``component``; one that the case lacks is left out."""
        raise NotImplementedError

    def scalars(self) -> dict[str, float | int]:
        """The end results of :attr:`scalar_table`, in its order: :meth:`end_values`, energies [J] times
        :attr:`mass` [kg] where they are :attr:`per_unit_mass`, ``balance_residual`` the largest |residual| of
        :meth:`energy_ledger` [J] and :attr:`counts` whole counts."""
        kernel = self.end_values()
        values = {name: float(kernel[name]) * (self.mass if unit == "J" and self.per_unit_mass else 1.0)
                  for name, (unit, _) in self.scalar_table.items() if name != "balance_residual"}
        if "balance_residual" in self.scalar_table:
            values["balance_residual"] = float(np.max(np.abs(self.energy_ledger()["balance_residual"])))
        for name in set(self.counts) & set(values):
            values[name] = whole_count(values[name])
        return {name: values[name] for name in self.scalar_table}

    def scalar_units(self) -> dict[str, str]:
        """The unit of each of :meth:`scalars`, UDUNITS spelling: :attr:`scalar_table`'s, else from
        :data:`stickslip.units.UNITS`."""
        if self.scalar_table:
            return {name: unit for name, (unit, _) in self.scalar_table.items()}
        return {name: UNITS[name] for name in self.scalars()}

    def scalar_attrs(self) -> dict[str, tuple[str, str]]:
        """The unit and long name of each of :meth:`scalars` (the tables of reports): :attr:`scalar_table`, else
        the unit of :meth:`scalar_units` and the name in words."""
        if self.scalar_table:
            return dict(self.scalar_table)
        return {name: (units, name.replace("_", " ")) for name, units in self.scalar_units().items()}

    def to_xarray(self):
        """The histories and end results as an :class:`xarray.Dataset` on ``time`` [s] (and ``component``), with
        units, long names and the case solved.

        Each of :meth:`histories` that :attr:`history_table` declares, with its unit and long name; each of
        :meth:`scalars` that is not a history's last value under the same name (or, :attr:`scalars_as_attributes`,
        each as the attributes ``name`` and ``name_units``); then :meth:`more_variables`. The attributes are the
        :meth:`title`, the CF conventions, :meth:`dataset_attrs`, :meth:`case_attrs`, those end results and the
        provenance.
        """
        import xarray as xr

        variables = {name: (("time",) if np.ndim(values) == 1 else ("time", "component"), np.asarray(values),
                            {"units": self.history_table[name][0], "long_name": self.history_table[name][1]})
                     for name, values in self.histories().items() if name in self.history_table}
        dataset = xr.Dataset(variables, coords={"time": ("time", self.time, dict(self.time_attrs)),
                                                **self.coordinates()})
        scalar_attrs = {}
        for name, value in self.scalars().items():  # an end result that is a history's last value is that history
            if self.scalars_as_attributes:
                scalar_attrs.update({name: value, f"{name}_units": self.scalar_table[name][0]})
            elif name not in dataset:
                dataset[name] = ((), value, {"units": self.scalar_table[name][0],
                                             "long_name": self.scalar_table[name][1]})
        for name, variable in self.more_variables().items():
            dataset[name] = variable
        title = self.title()
        dataset.attrs.update(**({"title": title} if title else {}), Conventions=CF_CONVENTIONS,
                             **self.dataset_attrs(), **self.case_attrs(), **scalar_attrs, **provenance())
        return dataset

    def title(self) -> str | None:
        """The title of :meth:`to_xarray` (what was solved on what); None: none."""
        return None

    def case_attrs(self) -> dict:
        """The case solved as attributes of :meth:`to_xarray`: :meth:`case`, None as ``""``."""
        return {key: ("" if value is None else value) for key, value in self.case().items()}

    def coordinates(self) -> dict:
        """Coordinates of :meth:`to_xarray` beside ``time`` (the components' names of a vector's histories)."""
        return {}

    def more_variables(self) -> dict:
        """Variables of :meth:`to_xarray` beside the histories and end results: name -> (dims, values, attrs)."""
        return {}

    def dataset_attrs(self) -> dict:
        """Attributes of :meth:`to_xarray` before the case (what the motion was, say)."""
        return {}

    def describe(self) -> str:
        """The case solved, in one line (``mu = 0.1, mass = 5.1 kg, method = exact``)."""
        raise NotImplementedError

    def energy_ledger(self) -> dict | None:
        """The energy ledger's histories, name -> values at the samples [J, or J kg-1 for a per-mass
        ledger: :data:`~stickslip.units.UNITS` of the name]: :attr:`ledger_terms` of :meth:`histories`;
        None where the scheme keeps none."""
        if not self.ledger_terms:
            return None
        histories = self.histories()
        return {name: histories[name] for name in self.ledger_terms}

    @property
    def never_slides(self) -> str | None:
        """Why the block never slid relative to its base in this case, in words; None when it slid."""
        return None

    def case(self) -> dict:
        """What was solved, JSON-ready: the model, the scheme and the parameters (and options) as solved."""
        raise NotImplementedError

    def case_units(self) -> dict[str, str]:
        """The units of the numbers of :meth:`case` (UDUNITS spelling)."""
        return {name: UNITS[name] for name, value in self.case().items()
                if name in UNITS and isinstance(value, (int, float)) and not isinstance(value, bool)}

    def extras(self) -> dict:
        """More results, JSON-ready, beside :meth:`scalars` (each component alone, say); none by default."""
        return {}

    def notices(self) -> list[str]:
        """What deserves a note beside the results: that the block never slid (and why), a caveat of the scheme."""
        return [] if self.never_slides is None else [f"the block never slides: {self.never_slides}, so E_df = 0"]

    def motion_notes(self) -> list[str]:
        """Sentences on the motion that the record report prints under the response (when a slider lifted off)."""
        return []

    def notes(self) -> list[str]:
        """Lines that say what the end results are, printed under them (what the energies are, say)."""
        return []

    def tables(self) -> list[str]:
        """Further text tables that belong with the end results (each component alone beside the plane, say)."""
        return []
