#!/usr/bin/env python3
"""The box-size study of the three-sphere validation (report.py --boxes):
the deviations from the boundary-integral reference of every box scale
run (run.py --box-scale), side by side, at the cell positions that every
scale ran, so that the box is apart from the position sampling.  Writes
report_boxes.md."""

import os

import numpy as np

from report import (HERE, TRI_NAMES, boxes, load, load_kernel,
                    shear_deviation, shear_section, suffix,
                    triangle_section)


def summary(tri, shear):
    """Largest |deviation|/reference (%) over r of the targeted triangle
    quantities, and (mean, largest) shear deviations (%) per config and
    radius."""
    out = {}
    for j in (2, 3, 4):
        devs = [abs(c[j] - r[j]) / abs(r[j]) for _, c, _, r in tri
                if not np.isnan(r[j])]
        if devs:
            out[TRI_NAMES[j]] = 100 * max(devs)
    for config, (ref, meas) in shear.items():
        for a, (m, _) in meas.items():
            dev = np.abs(shear_deviation(ref, m))
            out["%s a = %g" % (config, a)] = (100 * dev.mean(),
                                              100 * dev.max())
    return out


def positions_run(scale):
    """The cell positions (offset tuples) in a results file."""
    return {tuple(map(float, line.split()[3:6]))
            for line in open(os.path.join(HERE, "results%s.dat" %
                                          suffix(scale)))
            if not line.startswith("#")}


def box_study():
    """report_boxes.md: the deviations at every box scale run side by
    side (the box-size study), at the positions that every scale ran."""
    scales = sorted([1.0] + [float(f[len("results_box"):-4])
                             for f in os.listdir(HERE)
                             if f.startswith("results_box")])
    common = set.intersection(*(positions_run(s) for s in scales))
    rows = []
    for scale in scales:
        data = load(scale, common)
        kernel = load_kernel(scale)
        tri = (triangle_section(data, kernel, [], scale)[0]
               if any(k[0] == "triangle" for k in data) else [])
        shear = shear_section(data, [], scale)[0]
        positions = "/".join(
            "%d" % len(next(v for k, v in data.items() if k[0] == kind)[0])
            if any(k[0] == kind for k in data) else "-"
            for kind in ("triangle", "shear"))
        rows.append((scale, positions, summary(tri, shear)))
    keys = [TRI_NAMES[j] for j in (2, 3, 4)] + sorted(
        {k for _, _, s in rows for k in s} - set(TRI_NAMES))
    lines = ["# Three spheres: box-size study", "",
             "Largest deviation over r (%%) of the triangle quantities, "
             "mean/largest deviation (%%) of the shear clusters, against "
             "the boundary-integral reference; triangle box %s a and shear "
             "cube %g a at scale 1; cell positions %s (those every scale "
             "ran)." % (" x ".join("%g" % L for L in boxes(1)[0]),
                        boxes(1)[1], ", ".join(str(p) for p in
                                               sorted(common))), "",
             "| scale | positions (triangle/shear) | " + " | ".join(keys)
             + " |",
             "|---|---|" + "---|" * len(keys)]
    for scale, positions, s in rows:
        cells = ["-" if k not in s else "%.2f / %.2f" % s[k]
                 if isinstance(s[k], tuple) else "%.2f" % s[k] for k in keys]
        lines.append("| %g | %s | %s |" % (scale, positions,
                                           " | ".join(cells)))
    with open(os.path.join(HERE, "report_boxes.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
