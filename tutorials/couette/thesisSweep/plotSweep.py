#!/usr/bin/python3
"""Core rheology of the Couette sweep (thesis 1, section 4.2.2, Table 4.7)
against the thesis' fit and the published closures:

  eta_core(phi_core) against Maron-Pierce eta = 0.803/(1 - phi/0.59)^2
  (eq 4.12, the thesis' own fit) and our own weighted fit of alpha and
  phi_J with their standard errors;
  N1/Sigma12, N2/Sigma12, the contact share and the contact normal
  stresses hat Sigma^c_ii (eq 4.13) against phi_core/phi_J, with Morris &
  Boulay (1999) and Boyer et al. (2011) as cross-checks (each at its own
  phi_m: they are drawn against phi/phi_m), and the fitted closure
  hat Sigma^c_22 = beta (phi/phi_J)^n that fdmPost.suspensionBalance
  .sweep_poiseuille gives the suspension balance model.

    plotSweep.py [--runs DIR...] [--start STRAIN] [--from-results]

Reads every DIR/phi*/: a particle checkpoint's coreRecords.csv (the whole
run over all its segments; default checkpoints/, committed) or a case's
particles.h5 (default run/), the one of the largest strain where both
have the case; merges the points into the reduced data results/sweep.csv
(a point whose run and checkpoint are not here stays), writes the fits to
results/sweepFit.json and results/sweep.png.  --from-results redraws from
results/sweep.csv alone.  Wall layer 5 a1 for Ly >= 20, else Ly/4 (as
runPoint); averages from strain 5, or from a third of a run shorter than
15, which is drawn but not fitted (still in its transient).
"""

import argparse
import json
import os

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost import checkpoint, sweep  # noqa: E402
from fdmPost.rheology import (core_rheology, maron_pierce,  # noqa: E402
                              morris_boulay, morris_boulay_normal)
from fdmPost.suspensionBalance import boyer_friction  # noqa: E402

THESIS_ALPHA, THESIS_PHI_J = 0.803, 0.59


def rows_from_runs(folders, start_at):
    """A row per adhesionless phi*/ case of the folders (checkpoints or
    runs; a case in several, the one that reached the largest strain)."""
    rows = []
    for name, records in checkpoint.records_by_case(
            folders, "phi*", sweep.wall_layer).items():
        if records.meta.get("adhesionNumber", 0.0):
            continue    # the adhesion campaign's (plotCampaign.py)
        strain = records.strain()
        start = start_at if start_at is not None else \
            sweep.averaging_start(strain)
        rows.append(sweep.point_row(
            name, strain, start, records.meta["box"],
            core_rheology(records, start / records.meta["shearRate"])))
    return rows


def print_table(rows, fit):
    print(f"{'case':>18} {'strain':>6} {'phi_core':>13} {'eta_core':>14}"
          f" {'eq 4.12':>7} {'dev':>6} {'N1/S12':>13} {'N2/S12':>13}"
          f" {'contact':>13} {'Sc11/S12':>13} {'Sc22/S12':>13}"
          f" {'Sc33/S12':>13}")
    for r in rows:
        f = lambda k: f"{r[k]:.3f}+-{r[k + 'Err']:.3f}"  # noqa: E731
        thesis = maron_pierce(r["phiCore"])
        print(f"{r['case']:>18} {r['strain']:6.1f} {f('phiCore'):>13}"
              f" {f('etaCore'):>14} {thesis:7.2f}"
              f" {100 * (r['etaCore'] / thesis - 1):+5.1f}%"
              + "".join(f" {f(k):>13}" for k in
                        ("N1", "N2", "contactShare", "contact11",
                         "contact22", "contact33")))
    if fit is None:
        print("fits: fewer than three points")
        return
    print(f"Maron-Pierce fit (eq 4.12, {fit['points']} points, weighted by"
          f" the standard errors): alpha {fit['alpha']:.3f} +-"
          f" {fit['alphaErr']:.3f}, phi_J {fit['phiJ']:.4f} +-"
          f" {fit['phiJErr']:.4f} (thesis {THESIS_ALPHA}, {THESIS_PHI_J})")
    print(f"contact normal closure |Sc22|/S12 = beta (phi/phi_J)^n: beta"
          f" {fit['beta']:.3f} +- {fit['betaErr']:.3f}, n {fit['n']:.2f}"
          f" +- {fit['nErr']:.2f}")


def print_core_against_table_4_7(rows):
    """phi_core and gammaDot_core/gammaDot_0 next to the thesis' Table 4.7
    (its boxes): the wall layers' depletion and slip."""
    print(f"{'case':>18} {'phi_core':>13} {'Table 4.7':>9}"
          f" {'gdot_core/gdot_0':>16} {'Table 4.7':>9}")
    for r in rows:
        phi, rate = sweep.TABLE_4_7.get(sweep.phi0_of(r["case"]),
                                        (np.nan, np.nan))
        print(f"{r['case']:>18} {r['phiCore']:7.3f}+-{r['phiCoreErr']:.3f}"
              f" {phi:9.3f} {r['gammaDotCore']:10.3f}+-"
              f"{r['gammaDotCoreErr']:.3f} {rate:9.3f}")


def draw(rows, fit, path):
    phi_r = np.array([r["phiCore"] for r in rows]) / THESIS_PHI_J
    x = np.linspace(0.3, 0.98, 200)
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.3))
    phi = x * THESIS_PHI_J
    ax[0].plot(phi, maron_pierce(phi), "k-", label="thesis fit (eq 4.12)")
    if fit is not None:
        ax[0].plot(phi, maron_pierce(phi, fit["alpha"], fit["phiJ"]), "r--",
                   label=rf"this sweep: $\alpha$ {fit['alpha']:.2f},"
                   rf" $\phi_J$ {fit['phiJ']:.3f}")
    ax[0].plot(x * 0.68, morris_boulay(x * 0.68)[0], "k:",
               label="Morris & Boulay 1999")
    ax[0].plot(x * 0.585, boyer_friction(x * 0.585)[1], "k-.",
               label="Boyer et al. 2011")
    for young in (False, True):
        some = [r for r in rows if sweep.in_transient(r) == young]
        if some:
            ax[0].errorbar(
                [r["phiCore"] for r in some], [r["etaCore"] for r in some],
                # a run too short for block errors has none
                xerr=np.nan_to_num([r["phiCoreErr"] for r in some]),
                yerr=np.nan_to_num([r["etaCoreErr"] for r in some]),
                fmt="o", color="C3",
                mfc="none" if young else "C3",
                label="still in its transient, not fitted" if young
                else "fdmSuspensionFoam (core)")
    ax[0].set(yscale="log", xlabel=r"$\phi_{core}$", ylabel=r"$\eta_{core}$",
              xlim=(0.2, 0.6))
    eta_mb, n1_mb, n2_mb = morris_boulay(x * 0.68)
    ax[1].plot(x, n1_mb, "C0:", label=r"$\hat N_1$ Morris & Boulay")
    ax[1].plot(x, n2_mb, "C1:", label=r"$\hat N_2$ Morris & Boulay")
    for k, (key, lab) in enumerate([("N1", r"$\hat N_1$"),
                                    ("N2", r"$\hat N_2$"),
                                    ("contactShare", r"$\hat\Sigma^c_{12}$")]):
        ax[1].errorbar(phi_r, [r[key] for r in rows],
                       yerr=[r[key + "Err"] for r in rows], fmt="os^"[k],
                       color=f"C{k}", label=lab)
    mb_n = {i: -morris_boulay_normal(x * 0.68, i) / eta_mb for i in (1, 2, 3)}
    for k in (1, 2, 3):
        key = f"contact{k}{k}"
        ax[2].errorbar(phi_r, [r[key] for r in rows],
                       yerr=[r[key + "Err"] for r in rows], fmt="os^"[k - 1],
                       color=f"C{k - 1}", label=rf"$\hat\Sigma^c_{{{k}{k}}}$")
        ax[2].plot(x, mb_n[k], f"C{k - 1}:")
    ax[2].plot([], [], "k:", label=r"$-\eta_{ii}/\eta_s$ Morris & Boulay")
    ax[2].plot(x, -1 / boyer_friction(x * 0.585)[0], "C1-.",
               label=r"$-1/\mu(J)$ Boyer et al.")
    if fit is not None:
        ax[2].plot(x, -sweep.contact_normal_closure(x, fit["beta"], fit["n"]),
                   "C1--", label=r"fit $-\beta(\phi/\phi_J)^n$")
    for a in ax[1:]:
        a.set_xlabel(r"$\phi_{core}/\phi_J$ ($\phi_J$ = 0.59; closures:"
                     r" $\phi/\phi_m$)")
        a.axhline(0, color="grey", lw=0.5)
        a.legend(fontsize=7)
    ax[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--runs", nargs="+",
                    default=[f"{here}/checkpoints", f"{here}/run"],
                    help="folders of the phi*/ cases or checkpoints"
                    " (default checkpoints/ run/)")
    ap.add_argument("--start", type=float, default=None,
                    help="strain where averages start (default: runPoint's)")
    ap.add_argument("--from-results", action="store_true",
                    help="redraw from results/sweep.csv, without the runs")
    args = ap.parse_args()
    table = f"{here}/results/sweep.csv"
    if args.from_results:
        rows = sweep.read_points(table)
    else:
        rows = rows_from_runs(args.runs, args.start)
        if not rows:
            print(f"plotSweep: no phi*/ case with results in {args.runs}"
                  " (run runPoint or runSweep first)")
            return 1
        # Points whose runs and checkpoints are not here stay in the table
        found = {r["case"] for r in rows}
        kept = [r for r in sweep.read_points(table)
                if r["case"] not in found] if os.path.exists(table) else []
        rows = sorted(kept + rows, key=lambda r: r["phiCore"])
        sweep.write_points(table, rows)
        print(f"wrote {table}")
    fit = sweep.fit_sweep(rows)
    print_table(rows, fit)
    print_core_against_table_4_7(rows)
    if fit is not None:
        with open(f"{here}/results/sweepFit.json", "w") as f:
            json.dump(fit, f, indent=1)
    draw(rows, fit, f"{here}/results/sweep.png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
