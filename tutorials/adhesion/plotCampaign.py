#!/usr/bin/python3
"""The adhesion campaign of thesis 1, chapter 5 (runCampaign): per run
sigma*, eta_app, eta_core, gammaDot_core and phi_core (eqs 5.3-5.5),
banding and depletion flagged; eta_core and phi_core interpolated at chosen
sigma* in each phi0 series and eq 5.7 fitted there, giving
phi_J(sigma*), with the adhesionless phi_J of the Couette sweep
(thesisSweep/results/sweepFit.json) as its high-stress limit.

    plotCampaign.py [--runs DIR...] [--levels S...] [--start STRAIN]
                    [--from-results]

Reads DIR/phi*_G*/: the particle checkpoints' core records (default
../couette/thesisSweep/checkpoints, committed: every segment of a run) or
the cases' particles.h5 (default ../couette/thesisSweep/run), the one of
the largest strain where both have a case; writes results/campaign.csv
(one row per run) and results/campaign.png; --from-results redraws from
the CSV without the runs.
"""

import argparse
import csv
import json
import os
import re

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost import checkpoint  # noqa: E402
from fdmPost.adhesion import adhesion_records, jamming_fraction  # noqa: E402
from fdmPost.sweep import wall_layer  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
FIELDS = ("case", "phi0", "adhesionNumber", "strain", "state", "gammaRatio",
          "sigmaStar", "sigmaStarErr", "etaApp", "etaAppErr", "etaCore",
          "etaCoreErr", "phiCore", "phiCoreErr", "phiWall")
THESIS_PHI_J = 0.592   # mu = 0.5 without adhesion (section 5.4.4)


def rows_from_runs(folders, start):
    """A row per phi*_G*/ case of the folders (checkpoints or runs; a case
    in several, the one that reached the largest strain) that has run past
    the averaging start."""
    rows = []
    for name, records in checkpoint.records_by_case(
            folders, "phi*_G*", wall_layer).items():
        if records.strain() <= start:
            print(f"{name}: at strain {records.strain():.1f}, not past the"
                  f" averaging start {start}: left out")
            continue
        p = adhesion_records(records, start)
        row = {"case": name,
               "phi0": float(re.match(r"phi([0-9.]+)_", name).group(1))}
        for k in FIELDS[2:]:
            v = p[k.removesuffix("Err")]
            row[k] = v[k.endswith("Err")] if isinstance(v, tuple) else v
        rows.append(row)
    return rows


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in FIELDS[1:]:
            if k != "state":
                r[k] = float(r[k])
    return rows


def series_of(rows):
    """The runs of each phi0, in the form jamming_fraction takes."""
    out = {}
    for r in rows:
        out.setdefault(r["phi0"], []).append(
            {k: (r[k], r[k + "Err"]) for k in ("sigmaStar", "phiCore",
                                                "etaCore")})
    return [out[k] for k in sorted(out)]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    sweep = f"{HERE}/../couette/thesisSweep"
    ap.add_argument("--runs", nargs="+",
                    default=[f"{sweep}/checkpoints", f"{sweep}/run"])
    ap.add_argument("--levels", type=float, nargs="+",
                    default=[1.0, 1.5, 2.0, 3.0, 5.0])
    ap.add_argument("--start", type=float, default=5.0)
    ap.add_argument("--from-results", action="store_true")
    args = ap.parse_args()
    table = f"{HERE}/results/campaign.csv"
    if args.from_results:
        rows = read_rows(table)
    else:
        rows = rows_from_runs(args.runs, args.start)
        if not rows:
            print(f"plotCampaign: no phi*_G*/ case with results in"
                  f" {args.runs}")
            return 1
        os.makedirs(f"{HERE}/results", exist_ok=True)
        with open(table, "w", newline="") as f:
            w = csv.DictWriter(f, FIELDS)
            w.writeheader()
            w.writerows({k: (f"{v:.6g}" if isinstance(v, float) else v)
                         for k, v in r.items()} for r in rows)
        print(f"wrote {table}")
    print(f"{'case':>24} {'G_0':>6} {'strain':>6} {'sigma*':>7}"
          f" {'eta_app':>8} {'eta_core':>15} {'gd_c/gd_0':>9}"
          f" {'phi_core':>8}  state")
    for r in rows:
        print(f"{r['case']:>24} {r['adhesionNumber']:6g} {r['strain']:6.1f}"
              f" {r['sigmaStar']:7.3f} {r['etaApp']:8.2f}"
              f" {r['etaCore']:7.2f}+-{r['etaCoreErr']:5.2f}"
              f" {r['gammaRatio']:9.3f} {r['phiCore']:8.3f}  {r['state']}")
    fits = jamming_fraction(series_of(rows), args.levels)
    limit = None
    sweep_fit = f"{HERE}/../couette/thesisSweep/results/sweepFit.json"
    if os.path.exists(sweep_fit):
        with open(sweep_fit) as f:
            limit = json.load(f)
    print("eq 5.7 at fixed sigma* (section 5.4.3 interpolation):")
    for s, (alpha, pj, ea, ej, n) in sorted(fits.items()):
        print(f"  sigma* {s:5.2f}: phi_J {pj:.4f} +- {ej:.4f}, alpha"
              f" {alpha:.3f} +- {ea:.3f} ({n} series)")
    if limit:
        print(f"  no adhesion (Couette sweep): phi_J {limit['phiJ']:.4f} +-"
              f" {limit['phiJErr']:.4f}; thesis {THESIS_PHI_J}")
    draw(rows, fits, limit, f"{HERE}/results/campaign.png")
    return 0


def draw(rows, fits, limit, path):
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for k, (phi0, runs) in enumerate(sorted(
            {r["phi0"]: [q for q in rows if q["phi0"] == r["phi0"]]
             for r in rows}.items())):
        runs.sort(key=lambda r: r["sigmaStar"])
        banded = [r["state"] == "banding" for r in runs]
        ax[0].errorbar([r["sigmaStar"] for r in runs],
                       [r["etaApp"] if b else r["etaCore"]
                        for r, b in zip(runs, banded)],
                       # a run too short for block errors: no error bar
                       yerr=np.nan_to_num([r["etaAppErr"] if b
                                           else r["etaCoreErr"]
                                           for r, b in zip(runs, banded)]),
                       fmt="o-", color=f"C{k}", label=rf"$\phi_0$ {phi0:g}")
        for r, b in zip(runs, banded):
            if b:
                ax[0].plot(r["sigmaStar"], r["etaApp"], "x", color="r", ms=9)
    ax[0].plot([], [], "rx", label=r"shear banding ($\eta_{app}$)")
    ax[0].set(xscale="log", yscale="log", xlabel=r"$\sigma^*$ (eq 5.4)",
              ylabel=r"$\eta_{core}$ (eq 5.5)")
    ax[0].legend(fontsize=7)
    if fits:
        s = sorted(fits)
        ax[1].errorbar(s, [fits[k][1] for k in s],
                       yerr=[fits[k][3] for k in s], fmt="o-",
                       label=r"eq 5.7 fits, $\mu$ = 0.5")
    ax[1].axhline(THESIS_PHI_J, color="k", ls="--",
                  label="thesis, no adhesion (0.592)")
    if limit:
        ax[1].axhspan(limit["phiJ"] - limit["phiJErr"],
                      limit["phiJ"] + limit["phiJErr"], color="0.85",
                      label="Couette sweep, no adhesion")
    ax[1].set(xscale="log", xlabel=r"$\sigma^*$", ylabel=r"$\phi_J$")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


if __name__ == "__main__":
    raise SystemExit(main())
