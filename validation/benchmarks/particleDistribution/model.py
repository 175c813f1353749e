#!/usr/bin/env python3
"""Issue 38's baseline and model: memory per rank, time per step and
communication per step of the particle side, the replicated scheme (every
rank holds every particle, sums the per-particle integrals over all ranks
and solves the whole particle system) against particles owned by subdomain
(each rank holds its own particles and the ghosts within the halo,
exchanges with its neighbours and solves its block of the system with a
parallel CG).  Beside them, the solver's parallelParticleSolve distributed
as it is now ("now", fdm::particleHalo): owned by subdomain, but each
rank's particle lists are indexed by every particle (only the entries of
its own and its ghosts current), the owners are agreed by a reduction of
one label per particle and step, each step scans those lists a few times,
every exchange sends its sizes to all ranks (PstreamBuffers), and the
owners send their particles' records to the master, which writes the time
series (particles.h5) alone.

The particle-side constants are measured here: the per-particle time of
pair search, assembly and solve and the memory per particle come from the
particleSystemScaling report (its two largest sizes, where the fixed
overheads no longer count); the fluid side's time per cell-step and memory
per cell from the thesis box (validation/README.md, couetteTimeStep and
couetteCost: 799 core-s per strain over 250 steps at 10^6 cells, 2.0-2.3
GiB).  The network and the counts per step are assumptions, stated in
ASSUMPTIONS and printed with the tables.

    model.py [--system REPORT] [--solver inSolver.md]   (prints the report)
"""

import argparse
import math
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))

ASSUMPTIONS = {
    # Fluid side, measured on the thesis box (10^6 cells, 547 spheres)
    "cellStepSeconds": 3.2e-6,   # core-s per cell and step, all of a step
    "cellBytes": 2.2e3,          # resident bytes per cell
    # The thesis' Couette boxes: cells per particle and particles per core
    "cellsPerParticle": 1.0e6 / 547,
    "particlesPerCore": 547 / 64,    # Table 4.9, phi0 0.42 on 64 cores
    # Per step: outer iterations (integrals summed each), factorisations
    # of the particle system (the step's and two relinearisations) and CG
    # iterations per solve
    "outerIterations": 4.7,
    "factorisations": 3,
    "cgIterations": 10,
    # Geometry, in a1: the halo a ghost is needed within (the largest
    # pair's centre distance at the sub-grid cut-off, 0.3 a_max: 2 a_max +
    # 0.3 a_max, a_max = 1.4), number of scalars exchanged per particle
    # (the support integrals of eq 2.43: 12; velocities: 6)
    "halo": 2 * 1.4 + 0.3 * 1.4,
    "integralScalars": 12,
    "velocityScalars": 6,
    "neighbourRanks": 26,
    # The scheme as it is now: bytes of the lists indexed by every particle
    # on every rank (state, loads, moments, owners, stencil offsets; an
    # upper estimate), seconds per particle and step for the scans of
    # those lists, exchanges per step (moments, overlap blocks, contact
    # histories, the move, the dipoles; per outer iteration the integrals
    # and the velocities)
    "listBytes": 1024,
    "scanSeconds": 5e-8,
    "fixedExchanges": 5,
    "exchangesPerOuter": 2,
    # Output: a time series record every 40 steps (0.16 strain at gammaDot
    # deltaT 4e-3, thesisSweep/runPoint), gathered on the master (position,
    # velocities, Adams-Bashforth history, hydrodynamic and contact loads:
    # 37 scalars per particle) and written by it; the write per particle
    # and record measured serially (read_write_seconds: inSolver.md's
    # output column). The owned scheme writes each rank's particles.
    "recordSteps": 40,
    "recordScalars": 37,
    # Network: latency per message and bandwidth per rank (an InfiniBand
    # cluster of the thesis' kind)
    "latency": 2e-6,
    "bandwidth": 10e9,
}


def data_rows(text, columns):
    """The cells of the Markdown table rows of text that have at least
    columns cells and a count in the first."""
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= columns and re.fullmatch(r"\d+", cells[0]):
            yield cells


def read_system_report(path):
    """Rows (N, search s, assembly s, solve s, peak MiB) of the
    particleSystemScaling table."""
    rows = [tuple(float(cells[k]) for k in (0, 2, 3, 4, 7))
            for cells in data_rows(open(path).read(), 8)]
    if len(rows) < 2:
        raise SystemExit(f"model.py: {path} has fewer than two sizes with"
                         " the peak-memory column (run"
                         " ../particleSystemScaling/Allrun)")
    return rows


def read_write_seconds(path):
    """Seconds per particle of the master's write of one record: the
    output column of inSolver.md (run with --record) over the particles,
    at its largest serial size."""
    text = open(path).read()
    if "--record" not in text:
        raise SystemExit(f"model.py: {path} was not run with --record (run"
                         " inSolver.py --record)")
    n, seconds = max((int(cells[0]), float(cells[12]))
                     for cells in data_rows(text, 15) if cells[2] == "1")
    return seconds / n


def particle_constants(rows):
    """Seconds per particle for the step's search and assembly, per
    factorised solve, and bytes per particle: slopes between the two
    largest sizes."""
    (n0, s0, a0, v0, m0), (n1, s1, a1, v1, m1) = rows[-2], rows[-1]
    dn = n1 - n0
    return {"setup": ((s1 + a1) - (s0 + a0)) / dn,
            "solve": (v1 - v0) / dn,
            "bytes": (m1 - m0) * 2**20 / dn}


def ghosts(n, p, c):
    """Ghost particles per rank: the particles within the halo of a cubic
    subdomain of the rank's share of the volume (all the others at most)."""
    volume = n * c["cellsPerParticle"] * 0.2**3      # Delta = a1/5
    side = (volume / p) ** (1 / 3)
    shell = (side + 2 * c["halo"]) ** 3 - side ** 3
    return min(n - n / p, n / volume * shell) if p > 1 else 0.0


def tree_sum(n_scalars, p, c):
    """Seconds and bytes of a list of n_scalars summed over p ranks onto
    all of them (a tree gather and scatter)."""
    whole = n_scalars * 8
    return 2 * math.log2(p) * (c["latency"] + whole / c["bandwidth"]), \
        2 * whole


def output_seconds(n, p, c, gathered):
    """Seconds per step of the time series: the records of n particles
    written by one rank (gathered on it from p ranks when gathered), every
    recordSteps steps.  The other ranks wait for it at the next reduction."""
    seconds = n * c["writeSeconds"]
    if gathered and p > 1:
        seconds += ((p - 1) * c["latency"]
                    + n * c["recordScalars"] * 8 / c["bandwidth"])
    return seconds / c["recordSteps"]


def now(n, p, c, k):
    """Memory [GiB], time per step [s] and bytes sent per step of one rank
    of the solver's parallelParticleSolve distributed as it is now: the
    owned scheme, plus the lists of every particle, their scans, the
    owners' reduction and the sizes of each exchange sent to every rank."""
    memory, seconds, sent = per_rank(n, p, c, k, owned=True)
    memory += n * c["listBytes"] / 2**30
    # The master writes every particle's record, not each rank its own
    seconds += (n * c["scanSeconds"] + output_seconds(n, p, c, True)
                - output_seconds(n / p, 1, c, False))
    if p > 1:
        owners = tree_sum(n / 2, p, c)          # 4-byte labels
        exchanges = (c["fixedExchanges"]
                     + c["exchangesPerOuter"] * c["outerIterations"])
        sizes = exchanges * 4 * p
        seconds += (owners[0] + exchanges * math.log2(p) * c["latency"]
                    + sizes / c["bandwidth"])
        sent += owners[1] + sizes
    return memory, seconds, sent


def per_rank(n, p, c, k, owned):
    """Memory [GiB], time per step [s] and bytes sent per step of one rank
    with n particles on p ranks."""
    cells = n * c["cellsPerParticle"] / p
    held = n / p + ghosts(n, p, c) if owned else n
    outer, fact = c["outerIterations"], c["factorisations"]
    compute = (cells * c["cellStepSeconds"]
               + held * (k["setup"] + fact * k["solve"]))
    if p == 1:
        sent, comm = 0.0, 0.0
    elif owned:
        g = ghosts(n, p, c)
        per_outer = g * c["integralScalars"] * 8
        per_cg = g * c["velocityScalars"] * 8
        cgs = fact * c["cgIterations"]
        sent = outer * per_outer + cgs * per_cg
        messages = (outer + cgs) * c["neighbourRanks"] \
            + cgs * 2 * math.log2(p)
        comm = messages * c["latency"] + sent / c["bandwidth"]
    else:
        # The per-particle integrals of all particles summed over ranks
        # (a tree gather and scatter of the whole list every outer iteration)
        seconds, sent = tree_sum(n * c["integralScalars"], p, c)
        comm, sent = outer * seconds, outer * sent
    memory = (cells * c["cellBytes"] + held * k["bytes"]) / 2**30
    output = output_seconds(n / p if owned else n, p, c, False)
    return memory, compute + comm + output, sent


def table(title, header, rows):
    out = [f"### {title}", "", "| " + " | ".join(header) + " |",
           "|" + "---|" * len(header)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return out + [""]


def strong_rows(c, k):
    rows = []
    for n in (1e3, 1e4, 1e5):
        for p in (1, 2, 4, 8, 64, 256, 1024):
            rep = per_rank(n, p, c, k, owned=False)
            own = per_rank(n, p, c, k, owned=True)
            cur = now(n, p, c, k)
            rows.append([f"{n:.0e}", str(p), f"{ghosts(n, p, c):.0f}",
                         f"{rep[0]:.3g}", f"{cur[0]:.3g}", f"{own[0]:.3g}",
                         f"{rep[1]:.3g}", f"{cur[1]:.3g}", f"{own[1]:.3g}",
                         f"{rep[2] / 2**20:.3g}", f"{cur[2] / 2**20:.3g}",
                         f"{own[2] / 2**20:.3g}"])
    return rows


def weak_rows(c, k):
    rows = []
    for n in (1e3, 1e4, 1e5):
        p = max(1, round(n / c["particlesPerCore"]))
        rep = per_rank(n, p, c, k, owned=False)
        own = per_rank(n, p, c, k, owned=True)
        cur = now(n, p, c, k)
        rows.append([f"{n:.0e}", str(p), f"{rep[0]:.3g}", f"{cur[0]:.3g}",
                     f"{own[0]:.3g}", f"{rep[1]:.3g}", f"{cur[1]:.3g}",
                     f"{own[1]:.3g}"])
    return rows


def output_rows(c, k):
    rows = []
    for n in (1e4, 1e5, 1e6, 1e7):
        p = max(1, round(n / c["particlesPerCore"]))
        step = now(n, p, c, k)[1]
        gathered = output_seconds(n, p, c, True)
        rows.append([f"{n:.0e}", str(p), f"{step:.3g}", f"{gathered:.3g}",
                     f"{100 * gathered / step:.2g}",
                     f"{output_seconds(n / p, 1, c, False):.2g}"])
    return rows


def report(system_path, solver_path):
    c = dict(ASSUMPTIONS, writeSeconds=read_write_seconds(solver_path))
    k = particle_constants(read_system_report(system_path))
    lines = ["# Particles by subdomain: the replicated scheme's cost and"
             " the owned scheme's model (issue 38)", "",
             f"Measured particle constants ({os.path.relpath(system_path)}):"
             f" {k['setup'] * 1e6:.1f} us per particle for search and"
             f" assembly, {k['solve'] * 1e6:.1f} us per particle per"
             f" factorised solve, {k['bytes'] / 1024:.1f} KiB per particle;"
             f" {c['writeSeconds'] * 1e6:.2f} us per particle for a record"
             f" written ({os.path.relpath(solver_path)}).",
             "", "Assumptions: " + ", ".join(f"{key} {v:.4g}"
                                             for key, v in c.items()), ""]
    lines += table(
        "Strong scaling: one rank, per step, at the thesis' cells per"
        " particle",
        ["N", "ranks", "ghosts", "GiB replicated", "GiB now", "GiB owned",
         "s replicated", "s now", "s owned", "MiB sent replicated",
         "MiB sent now", "MiB sent owned"],
        strong_rows(c, k))
    lines += table(
        "Weak scaling at the thesis' particles per core"
        f" ({c['particlesPerCore']:.1f})",
        ["N", "ranks", "GiB replicated", "GiB now", "GiB owned",
         "s replicated", "s now", "s owned"], weak_rows(c, k))
    lines += table(
        "The time series gathered on the master (now), weak scaling: its"
        " share of a step, against each rank writing its own particles",
        ["N", "ranks", "s per step now", "s per step of output now",
         "% of the step", "s per step of output, per-rank writes"],
        output_rows(c, k))
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--system", default=os.path.join(
        HERE, "..", "particleSystemScaling", "report.md"))
    ap.add_argument("--solver", default=os.path.join(HERE, "inSolver.md"))
    args = ap.parse_args()
    print(report(args.system, args.solver))


if __name__ == "__main__":
    main()
