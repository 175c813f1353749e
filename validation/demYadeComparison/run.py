#!/usr/bin/env python3
"""lubricatedDEMFoam against YADE, side by side (thesis 2's implicit
lubricated contact; YADE's Law2_ScGeom_ImplicitLubricationPhys is the code
the thesis ran).  Each case is one packing sheared in both codes from the
same particle list and dictionaries, one core per code; YADE reads the
project's files itself (yadeShear.py).  Per case: sigma_xy series of both
codes, their early difference (while the trajectories coincide: one
dynamics, not two samples), means after --start with block errors (eta_r,
mu, N1, N2, contact share, interactions and contacts per particle) and
microseconds per particle-step of each code, measured in the same run.

Cases (build/validation/demYadeComparison/NAME):

  tutorial0.45, tutorial0.50   tutorials/lubricatedShear's parameters in a
      20 a1 cell (bidisperse 1:1.4, g 1e6, roughness 1e-2, friction 0.4,
      cut-off 2a), to strain 3
  tutorial0.50res2   the same as tutorial0.50 with YADE's log-gap
      resolution 2 (the shipped example's), to strain 0.25: its rolling and
      twisting torques act only at gaps above a (the reverse of resolution
      3 and of the paper)
  article3_mu0.4_0.45, ..._0.50, article3_mu0.5_...   article 3's
      parameters: monodisperse with 5 % Gaussian polydispersity, roughness
      1e-3 (stiffness 1e7, a third of the step), friction 0.4 and 0.5,
      cut-off 2a, 16 a1 cell, to strain 1.5
  article3_mu0.4_0.45_halfStep, _smooth, _mono   where the two codes'
      small separation comes from: half the step, roughness 0 (lubrication
      only) and equal spheres, to strain 0.5, 0.5 and 0.1
  speed1e3, speed1e4   cost only (validation/benchmarks/demCost): the
      tutorial's parameters at phi 0.4 in 25 and 54 a1 cells (about 10^3
      and 10^4 spheres), 0.1 and 0.04 strain

    run.py [--cases NAME,...] [--jobs 2] [--report report.md]

Each case is also run by lubricatedDEMFoam with its first sphere moved by
1e-9 a1 (NAME_perturbed): how fast the project's own trajectories separate,
the yardstick for the two codes' separation (the dynamics is chaotic).

PASS: the sigma_xy difference stays below 1e-3 of the mean sigma_xy up to
strain 0.5, and eta_r, mu and the contact share are equal within twice
their combined standard error.  Writes report.md and one PNG per case
here.  Needs YADE (Debian package yade); says so if it is absent.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from datetime import date

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.environ["FDM_PROJECT_DIR"]
TUTORIAL = os.path.join(PROJECT, "tutorials", "lubricatedShear")
sys.path.insert(0, os.path.join(PROJECT, "src", "python"))
from fdmPost.caseRunner import foam_set, in_case  # noqa: E402
from fdmPost.demRheology import (PARTS, read_series,  # noqa: E402
                                 series_averages, series_header,
                                 stress_column)
from fdmPost.particleCase import series_rows  # noqa: E402
from fdmPre.particleList import read_particle_list  # noqa: E402

WORK = os.path.join(PROJECT, "build", "validation", "demYadeComparison")
PP = "constant/particleProperties"
EARLY_STRAIN, EARLY_TOL = 0.5, 1e-3


def tutorial(phi):
    return {"box": 20, "pack": ["--phi", str(phi)], "set": {},
            "endTime": 3.0, "start": 1.0, "resolution": 3}


def article3(phi, friction):
    return {"box": 16, "pack": ["--phi", str(phi), "--ratio", "1",
                                "--polydispersity", "0.05"],
            "set": {"lubricatedContact.roughness": 1e-3,
                    "lubricatedContact.stiffness": 1e7,
                    "lubricatedContact.friction": friction,
                    "deltaT": 4e-5 / 3},
            "endTime": 1.5, "start": 0.75, "resolution": 3}


# A case with a "label" measures something (named in the report's last
# column) instead of passing or failing
COST_ONLY = "cost only"


def speed(box, end):
    """Cost only: the tutorial's parameters at phi 0.4, a short run."""
    return {"box": box, "pack": ["--phi", "0.4"], "set": {},
            "endTime": end, "start": 0, "resolution": 3,
            "label": COST_ONLY}


CASES = {
    "tutorial0.45": tutorial(0.45),
    "tutorial0.50": tutorial(0.50),
    "tutorial0.50res2": dict(tutorial(0.50), endTime=0.25, resolution=2,
                             label="measures resolution 2"),
}
CASES.update(("article3_mu%g_%.2f" % (mu, phi), article3(phi, mu))
             for mu in (0.4, 0.5) for phi in (0.45, 0.50))
# Is the two codes' separation a time-discretisation difference?  Half the
# step, to strain 0.5
CASES["article3_mu0.4_0.45_halfStep"] = dict(
    article3(0.45, 0.4), endTime=0.5, start=0.25, label="half step")
CASES["article3_mu0.4_0.45_halfStep"]["set"]["deltaT"] = 2e-5 / 3
# Are contacts opening and closing a step apart the cause?  Smooth spheres
# (roughness 0: lubrication only), to strain 0.5
CASES["article3_mu0.4_0.45_smooth"] = dict(
    article3(0.45, 0.4), endTime=0.5, start=0.25, label="smooth")
CASES["article3_mu0.4_0.45_smooth"]["set"]["lubricatedContact.roughness"] = 0
# Equal spheres (no polydispersity), to strain 0.1: do the codes differ
# where radii differ?
CASES["article3_mu0.4_0.45_mono"] = dict(
    article3(0.45, 0.4), endTime=0.1, start=0.05, label="monodisperse",
    pack=["--phi", "0.45", "--ratio", "1"])
# Cost at about 10^3 and 10^4 spheres (validation/benchmarks/demCost)
CASES.update(speed1e3=speed(25, 0.1), speed1e4=speed(54, 0.04))


def prepare(name, spec):
    case = os.path.join(WORK, name)
    if os.path.isfile(os.path.join(case, "constant", "particleList")):
        return case
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    for d in ("constant", "system"):
        shutil.copytree(os.path.join(TUTORIAL, d), os.path.join(case, d))
    L = spec["box"]
    subprocess.run(["fdmPackParticles", "--box", str(L), str(L), str(L),
                    "--walls", "", "--seed", "1", "-o",
                    "constant/particleList"] + spec["pack"], cwd=case,
                   check=True, stdout=subprocess.DEVNULL, env=in_case(case))
    foam_set(case, "cell.max", "(%d %d %d)" % (L, L, L), PP)
    foam_set(case, "endTime", spec["endTime"], "system/controlDict")
    for key, value in spec["set"].items():
        foam_set(case, key, value, "system/controlDict" if key == "deltaT"
                 else PP)
    return case


def perturbed(case):
    """A copy of the case with the first sphere moved by 1e-9 a1 along x:
    how far the project's own trajectory separates from a round-off-sized
    change, the yardstick for the separation of the two codes."""
    copy = case + "_perturbed"
    if os.path.isdir(copy):
        return copy
    os.makedirs(copy)
    for d in ("constant", "system"):
        shutil.copytree(os.path.join(case, d), os.path.join(copy, d))
    path = os.path.join(copy, "constant", "particleList")
    lines = open(path).read().split("\n")
    first = next(i for i, line in enumerate(lines)
                 if line.startswith("(") and "(" in line[1:])
    group, rest = lines[first][1:].split("(", 1)
    x, tail = rest.split(" ", 1)
    lines[first] = "(%s(%.15g %s" % (group, float(x) + 1e-9, tail)
    open(path, "w").write("\n".join(lines))
    return copy


def yade_file(case, resolution):
    return os.path.join(case, "yade_resolution%d.dat" % resolution)


def run_project(case):
    log = os.path.join(case, "log.lubricatedDEMFoam")
    if os.path.isfile(log) and "\nEnd" in open(log).read():
        return
    with open(log, "w") as f:
        subprocess.run(["lubricatedDEMFoam"], cwd=case, stdout=f,
                       stderr=subprocess.STDOUT, env=in_case(case),
                       check=True)


def project_us(case):
    """Microseconds per particle-step of the time loop, from the solver's
    closing line (End: N steps, T s, R particle-steps/s)."""
    text = open(os.path.join(case, "log.lubricatedDEMFoam")).read()
    rate = re.search(r"End: \d+ steps, \S+ s, (\S+) particle-steps/s", text)
    return 1e6 / float(rate.group(1))


def run_yade(case, resolution):
    out = yade_file(case, resolution)
    if os.path.isfile(out) and "# wall seconds" in open(out).read():
        return
    with open(os.path.join(case, "log.yade%d" % resolution), "w") as f:
        subprocess.run(["yade", "-j1", "-n", "-x",
                        os.path.join(HERE, "yadeShear.py"), case, out,
                        str(resolution)], cwd=case, stdout=f,
                       stderr=subprocess.STDOUT, env=in_case(case),
                       check=True)


def yade_series(path):
    eta, rate = series_header(path)
    rows = series_rows([path])
    tail = open(path).read().rsplit("# wall seconds", 1)[1]
    return rows, eta, rate, float(tail.split("us per particle-step")[1])


def compare(name, spec, case):
    """The report row of a case: both series (records every output
    interval from the first, so aligned by index), early difference, means,
    cost, result."""
    n = len(read_particle_list(os.path.join(case, "constant",
                                            "particleList"))[2])
    d_p, eta, rate = read_series(case)
    d_y, _, _, us_y = yade_series(yade_file(case, spec["resolution"]))
    us_p = project_us(case)
    scale = eta * abs(rate)

    def total_xy(d):
        return sum(stress_column(d, p, "xy") for p in PARTS) / scale

    m = min(len(d_p), len(d_y))
    strain = d_p[:m, 1]
    diff = total_xy(d_y[:m]) - total_xy(d_p[:m])
    start = min(spec["start"], 0.5 * spec["endTime"])
    a_p = series_averages(d_p, eta, rate, start)
    a_y = series_averages(d_y, eta, rate, start)
    early = strain <= EARLY_STRAIN
    early_diff = np.abs(diff[early]).max() / abs(a_p["eta_r"][0])
    chaos = float("nan")
    if os.path.isdir(case + "_perturbed"):
        d_q = read_series(case + "_perturbed")[0]
        k = min(len(d_p), len(d_q))
        self_diff = total_xy(d_q[:k]) - total_xy(d_p[:k])
        chaos = (np.abs(self_diff[d_p[:k, 1] <= EARLY_STRAIN]).max()
                 / abs(a_p["eta_r"][0]))
    row = {"name": name, "n": n, "phi": a_p["phi"], "usProject": us_p,
           "usYade": us_y, "earlyDiff": early_diff, "chaos": chaos,
           "project": a_p, "yade": a_y, "strain": strain, "diff": diff,
           "xyProject": total_xy(d_p), "xyYade": total_xy(d_y),
           "strainProject": d_p[:, 1], "strainYade": d_y[:, 1],
           "start": start, "resolution": spec["resolution"]}
    checks = [early_diff < EARLY_TOL]
    for key in ("eta_r", "muBlocks", "contactShare"):
        (mp, ep), (my, ey) = a_p[key], a_y[key]
        row[key + "Sigmas"] = (my - mp) / np.hypot(ep, ey)
        checks.append(abs(my - mp) <= 2 * np.hypot(ep, ey))
    row["pass"] = spec.get("label", all(checks))
    return row


def plot(row):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    ax[0].plot(row["strainProject"], row["xyProject"], "k", lw=0.8,
               label="lubricatedDEMFoam")
    ax[0].plot(row["strainYade"], row["xyYade"], "r--", lw=0.8,
               label="YADE resolution %d" % row["resolution"])
    ax[0].axvline(row["start"], color="0.6", ls=":")
    ax[0].set_xlabel("strain")
    ax[0].set_ylabel(r"$\sigma_{xy}/\eta\dot\gamma$")
    ax[0].set_title(row["name"])
    ax[0].legend(fontsize=8)
    mean = abs(row["project"]["eta_r"][0])
    ax[1].semilogy(row["strain"], np.abs(row["diff"]) / mean + 1e-12, "b",
                   lw=0.6)
    ax[1].axhline(EARLY_TOL, color="r", ls="--", label="1e-3")
    ax[1].axvline(EARLY_STRAIN, color="0.6", ls=":")
    ax[1].set_xlabel("strain")
    ax[1].set_ylabel(r"$|\Delta\sigma_{xy}|$ / mean $\sigma_{xy}$")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "%s.png" % row["name"]), dpi=110)
    plt.close(fig)


def fmt(pair):
    return "%.4g ± %.2g" % pair


def write_report(rows, failed, path):
    lines = [
        "# lubricatedDEMFoam against YADE %s" % yade_version(), "",
        "Same packing, dictionaries and step in both codes, one core each "
        "(`run.py`), %s, %s.  Early difference: max |Δσ_xy| up to strain "
        "%g over the mean σ_xy; means after the start strain with block "
        "errors (5 blocks), in brackets YADE minus project in combined "
        "standard errors.  µs per particle-step: the time of each code's "
        "stepping loop (the project's closing line, YADE's O.run calls) "
        "over particles × steps." % (os.uname().nodename, date.today(), EARLY_STRAIN), "",
        "| case | N | φ | early diff | the same, project perturbed | η_r project | η_r YADE | μ project "
        "| μ YADE | contact share project | YADE | N1/σ_xy p, Y | "
        "N2/σ_xy p, Y | interactions/particle p, Y | contacts/particle "
        "p, Y | µs/particle-step p, Y (ratio) | result |",
        "|" + "---|" * 17]
    for r in rows:
        p, y = r["project"], r["yade"]
        lines.append(
            "| %s | %d | %.3f | %.1e | %.1e | %s | %s (%+.1f) | %s | %s (%+.1f) | "
            "%s | %s (%+.1f) | %.3f, %.3f | %.3f, %.3f | %.2f, %.2f | "
            "%.2f, %.2f | %.2f, %.2f (%.1f) | %s |" % (
                r["name"], r["n"], r["phi"], r["earlyDiff"], r["chaos"],
                fmt(p["eta_r"]), fmt(y["eta_r"]), r["eta_rSigmas"],
                fmt(p["muBlocks"]), fmt(y["muBlocks"]), r["muBlocksSigmas"],
                fmt(p["contactShare"]), fmt(y["contactShare"]),
                r["contactShareSigmas"], p["N1"], y["N1"], p["N2"], y["N2"],
                2 * p["interactions"] / r["n"], 2 * y["interactions"] / r["n"],
                2 * p["contacts"] / r["n"], 2 * y["contacts"] / r["n"],
                r["usProject"], r["usYade"], r["usYade"] / r["usProject"],
                {True: "PASS", False: "FAIL"}.get(r["pass"], r["pass"])))
    lines += ["", "Failed runs (a code stopped; see its log in the case): %s"
              % (", ".join(failed) or "none")]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


def yade_version():
    out = subprocess.run(["yade", "--version"], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT)
    return out.stdout.decode().split("\n")[0].split()[-1]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--cases", default=",".join(
        n for n in CASES if CASES[n].get("label") != COST_ONLY))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--report", default=os.path.join(HERE, "report.md"))
    args = ap.parse_args()
    if shutil.which("yade") is None:
        raise SystemExit("YADE is not installed: apt-get install yade "
                         "(Debian package, YADE 2023.02a), then rerun")
    names = args.cases.split(",")
    for n in names:
        if n not in CASES:
            raise SystemExit("unknown case %s (known: %s)"
                             % (n, ", ".join(CASES)))
    cases = {n: prepare(n, CASES[n]) for n in names}
    with ThreadPoolExecutor(args.jobs) as pool:
        jobs = []
        for n in names:
            jobs.append((n, pool.submit(run_yade, cases[n],
                                        CASES[n]["resolution"])))
            jobs.append((n, pool.submit(run_project, cases[n])))
            if "label" not in CASES[n]:
                jobs.append((n, pool.submit(run_project,
                                            perturbed(cases[n]))))
        failed = set()
        for n, j in jobs:
            try:
                j.result()
            except subprocess.CalledProcessError as e:
                print("%s failed: %s (see the logs in %s)" % (n, e, cases[n]))
                failed.add(n)
    rows = [compare(n, CASES[n], cases[n]) for n in names if n not in failed]
    for r in rows:
        plot(r)
    write_report(rows, sorted(failed), args.report)


if __name__ == "__main__":
    main()
