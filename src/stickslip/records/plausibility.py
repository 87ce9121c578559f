"""How large a ground acceleration can plausibly be, and in which other units an implausible one would be plausible.

A record's values, a ``--target-pga`` or a ``--ky`` written without a unit
are read in the units the file, the format or the option implies (g for a
PEER or pySLAMMER file and for a bare ``--target-pga``).  A number in the
wrong units is off by 9.81 (m/s² read as g) or 981 (cm/s² read as g), which
lands a PGA outside :data:`PLAUSIBLE_PGA`: the values of a pySLAMMER-style
``time,acc`` file written in m/s² and read as g give a PGA of 4.63 g, where
0.47 g was meant.  :func:`pga_doubt` says so in one line that names the units
assumed and the readings that would be plausible:
``PGA 4.63 g if the values are in g; 0.472 g if they are in m/s2``.
"""

from __future__ import annotations

import math

from stickslip.records.formats import RECORD_UNITS, unit_factor

#: PGA [g] of the ground motions one analyses: above 4 g none recorded comes near (the largest are about
#: 4 g); below 0.001 g (1 cm/s²) the shaking slides no block.  Outside, the values are likely in other units.
PLAUSIBLE_PGA = (0.001, 4.0)
#: The band [g] for values whose units nobody stated (neither the file, the user nor a manifest: the format's
#: default is assumed).  Above 2 g lie a handful of recorded motions, and a motion of 0.2 g to 0.4 g written in
#: m/s² and read as g: the doubt is worth a line when nothing vouches for the units.
PLAUSIBLE_PGA_UNSTATED = (0.001, 2.0)


def other_readings(number: float, units: str, g: float, low: float, high: float) -> list[tuple[str, float]]:
    """The other readings of ``number``, written in ``units``, that are an acceleration from ``low`` to ``high`` [g].

    Each is (units, acceleration [g]) for one of :data:`~stickslip.records.formats.RECORD_UNITS`
    other than ``units``, converted with ``g`` [m/s²]; the nearest conversion
    (the smallest factor between the two units) first.
    """
    assumed = unit_factor(units, g)
    readings = [(other, abs(number) * unit_factor(other, g) / g) for other in RECORD_UNITS if other != units]
    readings.sort(key=lambda reading: abs(math.log(unit_factor(reading[0], g) / assumed)))
    return [(other, value) for other, value in readings if low <= value <= high]


def pga_doubt(peak: float, units: str, g: float, subject: str = "the values are", pronoun: str = "they are",
              plausible: tuple[float, float] = PLAUSIBLE_PGA) -> str | None:
    """``"PGA 4.63 g if the values are in g; 0.472 g if they are in m/s2"``, or None for a plausible PGA.

    ``peak`` is the largest |value| as written, in ``units`` (``g``, ``m/s2`` or
    ``cm/s2``), converted with ``g`` [m/s²]; the PGA is in doubt outside
    ``plausible`` [g] (:data:`PLAUSIBLE_PGA`), and the line names every other
    reading that lies inside (:func:`other_readings`).  ``subject`` and
    ``pronoun`` say what the number is (``"the number is"``, ``"it is"`` for an
    option's value).
    """
    pga = abs(peak) * unit_factor(units, g) / g
    low, high = plausible
    if low <= pga <= high:
        return None
    readings = other_readings(peak, units, g, low, high)
    others = "; ".join(f"{value:.3g} g if {pronoun} in {other}" for other, value in readings)
    return f"PGA {pga:.3g} g if {subject} in {units}" + (f"; {others}" if others else "")
