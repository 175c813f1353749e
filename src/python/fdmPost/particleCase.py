"""Read the particle outputs of an fdmSuspensionFoam case.

particleState  <case>/<time>/particleState (OpenFOAM dictionary, written
               by fdmParticleCloud::writeState)
balance        postProcessing/momentumBalance/<t0>/momentumBalance.dat
"""

import glob
import os
import re

import numpy as np


def _vector_list(text, key):
    """Parse 'key N ( (x y z) ... );' from an OpenFOAM dictionary text."""
    m = re.search(r"^%s\s+(\d+)\s*\((.*?)\)\s*;" % key, text, re.S | re.M)
    if m is None:
        # Uniform short form 'key N{(x y z)};'
        m = re.search(r"^%s\s+(\d+)\s*\{\s*\(([^)]*)\)\s*\}\s*;" % key,
                      text, re.M)
        if m is None:
            raise KeyError("%s not found" % key)
        n = int(m.group(1))
        return np.tile(np.array(m.group(2).split(), float), (n, 1))
    n = int(m.group(1))
    values = np.array(re.findall(r"\(([^()]*)\)", m.group(2) + ")"),
                      dtype=object)
    out = np.array([v.split() for v in values[:n]], float)
    return out.reshape(n, 3)


def particle_state(case, time):
    """Dictionary of arrays: position, velocity, angularVelocity, force,
    torque (N x 3)."""
    path = os.path.join(case, str(time), "particleState")
    with open(path) as f:
        text = f.read()
    keys = ["position", "velocity", "angularVelocity", "previousVelocity",
            "force", "torque"]
    return {k: _vector_list(text, k) for k in keys}


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
