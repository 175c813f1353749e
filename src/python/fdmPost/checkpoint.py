"""Particle checkpoints: a run continued on another machine.

A Stokes flow keeps no memory of earlier times: the flow of a step is
fixed by the particles' positions and the walls.  What a run must carry
from one machine (or session) to the next is therefore small and kept in
the repository: the particle state of its latest complete write and the
core series of its records (fdmPost.coreRecords), not its fields.

    python3 -m fdmPost.checkpoint save CASE DEST [--layer L] [--particles]
                                       [--forces NAME...]
    python3 -m fdmPost.checkpoint restore DEST CASE --procs N
    python3 -m fdmPost.checkpoint summary DEST [--start STRAIN]

save: DEST/particleState.<time> of CASE's newest time with a particle
state and the run's records up to that time, after those DEST already
holds from before the run's first record: with --layer the core records
(DEST/coreRecords.csv, fdmPost.coreRecords: a Couette run of any size),
with --particles the particle series (DEST/particles.h5,
fdmPost.thinSeries: a run of few particles), with --forces the rows of
those `forces` function objects (DEST/<NAME>.csv).  It refuses to replace
a later checkpoint with an earlier one.
summary: the core rheology of DEST's records (every segment of the run,
where a case continued on another machine holds its last segment only)
from strain STRAIN (default 5) on, against eq 4.12.
restore: the state as time <time> of a case set up at time 0 (startFrom
latestTime in its system/controlDict), the fields of time 0 copied to it
(processor*/0 when decomposed) and coldFluid set in the particle state:
the solver then converges the first step as tightly as at time 0
(lambdaToleranceFirstStep).
"""

import argparse
import glob
import os
import re
import shutil
import sys

from fdmPost import segments, thinSeries
from fdmPost.coreRecords import CoreRecords
from fdmPost.rheology import (case_description, channel_case, core_rheology,
                              maron_pierce, number)

STATE = "particleState."


def _is_time(name):
    return re.fullmatch(r"[0-9.eE+-]+", name) is not None


def latest_state(case):
    """(time name, path) of the newest case/<time>/particleState, None when
    the case has none after time 0 (a particle state file is written
    whole or not at all)."""
    times = [d for d in os.listdir(case) if _is_time(d) and float(d) > 0
             and os.path.isfile(f"{case}/{d}/particleState")]
    if not times:
        return None
    t = max(times, key=float)
    return t, f"{case}/{t}/particleState"


def checkpoint_state(dest):
    """(time name, path) of DEST's particle state, None when it has none
    (a copy a kill cut short, particleState.<time>.tmp, is not one)."""
    times = [p.rsplit(STATE, 1)[1] for p in glob.glob(f"{dest}/{STATE}*")]
    times = [t for t in times if _is_time(t)]
    if not times:
        return None
    t = max(times, key=float)
    return t, f"{dest}/{STATE}{t}"


def case_records(case, layer):
    """The core records of CASE's particles.h5 (series_records)."""
    cs, _, run = channel_case(case, layer)
    return series_records(cs, run, case)


def series_records(cs, run, case):
    """The core records of a case's CouetteSeries cs with the run's
    geometry (run: its description) and adhesion number
    (contact.adhesionNumber, 0 without it)."""
    props = run.get("particleProperties", "")
    adhesion = number(props, "adhesionNumber") \
        if re.search(r"^\s*adhesionNumber\b", props, re.M) else 0.0
    meta = {"case": os.path.basename(os.path.abspath(case)),
            "shearRate": run["shearRate"], "boxMin": run["boxMin"],
            "box": cs.span, "layer": cs.layer, "adhesionNumber": adhesion}
    return CoreRecords.from_series(cs, meta)


def run_records(case, layer_of_height):
    """The core records of a checkpoint (coreRecords.csv: the whole run,
    every segment) or of a case's particles.h5 (wall layer
    layer_of_height(L_y)), None for neither."""
    if os.path.exists(f"{case}/coreRecords.csv"):
        return CoreRecords.read(f"{case}/coreRecords.csv")
    if os.path.exists(f"{case}/postProcessing/particles.h5"):
        run = case_description(case)
        ly = run["boxMax"][1] - run["boxMin"][1]
        return case_records(case, layer_of_height(ly))
    return None


def records_by_case(folders, pattern, layer_of_height):
    """{case name: core records} of the folders' cases matching pattern
    (checkpoints or case directories, run_records); a case in several
    folders, the records that reach the largest strain."""
    out = {}
    for case in sorted(c for f in folders for c in glob.glob(f"{f}/{pattern}")):
        records = run_records(case, layer_of_height)
        if records is None or not len(records.t):
            continue
        name = os.path.basename(case)
        if name not in out or records.strain() > out[name].strain():
            out[name] = records
    return out


def save(case, dest, layer=None, particles=False, forces=()):
    """The checkpoint of CASE in DEST: its newest particle state and, joined
    with DEST's earlier records, the core records (layer given), the
    thinned particle series (particles) and the force rows of the
    `forces` function objects named."""
    found = latest_state(case)
    if found is None:
        raise SystemExit(f"checkpoint: {case} has no particle state after"
                         " time 0")
    time, state = found
    earlier = checkpoint_state(dest)
    if earlier is not None and float(earlier[0]) > float(time):
        raise SystemExit(
            f"checkpoint: {dest} holds time {earlier[0]}, later than {case}'s"
            f" newest state {time}: not replaced (continue the run from it"
            " with restore)")
    os.makedirs(dest, exist_ok=True)
    # The records first: a kill before the state is replaced leaves records
    # beyond the state, which the next segment's records replace (joined)
    summary = []
    if layer is not None:
        summary.append(_save_core_records(case, dest, layer, float(time)))
    if particles:
        summary.append(_save_thin_series(case, dest, float(time)))
    for name in forces:
        summary.append(_save_forces(case, dest, name, float(time)))
    tmp = f"{dest}/{STATE}{time}.tmp"
    shutil.copyfile(state, tmp)
    os.replace(tmp, f"{dest}/{STATE}{time}")
    for old in glob.glob(f"{dest}/{STATE}*"):
        if old != f"{dest}/{STATE}{time}":
            os.remove(old)   # older states and cut-short copies
    print(f"checkpoint: {case} at time {time} in {dest}"
          + "".join(f"; {s}" for s in summary))


def _save_core_records(case, dest, layer, time):
    records = case_records(case, layer).until(time)
    table = f"{dest}/coreRecords.csv"
    if os.path.exists(table):
        records = CoreRecords.read(table).joined(records)
    records.write(table)
    return f"core records to strain {records.strain():.3g} ({len(records.t)})"


def _save_thin_series(case, dest, time):
    data, attrs = thinSeries.read(f"{case}/postProcessing/particles.h5")
    data = thinSeries.until(data, time)
    path = f"{dest}/particles.h5"
    if os.path.exists(path):
        data = thinSeries.joined(thinSeries.read(path)[0], data)
    thinSeries.write(path, data, attrs)
    return f"particle series, {len(data['time'])} records"


def _save_forces(case, dest, name, time):
    rows = thinSeries.case_force_rows(case, name)
    rows = rows[segments.up_to(rows[:, 0], time)]
    path = f"{dest}/{name}.csv"
    if os.path.exists(path):
        rows = thinSeries.joined_rows(thinSeries.read_force_rows(path), rows)
    thinSeries.write_force_rows(path, rows)
    return f"{name}, {len(rows)} rows"


def restore(dest, case, procs):
    found = checkpoint_state(dest)
    if found is None:
        raise SystemExit(f"checkpoint: no particle state in {dest}")
    time, state = found
    if latest_state(case) is not None:
        raise SystemExit(f"checkpoint: {case} has written times already:"
                         " it continues from its own (not restored)")
    control = f"{case}/system/controlDict"
    with open(control) as f:
        start = re.search(r"^\s*startFrom\s+(\w+)\s*;", f.read(), re.M)
    if start is None or start.group(1) != "latestTime":
        raise SystemExit(
            f"checkpoint: {control}: startFrom"
            f" {start.group(1) if start else '(missing)'}; the restored time"
            " is run only with startFrom latestTime")
    sources = ([f"{case}/processor{p}" for p in range(procs)]
               if procs > 1 else [case])
    for src in sources:
        if not os.path.isdir(f"{src}/0"):
            raise SystemExit(f"checkpoint: {src}/0 missing (set the case up"
                             " first)")
        shutil.copytree(f"{src}/0", f"{src}/{time}", dirs_exist_ok=True)
    os.makedirs(f"{case}/{time}", exist_ok=True)
    with open(state) as f:
        text = f.read()
    if not re.search(r"^coldFluid\s", text, re.M):
        text = text.rstrip("\n") + "\n\ncoldFluid       true;\n"
    tmp = f"{case}/{time}/particleState.tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, f"{case}/{time}/particleState")
    print(f"checkpoint: {case} continues from {dest} at time {time}")
    return time


def summary(dest, start=5.0):
    """The core rheology of the checkpoint DEST's records from strain start
    on, as text: phi_core, eta_core (with eq 4.12 at that phi_core), N1 and
    N2 over Sigma_12, the contact share, each with its standard error."""
    records = CoreRecords.read(f"{dest}/coreRecords.csv")
    rate = records.meta["shearRate"]
    if not (records.t >= start / rate).any():
        return (f"{records.meta.get('case', dest)}: strain"
                f" {records.strain():.2f}, no records from strain {start:g}")
    r = core_rheology(records, start / rate)
    pm = lambda k: f"{r[k][0]:.3f} +- {r[k][1]:.3f}"  # noqa: E731
    return (f"{records.meta.get('case', dest)}: strain {records.strain():.2f},"
            f" {r['records']} records from strain {start:g}:"
            f" phi_core {pm('phiCore')}, eta_core {pm('etaCore')}"
            f" (eq 4.12: {maron_pierce(r['phiCore'][0]):.3f}),"
            f" N1/Sigma12 {pm('N1')}, N2/Sigma12 {pm('N2')},"
            f" contact share {pm('contactShare')}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    sub = ap.add_subparsers(dest="command", required=True)
    s = sub.add_parser("save")
    s.add_argument("case")
    s.add_argument("dest")
    s.add_argument("--layer", type=float,
                   help="keep the core records of this wall layer")
    s.add_argument("--particles", action="store_true",
                   help="keep the particle series (few particles)")
    s.add_argument("--forces", nargs="+", default=(),
                   help="keep the rows of these forces function objects")
    r = sub.add_parser("restore")
    r.add_argument("dest")
    r.add_argument("case")
    r.add_argument("--procs", type=int, default=1)
    m = sub.add_parser("summary")
    m.add_argument("dest")
    m.add_argument("--start", type=float, default=5.0)
    args = ap.parse_args(argv)
    if args.command == "save":
        save(args.case, args.dest, args.layer, args.particles, args.forces)
    elif args.command == "summary":
        print(summary(args.dest, args.start))
    else:
        restore(args.dest, args.case, args.procs)


if __name__ == "__main__":
    sys.exit(main())
