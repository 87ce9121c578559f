"""Draw docs/inclined_block.png: the forces on a rigid block on a plane inclined at β (docs/solvers.md).

Run from the project's root: ``.venv/bin/python scripts/draw-inclined-block.py``.
"""

from __future__ import annotations

import math
from pathlib import Path

from matplotlib.figure import Figure
from matplotlib.patches import Arc, Polygon, Rectangle

BETA = math.radians(20.0)
ALONG = (math.cos(BETA), math.sin(BETA))  # +x, upslope
NORMAL = (-math.sin(BETA), math.cos(BETA))  # out of the plane


def point(origin, along=0.0, normal=0.0):
    """``origin`` moved by ``along`` in +x and ``normal`` out of the plane."""
    return (origin[0] + along * ALONG[0] + normal * NORMAL[0], origin[1] + along * ALONG[1] + normal * NORMAL[1])


def arrow(ax, start, end, color, dashed=False):
    ax.annotate("", xy=end, xytext=start, arrowprops={
        "arrowstyle": "-|>", "color": color, "linewidth": 1.8, "linestyle": "--" if dashed else "-",
        "shrinkA": 0, "shrinkB": 0, "mutation_scale": 14})


def main() -> Path:
    figure = Figure(figsize=(6.4, 3.6), layout="constrained")
    ax = figure.subplots()
    ax.set_aspect("equal")
    ax.axis("off")
    top = point((0.0, 0.0), 11.0)
    ax.add_patch(Polygon([(0.0, 0.0), top, (top[0], 0.0)], closed=True, color="0.9"))
    ax.plot([0.0, top[0]], [0.0, top[1]], color="0.2", linewidth=2)
    ax.plot([0.0, 2.8], [0.0, 0.0], color="0.2", linewidth=0.8, linestyle="--")
    ax.add_patch(Arc((0.0, 0.0), 3.0, 3.0, theta1=0.0, theta2=math.degrees(BETA), color="0.2"))
    ax.text(1.7, 0.22, "β", fontsize=12)

    contact = point((0.0, 0.0), 5.5)
    width, height = 2.2, 1.4
    corner = point(contact, -width / 2)
    ax.add_patch(Rectangle(corner, width, height, angle=math.degrees(BETA), rotation_point="xy",
                           facecolor="#9ecae1", edgecolor="#08519c", alpha=0.8))
    centre = point(contact, 0.0, height / 2)
    ax.text(*point(centre, 0.35, 0.1), "m", fontsize=12)

    arrow(ax, centre, (centre[0], centre[1] - 1.6), "0.2")
    ax.text(centre[0] + 0.12, centre[1] - 1.75, "m·g", fontsize=11)
    normal_foot = point(contact, -0.6)
    arrow(ax, normal_foot, point(normal_foot, 0.0, 2.2), "#31a354")
    ax.text(*point(normal_foot, -2.9, 2.3), "N = m·g·cos β", color="#31a354", fontsize=11)
    friction_foot = point(contact, 0.7)
    arrow(ax, friction_foot, point(friction_foot, 1.8), "#de2d26")
    ax.text(*point(friction_foot, 0.9, -0.75), "F, |F| ≤ μ·N", color="#de2d26", fontsize=11)
    arrow(ax, centre, point(centre, -2.4), "#756bb1", dashed=True)
    ax.text(*point(centre, -4.6, 1.0), "−m·ü_g (inertia)", color="#756bb1", fontsize=11)
    base = point((0.0, 0.0), 1.2, -0.6)
    arrow(ax, base, point(base, 2.0), "0.2")
    ax.text(*point(base, 2.3, -0.45), "ü_g = a(t), base", fontsize=11)
    axis = point((0.0, 0.0), 7.0, 1.2)
    arrow(ax, axis, point(axis, 2.2), "0.2")
    ax.text(*point(axis, 2.4, -0.15), "+x (upslope)", fontsize=11)
    ax.text(4.8, -1.0, "downslope is −x: a(t) > 0 drives the block downslope", fontsize=10)
    ax.set_xlim(-0.5, top[0] + 0.3)
    ax.set_ylim(-1.2, top[1] + 1.0)
    path = Path(__file__).resolve().parents[1] / "docs" / "inclined_block.png"
    figure.savefig(path, dpi=110, metadata={"Software": None})
    return path


if __name__ == "__main__":
    print(main())
