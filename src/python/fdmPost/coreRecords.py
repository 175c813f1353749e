"""The core series of a Couette run as a small table that outlives the run.

A run longer than a session continues on another machine from a particle
checkpoint (fdmPost.checkpoint): the particles.h5 of the earlier segments
is gone there, so what the core averages need of it (eqs 2.72-2.76, 4.13:
per record the core shear rate, phi_core and the core stresses Sigma^hp
and Sigma^c) and the wall layers' phi (the depletion of chapter 5) is
kept record by record in coreRecords.csv, with the run's geometry in a
first comment line, and the segments are joined on time.

    CoreRecords.from_series(cs, meta)   from a CouetteSeries
    records.write(path) / CoreRecords.read(path)
    earlier.joined(later)               earlier's records before later's

A CoreRecords has the t, eta and series() that core_rheology reads, so
core_rheology(records, start_time) averages the joined run.
"""

import json
import os

import numpy as np

from fdmPost import segments

# Upper triangle of a symmetric tensor, the order of the stresslets in
# particles.h5 (rheology.symm6_to_tensor)
PAIRS = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))
COLUMNS = (["time", "gammaDotCore", "phiCore", "phiWall"]
           + [f"hp{i + 1}{j + 1}" for i, j in PAIRS]
           + [f"c{i + 1}{j + 1}" for i, j in PAIRS])


def _upper(tensors):
    return np.column_stack([tensors[:, i, j] for i, j in PAIRS])


def _tensors(upper):
    t = np.zeros((len(upper), 3, 3))
    for k, (i, j) in enumerate(PAIRS):
        t[:, i, j] = t[:, j, i] = upper[:, k]
    return t


class CoreRecords:
    """Per record: time t, core shear rate g, phi_core, the wall layers'
    phi (phi_wall), Sigma^hp (hp) and Sigma^c (c) as 3x3 tensors; meta:
    the run's geometry (at least eta, the fluid viscosity, shearRate, the
    walls' rate, box and layer)."""

    def __init__(self, t, g, phi, phi_wall, hp, c, meta):
        self.t = np.asarray(t, float)
        self.g = np.asarray(g, float)
        self.phi = np.asarray(phi, float)
        self.phi_wall = np.asarray(phi_wall, float)
        self.hp = np.asarray(hp, float).reshape(-1, 3, 3)
        self.c = np.asarray(c, float).reshape(-1, 3, 3)
        self.meta = dict(meta)
        self.eta = float(self.meta["eta"])

    @staticmethod
    def from_series(cs, meta):
        g, phi, hp, c = cs.series()
        wall = [cs.wall_volume_fraction(k) for k in range(len(cs.t))]
        return CoreRecords(cs.t, g, phi, wall, hp, c, {"eta": cs.eta, **meta})

    def _rows(self, keep):
        return (self.t[keep], self.g[keep], self.phi[keep],
                self.phi_wall[keep], self.hp[keep], self.c[keep])

    def series(self):
        return self.g, self.phi, self.hp, self.c

    def strain(self):
        """The strain of the last record."""
        return self.t[-1] * self.meta["shearRate"] if len(self.t) else 0.0

    def until(self, time):
        """The records at times up to `time` (a checkpoint's state)."""
        return CoreRecords(*self._rows(segments.up_to(self.t, time)),
                           self.meta)

    def joined(self, later):
        """This run's records before the first of `later`, then `later`'s:
        a segment restarted at time T writes its record of T again."""
        keep = segments.before(self.t, later.t)
        every = np.ones(len(later.t), bool)
        return CoreRecords(*(np.concatenate((a, b)) for a, b in
                             zip(self._rows(keep), later._rows(every))),
                           later.meta)

    def write(self, path):
        """Written under a temporary name and renamed into place: a kill
        leaves the previous table or the whole new one."""
        table = np.column_stack((self.t, self.g, self.phi, self.phi_wall,
                                 _upper(self.hp), _upper(self.c)))
        if not np.isfinite(table[:, [0, 2]]).all():
            raise ValueError(f"{path}: non-finite time or phi_core")
        tmp = f"{path}.tmp"
        with open(tmp, "w") as f:
            f.write("# " + json.dumps(self.meta, default=_plain) + "\n")
            f.write(",".join(COLUMNS) + "\n")
            for row in table:
                f.write(",".join(f"{v:.9g}" for v in row) + "\n")
        os.replace(tmp, path)

    @staticmethod
    def read(path):
        with open(path) as f:
            first = f.readline()
            if not first.startswith("# "):
                raise ValueError(f"{path}: no run description in its first"
                                 " line")
            meta = json.loads(first[2:])
            header = f.readline().strip().split(",")
            if header != COLUMNS:
                raise ValueError(f"{path}: columns {header}, expected"
                                 f" {COLUMNS}")
            table = np.loadtxt(f, delimiter=",", ndmin=2)
        if not table.size:
            table = np.zeros((0, len(COLUMNS)))
        return CoreRecords(table[:, 0], table[:, 1], table[:, 2],
                           table[:, 3], _tensors(table[:, 4:10]),
                           _tensors(table[:, 10:16]), meta)


def _plain(value):
    """numpy values in the JSON line as plain numbers and lists."""
    return value.tolist() if hasattr(value, "tolist") else str(value)
