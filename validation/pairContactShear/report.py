#!/usr/bin/env python3
"""Report of the rough-pair validation (run.py): the measured functions
against the exact ones, the trajectories, verdict and
pairContactShear.png."""

import os

import numpy as np
from fdmPost.report import write_markdown
from fdmResistance import pairContact as pc


def summary(track):
    """Exit offset r_y(+6), minimum gap and the r_x span of contact."""
    r, inside = track["r"], track["contactForce"] > 0
    span = ((r[inside, 0].min(), r[inside, 0].max()) if inside.any()
            else (np.nan, np.nan))
    end = np.interp(-r[0, 0], r[:, 0], r[:, 1])
    return end, track["gap"].min(), span


def deviation(track, ref):
    """Largest |r_y - r_y,ref| at the same r_x."""
    r, q = track["r"], ref["r"]
    return np.max(np.abs(r[:, 1] - np.interp(r[:, 0], q[:, 0], q[:, 1])))


def cell_table(cells, exact):
    """The shear functions against the cell size at one position."""
    lines = ["## The cell walls: shear functions against the cell size", "",
             "One position in a cell (offset 0), Couette cells of side L; "
             "exact values in the last row of each gap.", "",
             "| gap | L/a1 | A | B | c1 | c2 |", "|---|---|---|---|---|---|"]
    for g in np.unique(cells[:, 1]):
        rows = cells[cells[:, 1] == g]
        for row in rows[np.argsort(rows[:, 0])]:
            lines.append("| %g | %g | " % (g, row[0]) + " | ".join(
                "%.4f" % v for v in row[2:]) + " |")
        ex = pc.pair_functions(exact.motion, g, 1.4)
        lines.append("| %g | exact | " % g + " | ".join(
            "%.4f" % ex[f] for f in ("A", "B", "c1", "c2")) + " |")
    return lines + [
        "", "The solver's 12 a1 functions plus the change to the largest "
        "cell at the same position (interpolated in ln gap between the "
        "gaps above, constant outside) give the mobility 'solver, largest "
        "cells'; 'cell walls extrapolated' continues that change to L -> "
        "infinity as F_inf + c L^-3 from the two largest cells (an "
        "estimate; the verdict uses the largest cells).", ""]


def write(here, gaps, measured, spread, at_gaps, tracks, tol_offset,
          tol_trajectory, cells=None, exact=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lines = ["# Rough frictional pair in simple shear (thesis 1, section "
             "4.1.3, case 2)", "",
             "a2/a1 = 1.4, roughness 5e-3 a1, friction 0.5, Hertz stiffness "
             "from the deformation rule (0.2 h_r at 6 pi eta gammaDot a1^2); "
             "Delta = a1/5, Couette cell 12 a1, frameInvariant sub-grid.", "",
             "## The pair's functions: solver (exact)", "",
             "| gap | " + " | ".join(pc.FUNCTIONS) + " |",
             "|---" * (len(pc.FUNCTIONS) + 1) + "|"]
    for g, ex in zip(gaps, at_gaps):
        k = list(gaps).index(g)
        entries = []
        for f in pc.FUNCTIONS:
            m = measured[f][k]
            entries.append("-" if not np.isfinite(m) else
                           "%.4g (%.4g)" % (m, ex[f]))
        lines.append("| %g | " % g + " | ".join(entries) + " |")
    spreads = ", ".join("%s %.3g" % (f, np.nanmax(spread[f]))
                        for f in pc.FUNCTIONS if np.nanmax(spread[f]) > 0)
    if spreads:
        lines += ["", "Largest spread over the positions in a cell: "
                  + spreads + "."]
    lines += ["", "Shear probes: A at 45 degrees, B and the spins c_i along "
              "the flow; load probes (walls at rest): a unit normal pair "
              "load (m_n) and a unit tangential pair load with its torques "
              "(m_t, w_i).", ""]
    if cells is not None:
        lines += cell_table(cells, exact)
    verdict = ("solver, largest cells" if cells is not None else "solver")
    names = list(dict.fromkeys(n for _, n in tracks))   # run.py's order
    lines += [
              "## Trajectories from r = (-6, r_y0, 0)", "",
              "| r_y0 | mobility | exit offset r_y(+6) | minimum gap "
              "| contact for r_x in | largest \\|r_y - r_y,exact\\| |",
              "|---|---|---|---|---|---|"]
    ok = True
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    y0s = sorted({y0 for y0, _ in tracks})
    for k, y0 in enumerate(y0s):
        ref = tracks[y0, "exact"]
        ref_end = summary(ref)[0]
        for name in names:
            tr = tracks[y0, name]
            end, gmin, span = summary(tr)
            dev = deviation(tr, ref)
            lines.append("| %g | %s | %.4f | %.3g | %.3f ... %.3f | %.4f |"
                         % (y0, name, end, gmin, span[0], span[1], dev))
            if name == verdict:
                ok = ok and (abs(end - ref_end) <= tol_offset * ref_end
                             and dev <= tol_trajectory)
            style = {"exact": "-", "solver": "--",
                     "solver, largest cells": ":"}.get(name)
            if style is None:
                continue
            axes[0].plot(tr["r"][:, 0], tr["r"][:, 1], style,
                         color="C%d" % k, lw=1,
                         label="$r_{y0}$ = %g, %s" % (y0, name))
            axes[1].semilogy(tr["r"][:, 0], np.maximum(tr["gap"], 1e-6),
                             style, color="C%d" % k, lw=1)
    axes[0].set_xlabel("$r_x/a_1$")
    axes[0].set_ylabel("$r_y/a_1$")
    axes[0].legend(fontsize=6)
    axes[1].axhline(5e-3, color="grey", lw=0.6)
    axes[1].set_xlabel("$r_x/a_1$")
    axes[1].set_ylabel("surface gap$/a_1$")
    axes[1].set_xlim(-3, 3)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "pairContactShear.png"), dpi=120)
    lines += ["", "Targets: exit offset within %g %% and r_y within %g a1 "
              "of the exact trajectory (the unbounded theory), judged on "
              "the mobility '%s'."
              % (100 * tol_offset, tol_trajectory, verdict), "",
              "Result: %s" % ("PASS" if ok else "FAIL")]
    write_markdown(os.path.join(here, "report.md"), lines)
    return ok
