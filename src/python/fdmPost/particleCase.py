"""Read the particle outputs of an fdmSuspensionFoam case.

particleState  <case>/<time>/particleState (OpenFOAM dictionary, written
               by fdmParticleCloud::writeState)
balance        postProcessing/momentumBalance/<t0>/momentumBalance.dat
drag factor    of the periodic arrays (drag_factor, hasimoto_K)
"""

import glob
import os
import re
import warnings

import numpy as np


def read_list(text, key, width):
    """Parse 'key N ( (c1 .. cwidth) ... );' (width > 1) or 'key N ( s ...
    );' (width 1) from an OpenFOAM dictionary text; also the uniform short
    form 'key N{value};'.  Returns an N x width (or N) array."""
    m = re.search(r"^%s\s+(\d+)\s*\{\s*\(?([^()}]*)\)?\s*\}\s*;" % key,
                  text, re.M)
    if m is not None:
        n = int(m.group(1))
        value = np.array(m.group(2).split(), float)
        return np.tile(value, (n, 1)) if width > 1 else np.full(n, value[0])
    m = re.search(r"^%s\s+(\d+)\s*\((.*?)\)\s*;" % key, text, re.S | re.M)
    if m is None:
        raise KeyError("%s not found" % key)
    n = int(m.group(1))
    if width == 1:
        return np.array(m.group(2).split()[:n], float)
    values = re.findall(r"\(([^()]*)\)", m.group(2) + ")")
    return np.array([v.split() for v in values[:n]], float).reshape(n, width)


def particle_state(case, time):
    """Dictionary of arrays: position, velocity, angularVelocity,
    previousVelocity, force, torque (N x 3), and when present stresslet
    (N x 6: xx xy xz yy yz zz) and dipoleTrace (N)."""
    path = os.path.join(case, str(time), "particleState")
    with open(path) as f:
        text = f.read()
    keys = ["position", "velocity", "angularVelocity", "previousVelocity",
            "force", "torque"]
    state = {k: read_list(text, k, 3) for k in keys}
    for k, width in (("stresslet", 6), ("dipoleTrace", 1)):
        try:
            state[k] = read_list(text, k, width)
        except KeyError:
            pass
    return state


def series_files(case, folder, name):
    """The files postProcessing/<folder>/<t0>/<name>.dat and <name>_<k>.dat
    of a case in run order: by start time t0, then k (a run restarted from
    the same time writes <name>_1.dat beside the earlier file)."""
    pattern = re.compile(re.escape(name) + r"(?:_(\d+))?\.dat$")
    found = []
    for path in glob.glob(os.path.join(case, "postProcessing", folder, "*",
                                       name + "*.dat")):
        m = pattern.match(os.path.basename(path))
        try:
            t0 = float(os.path.basename(os.path.dirname(path)))
        except ValueError:
            continue
        if m:
            found.append((t0, int(m.group(1) or 0), path))
    if not found:
        raise FileNotFoundError("no postProcessing/%s/*/%s.dat in %s"
                                % (folder, name, case))
    return [path for _, _, path in sorted(found)]


def series_rows(files):
    """The rows of time-series files (time in the first column) in run
    order, one row per time: where runs overlap, the later run's row.
    Files with a header only (a run started at its end time) are skipped."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # empty input
        tables = [np.loadtxt(f, ndmin=2) for f in files]
    return latest_per_time(np.vstack([t for t in tables if t.size]))


def latest_per_time(data):
    """Rows (time in the first column, in run order) sorted by time, one
    per time: where runs overlap, the later run's row."""
    _, last = np.unique(data[::-1, 0], return_index=True)
    return data[::-1][last]


def momentum_balance(case):
    """Rows of the momentum-balance files as a dict of arrays: time (n),
    lambdaV, lambdaParts, wall, pressure, meanU (n x 3)."""
    data = series_rows(series_files(case, "momentumBalance",
                                    "momentumBalance"))
    names = ["lambdaV", "lambdaParts", "wall", "pressure", "meanU"]
    out = {"time": data[:, 0]}
    for i, n in enumerate(names):
        out[n] = data[:, 1 + 3 * i:4 + 3 * i]
    return out


def drag_factor(case, L):
    """Drag factor K = F/(6 pi eta a U_s) of a periodic-array case's last
    solve (thesis 1, eqs 4.2, 4.6, 4.7): F = V0 |grad P0| (held sphere) or
    the buoyant weight (settling sphere), both L^3 in these cases, and
    U_s = <u> - U_particle along the flow.  The mean velocity from the
    momentum-balance file, the particle's from the HDF5 series (both
    written after every solve)."""
    import h5py
    bal = momentum_balance(case)
    with h5py.File(os.path.join(case, "postProcessing", "particles.h5"),
                   "r") as f:
        t, Up = f["time"][-1], f["velocity"][-1, 0]
    if abs(t - bal["time"][-1]) > 1e-12 * (1 + abs(t)):
        raise RuntimeError("%s: last HDF5 time %g differs from the last"
                           " balance time %g" % (case, t, bal["time"][-1]))
    slip = bal["meanU"][-1, 0] - Up[0]
    return L ** 3 / (6 * np.pi * abs(slip))


def hasimoto_K(phi):
    """Drag factor of a simple cubic array, Hasimoto (1959), thesis eq 4.3."""
    return 1.0 / (1.0 - 1.7601 * phi ** (1.0 / 3.0) + phi
                  - 1.5593 * phi ** 2)
