"""Read the particle outputs of an fdmSuspensionFoam case.

particleState  <case>/<time>/particleState (OpenFOAM dictionary, written
               by fdmParticleCloud::writeState)
balance        postProcessing/momentumBalance/<t0>/momentumBalance.dat
"""

import glob
import os
import re

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


def momentum_balance(case):
    """Rows of the momentum-balance file as a dict of arrays: time (n),
    lambdaV, lambdaParts, wall, pressure, meanU (n x 3)."""
    files = sorted(glob.glob(os.path.join(
        case, "postProcessing", "momentumBalance", "*",
        "momentumBalance.dat")))
    if not files:
        raise FileNotFoundError("no momentumBalance.dat in %s" % case)
    data = np.vstack([np.loadtxt(f, ndmin=2) for f in files])
    names = ["lambdaV", "lambdaParts", "wall", "pressure", "meanU"]
    out = {"time": data[:, 0]}
    for i, n in enumerate(names):
        out[n] = data[:, 1 + 3 * i:4 + 3 * i]
    return out


def hasimoto_K(phi):
    """Drag factor of a simple cubic array, Hasimoto (1959), thesis eq 4.3."""
    return 1.0 / (1.0 - 1.7601 * phi ** (1.0 / 3.0) + phi
                  - 1.5593 * phi ** 2)
