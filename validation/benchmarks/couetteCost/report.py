#!/usr/bin/env python3
"""Report of the Couette cost benchmark (run.py): the per-step table in
the columns of thesis 1, Table 4.9, core-seconds per step per 10^6 cells
against the published 38-84 (at the thesis' step gammaDot dt = 1e-4), the
cost per unit strain, the speed-up of the default scheme over the thesis
scheme at equal lambda residual, and memory per 10^6 cells."""

import os
from fdmPost.report import write_markdown  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
PUBLISHED = (38, 84)
THESIS_DT = 1e-4


def main(rows, base, mcells):
    """rows from run.py; base: the base case; mcells: cells / 10^6."""

    def core_s(r):
        """Core-seconds per step per 10^6 cells."""
        return r["total"] * r["nprocs"] / mcells

    with open(os.path.join(base, "constant", "particleList")) as f:
        n = next(int(w) for w in f if w.strip().isdigit())
    lines = [
        "# Cost per time step: Couette suspension at the Table 4.7 size",
        "",
        "phi0 = 0.42, 20 a1 cube, Delta = a1/5 (10^6 cells), %d particles, "
        "frameInvariant sub-grid lubrication, hertz contacts, shear rate "
        "1; %s, %d cores. Times per step, averaged over the steps after "
        "the first restarted one (seconds, wall clock; core-seconds = wall "
        "x ranks); lambda residual = largest end-of-step residual (eq "
        "2.54)." % (n, os.uname().nodename, os.cpu_count()),
        "",
        "| scheme | gammaDot dt | ranks | outer its/step | lambda residual "
        "| s/step | flow | forcing | particle solve | pairs | acceleration "
        "| output | other | core-s/step/10^6 cells "
        "| core-s per strain/10^6 cells "
        "| peak memory/rank [MiB] | memory per 10^6 cells [GiB] |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
        "---|"]
    for r in rows:
        mem = r["peak"] / 1024.0
        lines.append(
            "| %s | %g | %d | %.1f | %.1e | %.2f | %.2f | %.2f | %.3f | %.3f "
            "| %.2f | %.3f | %.2f | %.1f | %.0f | %.0f | %.2f |" % (
                r["name"], r["dt"], r["nprocs"], r["outer"], r["residual"],
                r["total"], r["flow"], r["forcing"], r["particles"],
                r.get("pairs", 0), r["acceleration"], r["output"], r["rest"],
                core_s(r), core_s(r) / r["dt"], mem,
                mem * r["nprocs"] / 1024.0 / mcells))
    lines += ["", "Published (thesis 1, Table 4.9, gammaDot dt = 1e-4): "
              "%d-%d core-seconds per step per 10^6 cells, ~10 loops per "
              "step, i.e. %.0e-%.0e core-seconds per strain per 10^6 cells."
              % (PUBLISHED + (PUBLISHED[0] / THESIS_DT,
                              PUBLISHED[1] / THESIS_DT))]
    by = {(r["name"], r["dt"]): r for r in rows}
    a = by.get(("anderson", THESIS_DT))
    if a:
        lines.append("Default scheme at the thesis step: %.1f core-s per "
                     "step per 10^6 cells (published/ours: %.1f-%.1f)."
                     % (core_s(a), PUBLISHED[0] / core_s(a),
                        PUBLISHED[1] / core_s(a)))
        t = by.get(("thesis", THESIS_DT))
        if t:
            lines.append("Speed-up of the default over the thesis scheme at "
                         "the same lambda residual 1e-4, same machine and "
                         "step: %.1f x per step (%.1f against %.1f outer "
                         "iterations)." % (t["total"] / a["total"],
                                           a["outer"], t["outer"]))
        t = by.get(("thesis10", THESIS_DT))
        if t:
            lines.append("Thesis scheme with its fixed 10 loops: %.1f s per "
                         "step, reaching a lambda residual of %.1e only "
                         "(target 1e-4)." % (t["total"], t["residual"]))
        p = by.get(("anderson2", THESIS_DT))
        if p:
            lines.append("2 MPI ranks: %.1f s per step, parallel efficiency "
                         "%.0f %%." % (p["total"], 100 * a["total"]
                                       / (2 * p["total"])))
    for (name, dt), r in sorted(by.items()):
        if name == "anderson" and dt != THESIS_DT:
            lines.append("Default scheme at gammaDot dt = %g: %.0f core-s "
                         "per strain per 10^6 cells, %.0f-%.0f times less "
                         "than published per strain." % (
                             dt, core_s(r) / dt,
                             PUBLISHED[0] / THESIS_DT / (core_s(r) / dt),
                             PUBLISHED[1] / THESIS_DT / (core_s(r) / dt)))
    write_markdown(os.path.join(HERE, "report.md"), lines)
