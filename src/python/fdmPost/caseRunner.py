"""Make and run small fdmSuspensionFoam cases from a template: the
measurement loops of the sub-grid calibration and of the validations.

cell_offsets   positions inside a mesh cell to average over
fill_template  copy a template case and replace its @TOKENS@
run_case       blockMesh + fdmSuspensionFoam; the last particles.h5 record
read_last_record   that record of a case already run
"""

import os
import shutil
import subprocess

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
    state = read_last_record(case)
    if not keep_mesh:
        # The mesh is the bulk of a case: the measurement is in the h5 file
        shutil.rmtree(os.path.join(case, "constant", "polyMesh"))
    return state


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
