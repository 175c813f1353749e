"""Read the internal field of an ASCII OpenFOAM volField file with numpy.

Handles ``internalField uniform <value>`` and
``internalField nonuniform List<scalar|vector> N ( ... )``; the number of
cells must then be given for uniform fields (``nCells``).
"""

import re

import numpy as np

_NONUNIFORM = re.compile(
    r"internalField\s+nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(",
    re.MULTILINE)
_UNIFORM = re.compile(r"internalField\s+uniform\s+([^;]+);")


def read_internal_field(path, nCells=None):
    """Return the internal field as an array of shape (N,) or (N, 3)."""
    with open(path) as f:
        text = f.read()

    m = _NONUNIFORM.search(text)
    if m:
        kind, n = m.group(1), int(m.group(2))
        body = text[m.end():]
        if kind == "vector":
            values = np.array(
                re.findall(r"\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)", body[: body.find("\n)")]),
                dtype=float)
        else:
            values = np.array(body[: body.find(")")].split(), dtype=float)
        if len(values) != n:
            raise ValueError(f"{path}: expected {n} values, read {len(values)}")
        return values

    m = _UNIFORM.search(text)
    if m:
        if nCells is None:
            raise ValueError(f"{path}: uniform internalField, nCells needed")
        value = np.array(m.group(1).strip("() ").split(), dtype=float)
        return np.tile(value, (nCells, 1)) if value.size > 1 else np.full(nCells, value[0])

    raise ValueError(f"{path}: no internalField found")
