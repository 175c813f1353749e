"""Read and evaluate the resistance tables (theory: writeTables.py;
sub-grid: applications/utilities/subGridCalibration), the Python twin of
src/fdmParticles/subGrid/resistanceTable:

    f(x) = g1/x + g2 ln(1/x) + g3 x ln(1/x) + remainder(x)

with the remainder linearly interpolated on the gap grid (constant
outside it), zero above a function's cut-off when it has one, and x floored
at X_MIN as the C++ does (thesis 1e-5; tests/golden/resistanceTables.dat
holds the C++ values this reader is tested against).
"""

import re

import numpy as np

# The gap floor of resistanceTable (defaultXMin)
X_MIN = 1e-5


def read_table(path):
    """(meta, gap, functions): meta holds the scalar and word entries
    (kind, lambda, delta, ...), functions maps a name to a dict with
    'singular' (3), 'remainder' (like gap) and, if present, 'cutoff'."""
    with open(path) as f:
        text = re.sub(r"//.*", "", f.read())

    def numbers(s):
        return np.array(s.split(), float)

    gap = numbers(re.search(r"\bgap\s*\(([^)]*)\)", text).group(1))
    functions = {}
    body = text[text.index("functions"):]
    for m in re.finditer(r"(\w+)\s*\{([^{}]*)\}", body):
        entry = m.group(2)
        f = {"singular": numbers(re.search(r"singular\s*\(([^)]*)\)",
                                           entry).group(1)),
             "remainder": numbers(re.search(r"remainder\s*\(([^)]*)\)",
                                            entry).group(1))}
        cut = re.search(r"cutoff\s+([^;\s]+)\s*;", entry)
        if cut:
            f["cutoff"] = float(cut.group(1))
        functions[m.group(1)] = f
    head = text[:text.index("functions")]
    meta = dict(re.findall(r"^\s*(\w+)\s+([^;(\s]+)\s*;", head, re.M))
    return meta, gap, functions


def evaluate(function, gap, x, x_min=X_MIN):
    """Value of one function (an entry of read_table's functions) at the
    gaps x (array), floored at x_min, cut-off applied."""
    x = np.maximum(np.atleast_1d(np.asarray(x, float)), x_min)
    g1, g2, g3 = function["singular"]
    lx = np.log(1.0 / x)
    f = g1 / x + g2 * lx + g3 * x * lx + np.interp(x, gap,
                                                  function["remainder"])
    if "cutoff" in function:
        f = np.where(x > function["cutoff"], 0.0, f)
    return f
