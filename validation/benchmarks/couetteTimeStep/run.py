#!/usr/bin/env python3
"""Benchmark (issue 30, item 1, dynamics): how the time step changes the
rheology of the sheared Couette suspension, from one common start.

From a written time T of a Couette run (runPoint), the suspension is
sheared over a strain window with each time step, the current solver
settings otherwise.  While the trajectories of the runs stay close (the
suspension has not decorrelated), the differences between them are the
time-step error itself, not statistics: per record, the core relative
viscosity, N1/Sigma_xy, N2/Sigma_xy and the
contact share of the core stress (from the particles.h5 records) are
compared with the run of the smallest step, interpolated to the same
times (rms and max over the window), and the final particle positions too
(rms and max distance in a1, periodic images taken into account).  Over
the whole window: the means of eta_core, N1, N2, contact share and
phi_core with standard errors from 5 block means, their differences from
the smallest step in units of the combined error, and the Table 4.8
columns (fdmPost.rheology.mechanical_consistency).  The
cost per unit strain is the solve time of the Timing lines (core-seconds
when each run has a core to itself: --jobs no more than the cores).

    run.py --snapshot CASE:T [--dts 1e-3,2e-3,4e-3,8e-3] [--window 0.24]
           [--jobs 2] [--name NAME] [--out DIR]

A run DT:SETTING uses a named solver setting (validation/benchmarks/
solverSettings.py, as frozenCouette: NAME[+PART...][@TOL]) instead of
layerMean; the first run of the list, by step, is the comparison.  With
the part Delta0.25 the run starts from the snapshot meshed again at
Delta = a1/4 (the same particles, fields mapped, the a1/4 sub-grid
tables), so that the comparison shows what the resolution changes.

Writes report_windowW.md and timeStep_windowW.png here (cases in
build/benchmarks/couetteTimeStep).
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
from time import sleep
from datetime import date

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.environ["FDM_PROJECT_DIR"]
sys.path.insert(0, os.path.join(PROJECT, "src", "python"))
from fdmPost.caseRunner import (foam_set, in_case, snapshot_case,  # noqa
                                timing_lines, work_lock)
from fdmPost.rheology import (channel_case, core_rheology,  # noqa
                              core_series, mechanical_consistency)
sys.path.insert(0, os.path.dirname(HERE))
from solverSettings import (apply_mesh, apply_setting,  # noqa: E402
                            case_suffix, check_setting)

# The snapshot's outer iteration with the layer-mean correction (the
# snapshot may predate it)
DEFAULT_SETTING = "layerMean"

# Core quantities compared, per particles.h5 record
QUANTITIES = ("etaCore", "N1/Sigma_xy", "N2/Sigma_xy", "contactShare")
# The same as window means (fdmPost.rheology.core_rheology keys)
MEANS = ("etaCore", "N1", "N2", "contactShare", "phiCore")
CONSISTENCY = ("wall vs particles", "volume vs particles",
               "particle forces", "particle torques")
WALL_LAYER = 5      # a1, as runPoint for a gap of 20 a1


def record_at(case, time):
    """Positions and radii of the particles.h5 record at `time`, or None."""
    import h5py
    path = os.path.join(case, "postProcessing", "particles.h5")
    if not os.path.isfile(path):
        return None
    with h5py.File(path, "r") as f:
        hit = np.flatnonzero(np.abs(np.asarray(f["time"]) - float(time))
                             < 1e-9)
        if not len(hit):
            return None
        return np.array(f["position"][hit[-1]]), np.array(f["radius"])


def velocity_alternation(case):
    """The odd-even part of the particle velocities over the records (one
    per step): rms over particles and steps of |U(n+1) - 2 U(n) + U(n-1)|/4
    in gammaDot a1, the amplitude of a velocity that flips from step to
    step; a smooth trajectory gives dt^2 |U''|/4."""
    import h5py
    with h5py.File(os.path.join(case, "postProcessing", "particles.h5"),
                   "r") as f:
        U = np.array(f["velocity"])
    second = U[2:] - 2 * U[1:-1] + U[:-2]
    return float(np.sqrt(np.mean(np.sum(second ** 2, axis=-1)))) / 4


def stopped(case):
    """The run stopped on a fatal error (too large a step stops on its own
    checks; run again, it would stop again: delete the case to retry)."""
    log = os.path.join(case, "log.fdmSuspensionFoam")
    return os.path.isfile(log) and "FOAM FATAL" in open(log).read()


def finished(case, end):
    log = os.path.join(case, "log.fdmSuspensionFoam")
    return (os.path.isfile(log) and "\nEnd\n" in open(log).read()
            and record_at(case, end) is not None)


def parse_run(item):
    """A run DT[:SETTING]: gammaDot dt and the solver setting
    (solverSettings; default layerMean, the tutorial's outer iteration)."""
    dt, _, setting = item.partition(":")
    check_setting(setting or DEFAULT_SETTING)
    return dt, setting


def prepare(snapshot, time, item, window, work):
    dt, setting = parse_run(item)
    case = os.path.join(work, "dt_%s%s_window%s" % (
        dt, "_" + case_suffix(setting) if setting else "", window))
    end = "%.12g" % (float(time) + window)
    if finished(case, end) or stopped(case):
        return case, end, False
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(snapshot, case)
    cd, pp = "system/controlDict", "constant/particleProperties"
    foam_set(case, "startFrom", "latestTime", cd)
    foam_set(case, "deltaT", dt, cd)
    foam_set(case, "endTime", end, cd)
    # Fields once, at the end (runTime: counted from this run's start)
    foam_set(case, "writeControl", "runTime", cd)
    foam_set(case, "writeInterval", window, cd)
    foam_set(case, "functions", "{}", cd)
    # Positions every step (particles.h5), the end included
    foam_set(case, "output.timeSeriesInterval", 1, pp)
    apply_mesh(case, setting or DEFAULT_SETTING, time)
    apply_setting(case, setting or DEFAULT_SETTING)
    return case, end, True


def run_all(cases, jobs):
    """fdmSuspensionFoam in each case, at most `jobs` at once (a run that
    fails is reported, not fatal: too large a step stops on its own
    checks)."""
    waiting, running = list(cases), []
    while waiting or running:
        while waiting and len(running) < jobs:
            case = waiting.pop(0)
            log = open(os.path.join(case, "log.fdmSuspensionFoam"), "w")
            running.append((case, subprocess.Popen(
                ["fdmSuspensionFoam"], cwd=case, stdout=log,
                stderr=subprocess.STDOUT, env=in_case(case))))
        sleep(1)
        for case, proc in list(running):
            if proc.poll() is not None:
                running.remove((case, proc))
                if proc.returncode != 0:
                    print("fdmSuspensionFoam failed in %s" % case)


def measure(case, start, end, window):
    """The run's core series, its window means with their standard errors
    (5 block means), the Table 4.8 columns (rms over x y z), its cost and
    final positions."""
    text = open(os.path.join(case, "log.fdmSuspensionFoam")).read()
    last = timing_lines(text)[-1]
    cs, box, _ = channel_case(case, WALL_LAYER)
    series = cs.series()
    means = core_rheology(cs, float(start), series=series)
    consistency = mechanical_consistency(case, float(start))
    return {"t": cs.t, "values": core_series(cs, series), "box": box,
            "means": {k: means[k] for k in MEANS},
            "consistency": np.sqrt((consistency ** 2).mean(axis=1)),
            "belowFloor": len(re.findall(r"below the barrier floor", text)),
            "alternation": velocity_alternation(case),
            "coreSecondsPerStrain": sum(last[3:9]) / window,
            "outerPerStep": last[0] / last[1],
            "positions": record_at(case, end)}


def failure(case):
    """How a run that failed ended: the time it reached, its outer
    iterations per step, gaps below the contact floor, particle solves not
    converged and the first line of its fatal error."""
    text = open(os.path.join(case, "log.fdmSuspensionFoam")).read()
    times = re.findall(r"^Time = (\S+)", text, re.M)
    outer = [int(n) for n in re.findall(r"converged in (\d+) outer", text)]
    fatal = re.search(r"FOAM FATAL.*?\n\s*(\S.*)", text)
    return {"time": times[-1] if times else "-",
            "outerPerStep": np.mean(outer) if outer else np.nan,
            "belowFloor": len(re.findall(r"below the barrier floor", text)),
            "notConverged": len(re.findall(r"solve not converged", text)),
            "error": fatal.group(1).strip() if fatal else "killed"}


def compare(run, ref):
    row = {}
    for i, name in enumerate(QUANTITIES):
        d = run["values"][:, i] - np.interp(run["t"], ref["t"],
                                            ref["values"][:, i])
        row[name] = (run["values"][:, i].mean(), np.sqrt(np.mean(d ** 2)),
                     np.abs(d).max())
    x, radius = run["positions"]
    dx = x - ref["positions"][0]
    for k in (0, 2):    # periodic flow and vorticity directions
        dx[:, k] -= run["box"][k] * np.round(dx[:, k] / run["box"][k])
    d = np.linalg.norm(dx, axis=1) / radius.min()
    row["position"] = (np.sqrt(np.mean(d ** 2)), d.max())
    return row


def write_report(results, dts, window, snapshot, time, failures, path):
    lines = [
        "# Time step against rheology: the sheared Couette suspension",
        "",
        "From %s at strain %s, sheared over %s strain per time step "
        "(core of the particles.h5 records, wall layers %d a1); differences "
        "against the smallest "
        "step, interpolated to each run's times (rms / max over the "
        "window); final positions in a1.  Cost from the Timing lines, %s "
        "(%d cores), %s.  Velocity alternation: the odd-even part of the "
        "particle velocities from step to step, rms in gammaDot a1 "
        "(velocity_alternation)." % (os.path.basename(snapshot), time, window,
                             WALL_LAYER,
                             os.uname().nodename, os.cpu_count(),
                             date.today().isoformat()),
        "",
        "| gammaDot dt | core-s per strain | outer per step | steps with "
        "gaps below the contact floor | velocity alternation | " +
        " | ".join("%s mean, rms diff, max diff" % n for n in QUANTITIES) +
        " | positions rms, max |",
        "|---" * (6 + len(QUANTITIES)) + "|",
    ]
    for dt in dts:
        r = results[dt]
        cells = ["%.3g, %.1e, %.1e" % r[n] for n in QUANTITIES]
        lines.append("| %s | %.0f | %.1f | %d | %.1e | %s | %.1e, %.1e |" % (
            dt, r["coreSecondsPerStrain"], r["outerPerStep"], r["belowFloor"],
            r["alternation"], " | ".join(cells), *r["position"]))
    lines += [
        "",
        "Window means over the whole window (standard error from 5 block "
        "means; the runs decorrelate over a strain or so, so on windows "
        "longer than that the differences are statistics plus time-step "
        "error); in brackets the difference from the smallest step in "
        "units of the combined standard error.  Table 4.8 columns: rms "
        "over x, y, z.",
        "",
        "| gammaDot dt | " + " | ".join(MEANS) + " | " +
        " | ".join(CONSISTENCY) + " |",
        "|---" * (1 + len(MEANS) + len(CONSISTENCY)) + "|",
    ]
    ref = results[dts[0]]["means"]
    for dt in dts:
        m = results[dt]["means"]
        cells = []
        for k in MEANS:
            (mean, err), (rmean, rerr) = m[k], ref[k]
            z = (mean - rmean) / np.hypot(err, rerr) if dt != dts[0] \
                else np.nan
            cells.append("%.4g +- %.2g" % (mean, err) +
                         ("" if np.isnan(z) else " (%+.1f)" % z))
        lines.append("| %s | %s | %s |" % (
            dt, " | ".join(cells),
            " | ".join("%.2e" % c for c in results[dt]["consistency"])))
    if failures:
        lines += ["", "Runs that stopped before the end of the window:", ""]
    for dt, f in failures.items():
        lines.append(
            "- %s: at time %s, %.1f outer iterations per step, %d gaps below "
            "the contact floor, %d particle solves not converged; %s" % (
                dt, f["time"], f["outerPerStep"], f["belowFloor"],
                f["notConverged"], f["error"]))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", path)


def plot(runs, dts, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(QUANTITIES), figsize=(16, 3.8))
    for i, (ax, name) in enumerate(zip(axes, QUANTITIES)):
        for dt in dts:
            ax.plot(runs[dt]["t"], runs[dt]["values"][:, i],
                    label="gammaDot dt %s" % dt)
        ax.set_xlabel("strain")
        ax.set_title(name)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path,
                dpi=110)


def main():
    ap = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--snapshot", required=True, help="CASE:T")
    ap.add_argument("--dts", default="1e-3,2e-3,4e-3,8e-3")
    ap.add_argument("--window", type=float, default=0.24)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--name", help="report_NAME.md, timeStep_NAME.png "
                    "(default window<W>)")
    ap.add_argument("--out", default=HERE, help="folder of the report and "
                    "plot (default this benchmark's)")
    args = ap.parse_args()
    name = args.name or "window%g" % args.window
    dts = sorted(args.dts.split(","),
                 key=lambda r: (float(parse_run(r)[0]), r))
    for dt in dts:
        steps = args.window / float(parse_run(dt)[0])
        if abs(steps - round(steps)) > 1e-6 * steps:
            raise SystemExit("--window %s is not a whole number of steps of "
                             "%s" % (args.window, dt))
    work = os.path.join(PROJECT, "build", "benchmarks", "couetteTimeStep")
    lock = work_lock(work)  # noqa: F841 (held until the process ends)
    source, _, time = args.snapshot.rpartition(":")
    snap = snapshot_case(os.path.abspath(source), time, work)
    prepared = {dt: prepare(snap, time, dt, args.window, work) for dt in dts}
    run_all([c for c, _, todo in prepared.values() if todo], args.jobs)
    failures = {dt: failure(case) for dt, (case, end, _) in prepared.items()
                if not finished(case, end)}
    dts = [dt for dt in dts if dt not in failures]
    runs = {dt: measure(prepared[dt][0], time, prepared[dt][1], args.window)
            for dt in dts}
    results = {}
    for dt in dts:
        results[dt] = compare(runs[dt], runs[dts[0]])
        results[dt].update((k, runs[dt][k]) for k in (
            "coreSecondsPerStrain", "outerPerStep", "belowFloor", "means",
            "alternation",
            "consistency"))
    write_report(results, dts, args.window, snap, time, failures,
                 os.path.join(args.out, "report_%s.md" % name))
    plot(runs, dts, os.path.join(args.out, "timeStep_%s.png" % name))


if __name__ == "__main__":
    main()
