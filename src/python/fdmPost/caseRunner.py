"""Make and run small fdmSuspensionFoam cases from a template: the
measurement loops of the sub-grid calibration and of the validations.

cell_offsets   positions inside a mesh cell to average over
fill_template  copy a template case and replace its @TOKENS@
copy_case      a fresh case of another's 0, constant and system
run_case       blockMesh + fdmSuspensionFoam; the last particles.h5 record
read_last_record   that record of a case already run
run_logged, foam_set, foam_get   a command, a dictionary entry, in a case
run_measured   a command's wall time and its largest process' peak memory
solver_command fdmSuspensionFoam serially, or decomposed and run by mpirun
timing_lines   the cumulative Timing lines of an fdmSuspensionFoam log
snapshot_case  constant/, system/ and one written time of a run, copied
work_lock      one benchmark at a time in a work folder
"""

import fcntl
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np


def vec(v):
    """OpenFOAM vector text of a 3-sequence, full precision."""
    return "(%s)" % " ".join("%.17g" % c for c in v)


def cell_offsets(count, dims):
    """count offsets inside one mesh cell, in units of Delta: a fixed
    spread (seeded permutation) of the 4^dims lattice of quarter cells
    (thesis: 4 x 4 x 4 for pairs, 4 x 4 in a plane near a wall).  Arrays of
    length dims."""
    lattice = np.array(list(np.ndindex(*(4,) * dims)), float) / 4.0
    order = np.random.RandomState(2022).permutation(len(lattice))
    return [lattice[i] for i in order[:count]]


def fill_template(template, case, tokens):
    """Fresh copy of template (0, constant, system) in case with every
    token (dict key, e.g. '@L@') replaced by its value in system/ and
    constant/ (and 0/)."""
    if os.path.isdir(case):
        shutil.rmtree(case)
    shutil.copytree(template, case)
    for sub in ("0", "system", "constant"):
        folder = os.path.join(case, sub)
        for name in os.listdir(folder):
            path = os.path.join(folder, name)
            with open(path) as f:
                text = f.read()
            for k, v in tokens.items():
                text = text.replace(k, v)
            with open(path, "w") as f:
                f.write(text)


def copy_case(source, case):
    """A fresh case holding source's 0, constant and system (not its
    times, logs or processor folders)."""
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    for d in ("0", "constant", "system"):
        shutil.copytree(os.path.join(source, d), os.path.join(case, d))


def run_case(case, keep_mesh=False):
    """blockMesh and fdmSuspensionFoam in case (logs log.<app>); returns
    the last record of postProcessing/particles.h5 as a dict of arrays
    (force, torque, stresslet, dipoleTrace, velocity, angularVelocity,
    position).  Raises RuntimeError naming the log on failure."""
    for app in ("blockMesh", "fdmSuspensionFoam"):
        log = os.path.join(case, "log." + app)
        with open(log, "w") as f:
            rc = subprocess.call([app, "-case", case], stdout=f,
                                 stderr=subprocess.STDOUT)
        if rc != 0:
            raise RuntimeError("%s failed in %s (see %s)" % (app, case, log))
    if not solved(case):
        raise RuntimeError("no converged solve in %s" % log)
    state = read_last_record(case)
    if not keep_mesh:
        # The mesh is the bulk of a case: the measurement is in the h5 file
        shutil.rmtree(os.path.join(case, "constant", "polyMesh"))
    return state


def solved(case):
    """Whether the solver's log in case reports a converged solve: a record
    without one (a solver that skipped it, as one run against a library
    being rebuilt did) is no measurement."""
    log = os.path.join(case, "log.fdmSuspensionFoam")
    return os.path.isfile(log) and ": converged in " in open(log).read()


def read_last_record(case):
    """Last record of <case>/postProcessing/particles.h5 as a dict of
    arrays (position, velocity, angularVelocity, force, torque, stresslet,
    dipoleTrace)."""
    import h5py
    with h5py.File(os.path.join(case, "postProcessing", "particles.h5"),
                   "r") as f:
        return {k: np.array(f[k][-1]) for k in
                ("position", "velocity", "angularVelocity", "force",
                 "torque", "stresslet", "dipoleTrace")}


def symm(s):
    """3 x 3 array of a symmTensor given as xx xy xz yy yz zz."""
    return np.array([[s[0], s[1], s[2]], [s[1], s[3], s[4]],
                     [s[2], s[4], s[5]]])


def in_case(case):
    """Environment for a command run in case (OpenFOAM warns on stdout when
    PWD is not the working directory)."""
    return dict(os.environ, PWD=os.path.abspath(case))


def run_logged(cmd, case, log):
    """Run cmd (a list) in case, its output in case/log; RuntimeError
    naming the log on failure."""
    with open(os.path.join(case, log), "w") as f:
        rc = subprocess.call(cmd, cwd=case, stdout=f,
                             stderr=subprocess.STDOUT, env=in_case(case))
    if rc != 0:
        raise RuntimeError("%s failed in %s (see %s)" % (cmd, case, log))


# Runs a command and writes the peak resident set size [KiB] of its
# largest process (getrusage of the children of a fresh interpreter: with
# mpirun, the largest rank)
PEAK = ("import resource, subprocess, sys; rc = subprocess.call(sys.argv[2:]);"
        " open(sys.argv[1], 'w').write(str(resource.getrusage("
        "resource.RUSAGE_CHILDREN).ru_maxrss)); sys.exit(rc)")


def run_measured(cmd, case, log):
    """run_logged, returning the wall seconds and the peak resident set
    size [KiB] of the largest process cmd started."""
    start = time.time()
    run_logged([sys.executable, "-c", PEAK, "peakMemory"] + cmd, case, log)
    wall = time.time() - start
    return wall, int(open(os.path.join(case, "peakMemory")).read())


def solver_command(case, ranks, split=None):
    """The command that runs fdmSuspensionFoam in case: serially for one
    rank, else on ranks ranks (oversubscribed beyond the cores) after
    decomposing the case's latest time by its decomposeParDict (simple)
    into split, by default (ranks 1 1)."""
    if ranks == 1:
        return ["fdmSuspensionFoam"]
    dictionary = "system/decomposeParDict"
    foam_set(case, "numberOfSubdomains", ranks, dictionary)
    foam_set(case, "coeffs.n", split or "(%d 1 1)" % ranks, dictionary)
    run_logged(["decomposePar", "-latestTime"], case, "log.decomposePar")
    return ["mpirun", "-np", str(ranks), "--oversubscribe",
            "fdmSuspensionFoam", "-parallel"]


def foam_set(case, entry, value, path):
    """foamDictionary -entry entry -set value on case/path."""
    run_logged(["foamDictionary", "-entry", entry, "-set", str(value), path],
               case, "log.foamDictionary")


def foam_get(case, entry, path):
    """The value of a dictionary entry of case/path, as text."""
    out = subprocess.run(["foamDictionary", "-entry", entry, "-value", path],
                         cwd=case, stdout=subprocess.PIPE, check=True,
                         env=in_case(case))
    return out.stdout.decode().strip()


# The columns of the solver's "Timing [s]" report (reportTimings.H), all
# cumulative since the start of the run; pairs (the pair search, updates,
# relinearisation and loads) is 0 in logs from before it was reported
TIMING_COLUMNS = ("outer", "steps", "total", "flow", "indicators",
                  "integrals", "particleSolve", "corrections",
                  "acceleration", "output", "pairs")
TIMING = re.compile(
    r"Timing \[s\] after (\d+) outer iterations in (\d+) step\(s\): total "
    r"(\S+),.*\n\s+flow (\S+), indicators (\S+), lambda/u integrals (\S+), "
    r"particle solve (\S+), corrections (\S+), acceleration (\S+), output "
    r"(\S+),(?: pairs (\S+),)?")


def timing_lines(text):
    """Each Timing report of a log as a list of floats, TIMING_COLUMNS."""
    return [[float(v or 0) for v in m.groups()]
            for m in TIMING.finditer(text)]


def snapshot_case(source, time, work):
    """work/snapshots/<source name>_<time>: constant/, system/ and the
    (reconstructed, when the run was decomposed) time of a run; made once."""
    name = "%s_%s" % (os.path.basename(os.path.normpath(source)), time)
    case = os.path.join(work, "snapshots", name)
    if os.path.isfile(os.path.join(case, time, "U")):
        return case
    if not os.path.isfile(os.path.join(source, time, "U")):
        run_logged(["reconstructPar", "-time", time], source,
                   "log.reconstructPar")
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    for d in ("constant", "system", time):
        shutil.copytree(os.path.join(source, d), os.path.join(case, d))
    return case


def work_lock(work):
    """Hold work/.lock for the life of the process, or stop: a second
    invocation would remove the unfinished cases the first is running.
    The lock goes with the process (flock), also when it is killed."""
    os.makedirs(work, exist_ok=True)
    handle = open(os.path.join(work, ".lock"), "w")
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        raise SystemExit("%s is in use by another run of this benchmark; "
                         "wait for it to end" % work)
    return handle
