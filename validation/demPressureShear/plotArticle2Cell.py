"""Article 2's walled cell (article2Cell runs, their rows in
article2Cell.dat) beside the tri-periodic cell with the same spheres and
pairs (the article2radius runs of ../demFrictionSweep/results.dat) and
article 2's laws: phi'(I_v) against eq 15 with phi_m from eq 13, mu(I_v)
against eq 14, eta_r(phi') against eq 16, at each run's friction.  With
four walled runs or more at a friction, phi_m fitted as article 2 did
(demRheology.fit_phi_m: phi' = phi_m/(1 + c I_v^n)) is printed and drawn.
Writes article2Cell.png.

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

from fdmPost.demRheology import (  # noqa: E402
    ARTICLE2_ROUGHNESS, article2_phi, fit_phi_m, model_eta, model_mu, phi_m)
from analyse import TRIPERIODIC_RADIUS_ARMS  # noqa: E402

def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--table", default=os.path.join(here, "article2Cell.dat"))
    ap.add_argument("--against", default=os.path.join(
        here, "..", "demFrictionSweep", "results.dat"))
    args = ap.parse_args()
    walled = np.loadtxt(args.table, usecols=range(1, 10), ndmin=2)
    tri = np.loadtxt(args.against, ndmin=2)
    fig, (left, right, third) = plt.subplots(1, 3, figsize=(15, 4))
    for mu_m in np.unique(walled[:, 0]):
        w = walled[walled[:, 0] == mu_m]
        t = tri[(tri[:, 2] == TRIPERIODIC_RADIUS_ARMS)
                & np.isclose(tri[:, 0], mu_m)]
        t = t[np.argsort(t[:, 4])]
        iv = np.logspace(-3.5, 0.5, 100)
        pm = phi_m(mu_m)
        t_phi = article2_phi(t[:, 3], ARTICLE2_ROUGHNESS)
        left.plot(t[:, 4], t_phi, "s--",
                  mfc="none", label=f"tri-periodic, mu_m {mu_m:g}")
        left.plot(w[:, 1], w[:, 3], "o", ms=8, label=f"walled, mu_m {mu_m:g}")
        left.plot(iv, pm / (1 + np.sqrt(iv)), "k-",
                  label="article 2, eqs 13, 15")
        if len(w) >= 4:
            (fm, c, n), err = fit_phi_m(w[:, 3], w[:, 1])
            print(f"mu_m {mu_m:g}: phi_m {fm:.4f} +- {err[0]:.4f}, c {c:.3f},"
                  f" n {n:.3f} +- {err[2]:.3f} from {len(w)} walled runs"
                  f" (I_v {w[:, 1].min():.2g}-{w[:, 1].max():.2g}); eq 13:"
                  f" {pm:.4f}")
            span = np.logspace(np.log10(w[:, 1].min() / 3),
                               np.log10(w[:, 1].max() * 3), 50)
            left.plot(span, fm / (1 + c * span**n), "r:",
                      label=f"fit: phi_m {fm:.3f} +- {err[0]:.3f}")
        p = np.linspace(0.42, pm - 0.005, 100)
        third.plot(t_phi, t[:, 6], "s--",
                   mfc="none", label=f"tri-periodic, mu_m {mu_m:g}")
        third.errorbar(w[:, 3], w[:, 7], w[:, 8], fmt="o", ms=8,
                       label=f"walled, mu_m {mu_m:g}")
        third.plot(p, model_eta(p, pm), "k-", label="article 2, eq 16")
        right.plot(t[:, 4], t[:, 5], "s--", mfc="none",
                   label=f"tri-periodic, mu_m {mu_m:g}")
        right.errorbar(w[:, 1], w[:, 4], w[:, 5], fmt="o", ms=8,
                       label=f"walled, mu_m {mu_m:g}")
        right.plot(iv, model_mu(iv, pm), "k-", label="article 2, eq 14")
    left.set(xscale="log", xlabel="I_v (core)",
             ylabel="phi' (article 2's radius)")
    right.set(xscale="log", yscale="log", xlabel="I_v (core)",
              ylabel="mu = sigma_xy/P")
    third.set(yscale="log", xlabel="phi' (article 2's radius)",
              ylabel="eta_r (core)")
    for ax in (left, right, third):
        ax.legend(fontsize=8)
    fig.tight_layout()
    out = os.path.join(os.path.dirname(os.path.abspath(args.table)),
                       "article2Cell.png")
    fig.savefig(out, dpi=120)
    print("plotArticle2Cell.py: wrote", out)


if __name__ == "__main__":
    main()
