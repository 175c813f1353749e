#!/usr/bin/env python3
"""Benchmark (issue 30): how often a sheared suspension needs a record.

A record (a step written to particles.h5) is solved to the tight lambda
residual; the steps between records only move the particles.  The window
means of the core rheology are what a record is for, and their standard
error is set by how long the stress stays correlated (thesis appendix G:
the statistical inefficiency), not by the number of records once they are
closer than that.  From the particles.h5 series of one run with records
every k steps, this keeps every m-th record (m = 1 ... M) and reports per
quantity (core eta, N1/Sigma_xy, N2/Sigma_xy, contact share):

- the integrated autocorrelation strain tau (fdmPost.rheology.
  autocorrelation_time) of the full series;
- the standard error of the window mean, sqrt(2 tau_m var / W), with
  tau_m from the kept records, and the same from 5 block means, each as a
  ratio to the full series' value.

With an exponential correlation of strain tau, records every d strain give
a standard error (d/2tau coth(d/2tau))^(1/2) times that of a continuous
record: 1.01 at d = tau/2, 1.04 at d = tau, 1.15 at d = 2 tau (printed as
the model column).

    run.py CASE [CASE ...] --start T [--every 1,2,3,4,5]

Writes report.md and recordInterval.png here.
"""

import argparse
import os
import sys
from datetime import date

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.environ["FDM_PROJECT_DIR"]
sys.path.insert(0, os.path.join(PROJECT, "src", "python"))
from fdmPost.rheology import (autocorrelation_time, block_mean,  # noqa
                              channel_case, core_series)

QUANTITIES = ("etaCore", "N1/Sigma_xy", "N2/Sigma_xy", "contactShare")
WALL_LAYER = 5      # a1, as runPoint for a gap of 20 a1


def standard_errors(x, dt):
    """(tau, autocorrelation standard error, block standard error) of the
    mean of an evenly sampled series x with spacing dt (in strain)."""
    tau = autocorrelation_time(x, dt)
    window = dt * len(x)
    tau_se = np.sqrt(2 * max(tau, dt / 2) * np.var(x) / window)
    return tau, tau_se, block_mean(x)[1]


def model_ratio(d, tau):
    """Standard error with records every d against a continuous record,
    exponential correlation of strain tau."""
    z = d / (2 * tau)
    return np.sqrt(z / np.tanh(z))


def analyse(case, start, every):
    cs, _, _ = channel_case(case, WALL_LAYER)
    keep = cs.t >= start
    t = cs.t[keep]
    values = core_series(cs)[keep]
    dt = float(np.median(np.diff(t)))
    rows = []
    for j, name in enumerate(QUANTITIES):
        full = standard_errors(values[:, j], dt)
        for m in every:
            tau, tau_se, block_se = standard_errors(values[::m, j], m * dt)
            rows.append({
                "quantity": name, "every": m, "interval": m * dt,
                "records": len(values[::m, j]), "mean": values[::m, j].mean(),
                "tau": tau, "tauFull": full[0],
                "tauRatio": tau_se / full[1], "blockRatio": block_se / full[2],
                "model": model_ratio(m * dt, full[0]) / model_ratio(dt, full[0]),
            })
    return {"case": case, "window": t[-1] - t[0] + dt, "dt": dt,
            "records": len(t), "rows": rows}


def report(results):
    lines = [
        "# Record interval against the standard error of window means",
        "",
        f"Measured {date.today().isoformat()} (`run.py`).  Core of the "
        f"particles.h5 records (wall layers {WALL_LAYER} a1).  Ratios to the "
        "full series' standard error; `model` is the exponential-"
        "correlation prediction from the full series' tau.", ""]
    for r in results:
        lines += [
            f"## {os.path.basename(r['case'].rstrip('/'))}", "",
            f"{r['records']} records every {r['dt']:.3g} strain over "
            f"{r['window']:.3g} strain.", "",
            "| quantity | record every (strain) | records | mean | tau (strain) "
            "| SE ratio (tau) | SE ratio (5 blocks) | model |",
            "|---|---|---|---|---|---|---|---|"]
        for row in r["rows"]:
            lines.append(
                f"| {row['quantity']} | {row['interval']:.3g} | "
                f"{row['records']} | {row['mean']:.4g} | {row['tau']:.3g} | "
                f"{row['tauRatio']:.3f} | {row['blockRatio']:.3f} | "
                f"{row['model']:.3f} |")
        lines.append("")
    with open(os.path.join(HERE, "report.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


def plot(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(QUANTITIES), figsize=(14, 3.6),
                             sharey=True)
    for ax, name in zip(axes, QUANTITIES):
        for k, r in enumerate(results):
            rows = [row for row in r["rows"] if row["quantity"] == name]
            d = [row["interval"] for row in rows]
            label = os.path.basename(r["case"].rstrip("/"))[:24]
            ax.plot(d, [row["tauRatio"] for row in rows], "o-",
                    label=f"{label} (tau)")
            ax.plot(d, [row["blockRatio"] for row in rows], "s--",
                    label=f"{label} (blocks)")
            ax.plot(d, [row["model"] for row in rows], "k:",
                    label=None if k else "exponential model")
        ax.set_title(name)
        ax.set_xlabel("record interval (strain)")
        ax.axhline(1, color="grey", lw=0.5)
    axes[0].set_ylabel("standard error / every record's")
    axes[0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "recordInterval.png"), dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("cases", nargs="+")
    parser.add_argument("--start", type=float, required=True)
    parser.add_argument("--every", default="1,2,3,4,5")
    args = parser.parse_args()
    every = [int(m) for m in args.every.split(",")]
    results = [analyse(c, args.start, every) for c in args.cases]
    report(results)
    plot(results)


if __name__ == "__main__":
    main()
