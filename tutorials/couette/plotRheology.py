#!/usr/bin/python3
"""Couette suspension post-processing (thesis 1, sections 2.7 and 4.2), also
of a Lees-Edwards box (tutorials/leesEdwards: --layer 0, the whole box at
the imposed shear rate, no wall column in the consistency check):
core viscosity (eq 2.76) with its error bar, normal stress differences and
contact share (eq 4.13), per unit of strain and averaged with two error
bars (block means; integrated autocorrelation), profiles phi(y) (eq 2.70) and u_p(y) (eq 6.4),
per-particle force balance (eq 4.17), and PNG plots.

    plotRheology.py [case] [--layer H] [--start STRAIN]

Reads postProcessing/particles.h5: the records and, from its attributes,
the box, the viscosity and the walls' shear rate.
"""

import argparse
import os
import sys


import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost.rheology import (autocorrelation_time, couette_case,  # noqa: E402
                              core_rheology, maron_pierce,
                              mechanical_consistency)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("case", nargs="?", default=".")
    ap.add_argument("--layer", type=float, default=2.0,
                    help="wall layer excluded from the core, in a1 (thesis 5)")
    ap.add_argument("--start", type=float, default=0.5,
                    help="strain gammaDot_0 t where time averages start")
    args = ap.parse_args()
    case = args.case

    cs, gamma0 = couette_case(case, args.layer)
    leesEdwards = cs.imposed_rate is not None
    L, eta = cs.span, cs.eta
    strain = cs.t * gamma0
    if strain[-1] <= args.start:
        sys.exit(f"plotRheology: the run reached strain {strain[-1]:.3g}, not"
                 f" beyond --start {args.start}")
    series = cs.series()
    r = core_rheology(cs, args.start / gamma0, series=series)
    steady = np.nonzero(cs.t >= args.start / gamma0)[0]
    g, phic, hp, c = series
    sxy = eta * g + hp[:, 0, 1] + c[:, 0, 1]
    # Second error estimate of eta_core: the number of independent samples
    # from the integrated autocorrelation time of the instantaneous value
    etaInst = (sxy / (eta * g))[steady]
    tau = autocorrelation_time(etaInst, np.median(np.diff(strain)))
    samples = (strain[-1] - args.start) / (2 * tau)

    # Mechanical consistency (Table 4.8 columns)
    with np.errstate(divide="ignore", invalid="ignore"):  # no wall: LE
        balance = mechanical_consistency(case, args.start / gamma0)

    def pm(key, fmt=".3f"):
        m, e = r[key]
        return f"{m:{fmt}} +- {e:{fmt}}"

    print(f"{'Lees-Edwards box' if leesEdwards else 'Couette suspension'}:"
          f" {len(cs.a)} particles, box {L.tolist()},"
          f" strain {strain[-1]:.2f}, averages over strain >= {args.start}"
          f" ({r['records']} records, 5 blocks)")
    print(f"  core (|y - Ly/2| < {L[1] / 2 - args.layer:g}): phi_core"
          f" {pm('phiCore')}, gammaDot_core/gammaDot_0"
          f" {r['gammaDotCore'][0] / gamma0:.3f}"
          + (" (imposed: Lees-Edwards)" if leesEdwards else ""))
    print(f"  core viscosity eta_core (eq 2.76): {pm('etaCore')} (5 blocks);"
          f" +- {np.nanstd(etaInst) / np.sqrt(samples):.3f} from its"
          f" autocorrelation strain {tau:.2f} ({samples:.1f} independent"
          " samples)")
    print(f"  thesis fit at this phi_core (Maron-Pierce, alpha 0.803, phi_J"
          f" 0.59): {maron_pierce(r['phiCore'][0]):.3f}")
    print(f"  N1/Sigma12 {pm('N1')}, N2/Sigma12 {pm('N2')},"
          f" contact share of Sigma12 {pm('contactShare')}")
    print("  per unit of strain: phi_core, gammaDot_core/gammaDot_0, eta_core,"
          " contact share, N1/Sigma12, N2/Sigma12")
    for k in range(int(strain[0]), int(strain[-1]) + 1):
        w = core_rheology(cs, k / gamma0, end_time=(k + 1) / gamma0,
                          series=series)
        if w["records"] > 1:
            print(f"    {k:3d}-{k + 1:<3d} {w['phiCore'][0]:.4f}"
                  f" {w['gammaDotCore'][0] / gamma0:6.3f}"
                  f" {w['etaCore'][0]:7.2f} {w['contactShare'][0]:6.3f}"
                  f" {w['N1'][0]:7.3f} {w['N2'][0]:7.3f}")
    print("  mechanical consistency (Table 4.8 columns, x y z):")
    for name, v in zip(("wall vs particles rms(F^w - F^FDM,parts)/rms(F^w)",
                        "volume vs particles rms(F^FDM,V - F^FDM,parts)/rms(F^FDM,V)",
                        "particle force balance rms(F^h + F^c)/rms(F^c)",
                        "particle torque balance rms(T^h + T^c)/rms(T^c)"),
                       balance):
        if leesEdwards and name.startswith("wall"):
            continue
        print(f"    {name}: {' '.join(f'{x:.2e}' for x in v)}")

    # Plots: profiles and time series
    bins = int(round(L[1] / 0.2))
    yb, phi, up = cs.profiles(bins, steady)
    fig, ax = plt.subplots(1, 3, figsize=(12, 3.8))
    ax[0].plot(phi, yb, "-")
    ax[0].axhspan(0, args.layer, color="0.9")
    ax[0].axhspan(L[1] - args.layer, L[1], color="0.9")
    ax[0].set_xlabel(r"$\phi(y)$")
    ax[0].set_ylabel(r"$y/a_1$")
    ax[0].set_title("volume fraction (eq 2.70)")
    ax[1].plot(up, yb, "o", ms=3, mfc="none", label="particles (eq 6.4)")
    ax[1].plot(gamma0 * (yb - L[1] / 2), yb, "k--", label=r"imposed $\dot\gamma_0 y$")
    ax[1].set_xlabel(r"$u_{p,x}$")
    ax[1].set_title("particle velocity")
    ax[1].legend(fontsize=8)
    ax[2].plot(strain, sxy / (eta * g), label=r"$\eta_{core}$ (instantaneous)")
    ax[2].plot(strain, c[:, 0, 1] / (eta * g), label=r"contact part $\Sigma^c_{xy}/\eta\dot\gamma$")
    ax[2].axhline(r["etaCore"][0], color="k", lw=0.8, ls="--",
                  label=f"mean {r['etaCore'][0]:.2f}")
    ax[2].axvline(args.start, color="0.6", lw=0.8)
    ax[2].set_xlabel(r"strain $\dot\gamma_0 t$")
    ax[2].set_title("core stress")
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    out = os.path.join(case, "rheology.png")
    fig.savefig(out, dpi=110)
    print(f"  wrote {out}")


if __name__ == "__main__":
    main()
