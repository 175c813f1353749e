"""Two-sphere X^C by rotlet images.

X^C (rotation about the line of centres) is computed exactly from the rotlet
image series (each rotlet has a single rotlet image in the other sphere,
strength -(a/D)^3 at the inverse point), which converges for every xi > 0.
"""

import numpy as np


def xc_hat(name, xi, lam, nimg=200000):
    """X11C or X12C (hat normalisation) at gap xi by the rotlet images."""
    xi = np.atleast_1d(np.asarray(xi, dtype=float))
    out = np.empty_like(xi)
    for i, x in enumerate(xi):
        R = (1.0 + lam) * (2.0 + x) / 2.0   # centre distance, a1 = 1
        a = (1.0, lam)
        # rotlet: owner sphere index, position along axis from centre 1
        pos, S, own = 0.0, 1.0, 0           # sphere 1 rotates, strength a1^3
        tot = [1.0, 0.0]
        for it in range(nimg):
            other = 1 - own
            c = 0.0 if other == 0 else R
            D = abs(pos - c)
            ai = a[other]
            S = -S * (ai / D) ** 3
            pos = c + (ai * ai / D) * (1.0 if pos > c else -1.0)
            own = other
            tot[own] += S
            if abs(S) < 1e-17 * abs(tot[0]):
                break
        out[i] = tot[0] if name == "X11C" else tot[1]
    return out.reshape(np.shape(xi)) if out.size > 1 else out
