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
"""

from __future__ import annotations

# the codes of a history's ``phase`` that every model shares (the engine's): the block sticks to its base, or (a
# pendulum's slider under a vertical motion) has lifted off its surface; sliding is any other code (±1)
from stickslip.solvers.events import FLIGHT, STICK
from stickslip.units import UNITS


class Result:
    """One solved case of a sliding-block model.

    A subclass provides :attr:`model`, :attr:`method`, :meth:`scalars`,
    :meth:`to_xarray` and :meth:`describe`, and :meth:`energy_ledger` and
    :attr:`never_slides` where it has them.
    """

    #: The model solved (``"rigid"``, ``"coupled"`` …) and the scheme that solved it.
    model: str
    method: str

    def scalars(self) -> dict[str, float | int]:
        """The end results: name -> number, in the units of :meth:`scalar_units`."""
        raise NotImplementedError

    def scalar_units(self) -> dict[str, str]:
        """The unit of each of :meth:`scalars`, UDUNITS spelling, from :data:`stickslip.units.UNITS`."""
        return {name: UNITS[name] for name in self.scalars()}

    def scalar_attrs(self) -> dict[str, tuple[str, str]]:
        """The unit and long name of each of :meth:`scalars` (the tables of reports); by default the unit of
        :meth:`scalar_units` and the name in words."""
        return {name: (units, name.replace("_", " ")) for name, units in self.scalar_units().items()}

    def to_xarray(self):
        """The histories and end results as an :class:`xarray.Dataset` with units and the case solved."""
        raise NotImplementedError

    def describe(self) -> str:
        """The case solved, in one line (``mu = 0.1, mass = 5.1 kg, method = exact``)."""
        raise NotImplementedError

    def energy_ledger(self) -> dict | None:
        """The energy ledger's histories, name -> values at the samples [J, or J kg-1 for a per-mass
        ledger: :data:`~stickslip.units.UNITS` of the name]; None where the scheme keeps none."""
        return None

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

    def notes(self) -> list[str]:
        """Lines that say what the end results are, printed under them (what the energies are, say)."""
        return []

    def tables(self) -> list[str]:
        """Further text tables that belong with the end results (each component alone beside the plane, say)."""
        return []
