"""The figure of a record's or a pair's response spectra (``stickslip spectrum --plot``)."""

from __future__ import annotations

from matplotlib.figure import Figure

from stickslip.reports.plots import new_figure

#: How the figure names each measure.
MEASURE_LABELS = {"psa": "component", "rotd100": "RotD100", "rotd50": "RotD50", "geomean": "geometric mean",
                  "srss": "SRSS"}


def plot_spectra(spectra, g: float, title: str) -> Figure:
    """PSA [g] (top) and SD [m] (bottom) of each measure of ``spectra`` (:class:`stickslip.spectra.Spectra`) over
    the period T [s] on a log axis; ``g`` [m/s²] converts the accelerations."""
    figure, (top, bottom) = new_figure(2, 1, figsize=(7.0, 7.0), sharex=True)
    for measure in spectra.measures:
        label = MEASURE_LABELS[measure]
        top.plot(spectra.periods, spectra.pseudo_acceleration(measure) / g, label=label)
        bottom.plot(spectra.periods, spectra.displacements[measure], label=label)
    top.set(xscale="log", ylabel="pseudo-spectral acceleration PSA [g]", title=title)
    bottom.set(xscale="log", xlabel="oscillator period T [s]", ylabel="spectral displacement SD [m]")
    for ax in (top, bottom):
        ax.grid(True, which="both", linewidth=0.3)
        ax.legend(fontsize="small")
    return figure
