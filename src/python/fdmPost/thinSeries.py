"""The series a particle checkpoint keeps of a run with few particles.

A run of a few dozen spheres (the resolved-fluid resuspension) is analysed
from its whole particle series (profiles over time windows, stresses by
slab), not from core averages.  For such runs a checkpoint keeps the
particle series thinned to what fdmPost.rheology.CouetteSeries reads
(positions, velocities, stresslets; single precision, compressed: about
1.5 kB a record for 19 spheres) and the rows of a `forces` function
object (the lid's force: the shear stress the suspension bears), each
joined over the run's segments on time.
"""

import glob
import os
import re
import warnings

import numpy as np

from fdmPost import segments
from fdmPost.particleCase import latest_per_time

# The per-record series CouetteSeries reads, and the per-particle constants
SERIES = ("position", "velocity", "stresslet", "dipoleTrace",
          "contactStresslet")
CONSTANTS = ("radius", "group")


def read(path):
    """(data, attrs) of a particles.h5 (a run's or a thinned one)."""
    import h5py
    with h5py.File(path, "r") as f:
        data = {k: f[k][...] for k in ("time",) + SERIES + CONSTANTS
                if k in f}
        return data, dict(f.attrs)


def until(data, time):
    """The records at times up to `time`."""
    keep = segments.up_to(data["time"], time)
    return {k: (v[keep] if k in SERIES + ("time",) else v)
            for k, v in data.items()}


def joined(earlier, later):
    """earlier's records before later's first, then later's (a segment
    restarted at time T writes its record of T again)."""
    if earlier is None:
        return later
    keep = segments.before(earlier["time"], later["time"])
    out = dict(later)
    for k in ("time",) + SERIES:
        if k in later:
            out[k] = np.concatenate((earlier[k][keep], later[k]))
    return out


def write(path, data, attrs):
    """A thinned particles.h5: times and constants in double precision,
    the series in single precision (7 digits, beyond what averages over
    records resolve), gzip; under a temporary name renamed into place."""
    import h5py
    tmp = f"{path}.tmp"
    with h5py.File(tmp, "w") as f:
        for k, v in data.items():
            if k in SERIES:
                f.create_dataset(k, data=np.asarray(v, np.float32),
                                 compression="gzip", shuffle=True)
            else:
                f[k] = v
        f.attrs.update(attrs)
    os.replace(tmp, path)


def force_rows(files):
    """(time, Fx, Fy, Fz) of the total force in the force.dat files of an
    OpenFOAM `forces` function object, in run order, one row per time (the
    later file's where runs overlap)."""
    rows = []
    for path in files:
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                values = re.sub(r"[()]", " ", line).split()
                rows.append([float(v) for v in values[:4]])
    if not rows:
        return np.zeros((0, 4))
    return latest_per_time(np.array(rows))


def case_force_rows(case, name):
    """The force rows of the function object `name` of a case directory:
    postProcessing/<name>/<t0>/force*.dat ordered by start time (and
    within a start time force.dat before the force_<t0>.dat that OpenFOAM
    writes beside it on a second run from the same time)."""
    found = []
    for path in glob.glob(f"{case}/postProcessing/{name}/*/force*.dat"):
        try:
            found.append((float(os.path.basename(os.path.dirname(path))),
                          path))
        except ValueError:
            continue
    return force_rows([p for _, p in sorted(found)])


def write_force_rows(path, rows):
    tmp = f"{path}.tmp"
    np.savetxt(tmp, rows, fmt="%.10g", delimiter=",",
               header="time,Fx,Fy,Fz (total force on the patches)")
    os.replace(tmp, path)


def read_force_rows(path):
    """The rows of write_force_rows, (0, 4) when it kept none (a segment
    shorter than the function object's interval)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # no rows
        return np.loadtxt(path, delimiter=",", ndmin=2).reshape(-1, 4)


def joined_rows(earlier, later):
    """Force rows (time first) joined as the records are (joined)."""
    if earlier is None:
        return later
    return np.vstack((earlier[segments.before(earlier[:, 0], later[:, 0])],
                      later))
