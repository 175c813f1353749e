"""Pass/fail bookkeeping shared by the case-test checkers: every check
prints its measured value with its tolerance."""

import sys

import numpy as np


def rel_linf(a, ref):
    """max |a - ref| / max |ref| (relative L-infinity difference)."""
    a, ref = np.asarray(a, float), np.asarray(ref, float)
    return np.abs(a - ref).max() / max(np.abs(ref).max(), 1e-300)


class Checks:
    """Collect checks; finish() exits 1 if any failed."""

    def __init__(self, width=55):
        self.width = width
        self.failures = []

    def check(self, name, value, tol):
        """Pass when value <= tol."""
        ok = value <= tol
        print("%-*s %.3e (tolerance %.1e) %s"
              % (self.width, name, value, tol, "ok" if ok else "FAILED"))
        if not ok:
            self.failures.append(name)
        return ok

    def same_state(self, label, a, b, tol=1e-12,
                   keys=("position", "velocity", "angularVelocity", "force")):
        """Two particle states (particleCase.particle_state) agree key by
        key, relative to the largest value of the first."""
        for key in keys:
            self.check("%s %s (relative)" % (label, key),
                       np.abs(a[key] - b[key]).max() / np.abs(a[key]).max(),
                       tol)

    def finish(self):
        sys.exit(1 if self.failures else 0)
