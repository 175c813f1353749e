"""Article 2's walled cell (article2Cell runs, their rows in
article2Cell.dat) beside the tri-periodic cell with the same spheres and
pairs (the article2radius runs of ../demFrictionSweep/results.dat) and
article 2's laws: phi'(I_v) against eq 15 with phi_m from eq 13, mu(I_v)
against eq 14, at each run's friction.  Writes article2Cell.png.

    plotArticle2Cell.py [--table article2Cell.dat]
                        [--against ../demFrictionSweep/results.dat]
"""

import argparse
import os
import sys

here = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "src", "python"))

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from fdmPost.demRheology import (ARTICLE2_ROUGHNESS, article2_phi,  # noqa: E402
                                 model_mu, phi_m)
from analyse import TRIPERIODIC_RADIUS_ARMS  # noqa: E402

def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--table", default=os.path.join(here, "article2Cell.dat"))
    ap.add_argument("--against", default=os.path.join(
        here, "..", "demFrictionSweep", "results.dat"))
    args = ap.parse_args()
    walled = np.loadtxt(args.table, usecols=range(1, 10), ndmin=2)
    tri = np.loadtxt(args.against, ndmin=2)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for mu_m in np.unique(walled[:, 0]):
        w = walled[walled[:, 0] == mu_m]
        t = tri[(tri[:, 2] == TRIPERIODIC_RADIUS_ARMS)
                & np.isclose(tri[:, 0], mu_m)]
        t = t[np.argsort(t[:, 4])]
        iv = np.logspace(-3.5, 0.5, 100)
        pm = phi_m(mu_m)
        left.plot(t[:, 4], article2_phi(t[:, 3], ARTICLE2_ROUGHNESS), "s--",
                  mfc="none", label=f"tri-periodic, mu_m {mu_m:g}")
        left.plot(w[:, 1], w[:, 3], "o", ms=8, label=f"walled, mu_m {mu_m:g}")
        left.plot(iv, pm / (1 + np.sqrt(iv)), "k-",
                  label="article 2, eqs 13, 15")
        right.plot(t[:, 4], t[:, 5], "s--", mfc="none",
                   label=f"tri-periodic, mu_m {mu_m:g}")
        right.errorbar(w[:, 1], w[:, 4], w[:, 5], fmt="o", ms=8,
                       label=f"walled, mu_m {mu_m:g}")
        right.plot(iv, model_mu(iv, pm), "k-", label="article 2, eq 14")
    left.set(xscale="log", xlabel="I_v (core)",
             ylabel="phi' (article 2's radius)")
    right.set(xscale="log", xlabel="I_v (core)", ylabel="mu = sigma_xy/P")
    for ax in (left, right):
        ax.legend(fontsize=8)
    fig.tight_layout()
    out = os.path.join(os.path.dirname(os.path.abspath(args.table)),
                       "article2Cell.png")
    fig.savefig(out, dpi=120)
    print("plotArticle2Cell.py: wrote", out)


if __name__ == "__main__":
    main()
