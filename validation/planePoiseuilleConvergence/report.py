#!/usr/bin/env python3
"""Report for validation/planePoiseuilleConvergence: relative L-inf error of
u_x against the parabola u = G/(2 nu) y (H - y), G = 8, nu = H = 1, for both
wall closures and N cells across; observed order; PNG plot.

Pass criteria (printed): two-point wall error equals (Delta/H)^2 within
1e-6 relative (the exact discrete solution, tests/README.md); quadratic
wall error <= 1e-9 at every N.
"""

import re
import sys
from pathlib import Path

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from fdmPost.foamFields import read_internal_field


def main(work, out):
    work, out = Path(work), Path(out)
    rows = []
    for case in sorted(work.iterdir()):
        wall, n = case.name.rsplit("-", 1)
        n = int(n)
        y = read_internal_field(case / "0/C")[:, 1]
        u = read_internal_field(case / "1/U")[:, 0]
        exact = 4.0 * y * (1 - y)
        err = np.abs(u - exact).max() / np.abs(exact).max()
        iters = re.search(r"converged in (\d+)", (case / "log.fdmSuspensionFoam").read_text())
        rows.append((wall, n, err, int(iters.group(1)) if iters else -1))

    ok = True
    lines = ["# Plane Poiseuille: mesh convergence of the particle-free solver", "",
             "Relative L-inf error of u_x against the analytic parabola (G = 8, nu = H = 1).", "",
             "| wall closure | N | Delta/H | error | predicted | outer iterations |",
             "|---|---|---|---|---|---|"]
    for wall, n, err, iters in sorted(rows):
        # Two-point wall: uniform offset Delta^2 (G Delta^2/(8 nu) with G = 8),
        # divided by the largest cell-centre value of the parabola, 1 - Delta^2
        d = 1 / n
        predicted = d**2 / (1 - d**2) if wall == "fixedValue" else 0.0
        if wall == "fixedValue":
            passed = abs(err / predicted - 1) < 1e-6
        else:
            passed = err < 1e-9
        ok &= passed
        lines.append(f"| {wall} | {n} | {1 / n:.4g} | {err:.3e} | {predicted:.3e} | {iters} |")

    two = sorted((n, e) for w, n, e, _ in rows if w == "fixedValue")
    orders = [np.log2(e1 / e2) for (_, e1), (_, e2) in zip(two, two[1:])]
    lines += ["", "Observed order (fixedValue): " + ", ".join(f"{o:.3f}" for o in orders),
              "", f"Result: {'PASS' if ok else 'FAIL'} (fixedValue error = (Delta/H)^2 / max u_h "
              "within 1e-6 relative; secondOrderWallVelocity error < 1e-9)"]
    (out / "report.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))

    fig, ax = plt.subplots(figsize=(5, 4))
    for wall, marker in (("fixedValue", "o"), ("secondOrderWallVelocity", "s")):
        d = sorted((n, max(e, 1e-16)) for w, n, e, _ in rows if w == wall)
        ax.loglog([1 / n for n, _ in d], [e for _, e in d], marker, label=wall)
    h = np.array([1 / 8, 1 / 64])
    ax.loglog(h, h**2, "k--", label=r"$(\Delta/H)^2$")
    ax.set_xlabel(r"$\Delta/H$")
    ax.set_ylabel(r"relative $L_\infty$ error")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "convergence.png", dpi=120)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
