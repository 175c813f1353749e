#!/usr/bin/env python3
"""Report of the periodic-array drag validation (thesis 1, Table 4.1).

Reads L<L>/x?y?z?/ cases written by Allrun, weights the 6 symmetry classes
to the 64-position average, compares with Hasimoto (eq 4.3) and with the
published FDM values, writes report.md and dragFactor.png, and exits
non-zero if the mean error exceeds the target at L/a = 8 or 10.
"""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.particleCase import drag_factor, hasimoto_K  # noqa: E402
from fdmPost.report import write_markdown  # noqa: E402

# Published FDM values (Orsi 2022, Table 4.1): L/a -> (K, sigma_K, error %)
THESIS = {8: (1.532059, 0.014381, 0.11), 10: (1.389611, 0.011877, 0.11),
          20: (1.167027, 0.009899, 0.21), 30: (1.109563, 0.014221, 0.48),
          40: (1.085323, 0.018710, 0.84), 50: (1.073184, 0.021934, 1.23)}
TARGET = 0.2        # % mean error at L/a = 8 and 10 (issue 3)
CLASSES = {"x1y1z1": 8, "x1y1z3": 16, "x1y3z3": 8,
           "x3y1z1": 8, "x3y1z3": 16, "x3y3z3": 8}


def lambda_tolerance(case):
    with open(os.path.join(case, "constant", "particleProperties")) as f:
        for line in f:
            if line.strip().startswith("lambdaTolerance"):
                return float(line.split()[1].rstrip(";"))
    return float("nan")


def iterations(case):
    with open(os.path.join(case, "log.fdmSuspensionFoam")) as f:
        n = [int(l.split()[3]) for l in f if "converged in" in l]
    return n[0] if n else -1


def main(sizes):
    here = os.path.dirname(os.path.abspath(__file__))
    rows, ok = [], True
    for L in sizes:
        Ks, ws, its, tols = [], [], [], []
        for name, w in CLASSES.items():
            case = os.path.join(here, "L%g" % L, name)
            Ks.append(drag_factor(case, L))
            ws.append(w)
            its.append(iterations(case))
            tols.append(lambda_tolerance(case))
        Ks, ws = np.array(Ks), np.array(ws, float)
        mean = np.average(Ks, weights=ws)
        std = math.sqrt(np.average((Ks - mean) ** 2, weights=ws))
        phi = 4 * math.pi / 3 / L ** 3
        KH = hasimoto_K(phi)
        err = 100 * (mean - KH) / KH
        passed = abs(err) <= TARGET if L in (8, 10) else True
        ok &= passed
        rows.append((L, phi, KH, mean, std, err, THESIS.get(L), its,
                     max(tols), passed))

    lines = ["# Periodic-array drag (Hasimoto), thesis 1 section 4.1.1", "",
             "One held sphere per periodic cube, Delta = a/5, b = 5, c = 0.3;"
             " K averaged over 64 positions in a cell (6 symmetry classes)."
             " Target: mean error <= %.1f %% at L/a = 8, 10." % TARGET, "",
             "| L/a | phi | K_H | K (ours) | sigma_K | (K-K_H)/K_H % |"
             " thesis K | thesis sigma | thesis abs. error % | outer its |"
             " lambda tol | result |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for L, phi, KH, K, s, e, th, its, tol, p in rows:
        thK, ths, the = th if th else (float("nan"),) * 3
        lines.append("| %g | %.3g | %.5f | %.6f | %.6f | %+.4f | %.6f | %.6f |"
                     " %.2f | %d-%d | %.0e | %s |"
                     % (L, phi, KH, K, s, e, thK, ths, the, min(its), max(its),
                        tol, "PASS" if p else "FAIL"))
    lines += ["", "Result: %s" % ("PASS" if ok else "FAIL")]
    write_markdown(os.path.join(here, "report.md"), lines)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    Lc = np.linspace(6, 55, 200)
    ax.plot(Lc, [hasimoto_K(4 * math.pi / 3 / l ** 3) for l in Lc], "k-",
            label="Hasimoto (1959), eq 4.3")
    tl = sorted(THESIS)
    ax.errorbar(tl, [THESIS[l][0] for l in tl],
                yerr=[THESIS[l][1] for l in tl], fmt="s", mfc="none",
                capsize=3, label="Orsi (2022), Table 4.1")
    ax.errorbar([r[0] for r in rows], [r[3] for r in rows],
                yerr=[r[4] for r in rows], fmt="o", capsize=3,
                label="fdmSuspension")
    ax.set_xlabel("L/a")
    ax.set_ylabel("K (mean over 64 positions, bars: std)")
    ax.legend()
    ax.set_title("Drag of a simple cubic array of spheres")
    # Relative error of the mean and position scatter, both in %
    KHt = [hasimoto_K(4 * math.pi / 3 / l ** 3) for l in tl]
    ax2.errorbar(tl, [100 * (THESIS[l][0] - k) / k for l, k in zip(tl, KHt)],
                 yerr=[100 * THESIS[l][1] / k for l, k in zip(tl, KHt)],
                 fmt="s", mfc="none", capsize=3, label="Orsi (2022)")
    ax2.errorbar([r[0] for r in rows], [r[5] for r in rows],
                 yerr=[100 * r[4] / r[2] for r in rows], fmt="o", capsize=3,
                 label="fdmSuspension")
    ax2.axhline(0, color="k", lw=0.8)
    for sgn in (1, -1):
        ax2.axhline(sgn * TARGET, color="r", ls=":", lw=0.8)
    ax2.set_xlabel("L/a")
    ax2.set_ylabel("(K - K_H)/K_H [%]  (bars: position std)")
    ax2.legend()
    ax2.set_title("error of the mean; target +-%.1f %% dotted" % TARGET)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "dragFactor.png"), dpi=120)
    return 0 if ok else 1


def available_sizes():
    """L of every L<L>/ folder holding all six position cases."""
    here = os.path.dirname(os.path.abspath(__file__))
    sizes = []
    for d in os.listdir(here):
        if d.startswith("L") and all(os.path.isdir(os.path.join(here, d, c))
                                     for c in CLASSES):
            sizes.append(float(d[1:]))
    return sorted(sizes)


if __name__ == "__main__":
    sys.exit(main([float(a) for a in sys.argv[1:]] or available_sizes()))
