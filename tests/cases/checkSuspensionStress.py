#!/usr/bin/env python3
"""Checks of the suspensionStress function object (restartContinuity.sh).

Reference: fdmPost.rheology, an independent (Python) implementation of the
same equations (thesis 1, eqs 2.70, 2.71, 2.73, 6.4; core shear rate by
regression), applied to the HDF5 record of the same time.  Both are
written with 17 digits (the case's writePrecision), so they must agree to
round-off (1e-10 relative), also the stress profiles (eqs 6.18-6.19,
particle stresslets spread over the particle volumes).  Also: the profiles
hold the particle volume (eq 2.70 integrated), the postProcess pass
writes the same rows as the run, and the restarted run the same as the
straight one.
"""

import glob
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.checks import Checks, rel_linf as rel  # noqa: E402
from fdmPost.rheology import CouetteSeries  # noqa: E402

work = sys.argv[1]
LO, SPAN, LAYER, BINS = (0, -3, 0), (6, 6, 6), 1.0, 6
checks = Checks()
check = checks.check


def rows(case, pattern):
    files = sorted(glob.glob(os.path.join(
        case, "postProcessing", "stress", "*", pattern)))
    if not files:
        raise FileNotFoundError("no %s in %s" % (pattern, case))
    return np.atleast_2d(np.loadtxt(files[0]))


straight = os.path.join(work, "straight")
run = rows(straight, "suspensionStress.dat")
with h5py.File(os.path.join(straight, "postProcessing", "particles.h5"),
               "r") as f:
    data = {k: f[k][...] for k in f.keys()}
cs = CouetteSeries(data, lo=LO, span=SPAN, eta=1.0, layer=LAYER)
whole = CouetteSeries(data, lo=LO, span=SPAN, eta=1.0, layer=0.0)

check("rows written at the 4 write times", abs(len(run) - 4), 0)
for row in run:
    t = row[0]
    k = int(np.argmin(np.abs(cs.t - t)))
    hp, c = cs.core_stresses(k)
    fo_hp = row[11:17]
    ref_hp = hp[np.triu_indices(3)]
    check("t = %g: phi (whole) vs fdmPost" % t,
          rel(row[1], whole.core_volume_fraction(k)), 1e-10)
    check("t = %g: phi_core vs fdmPost" % t,
          rel(row[2], cs.core_volume_fraction(k)), 1e-10)
    check("t = %g: particles in the core vs fdmPost" % t,
          abs(row[3] - cs.in_core(k).sum()), 0)
    check("t = %g: core shear rate vs fdmPost" % t,
          rel(row[5], cs.core_shear_rate(k)), 1e-10)
    check("t = %g: core Sigma^hp vs fdmPost" % t, rel(fo_hp, ref_hp), 1e-10)
    check("t = %g: eta_core = 1 + Sigma^hp_xy/shear rate" % t,
          rel(row[7], 1 + hp[0, 1] / cs.core_shear_rate(k)), 1e-10)

    prof = np.loadtxt(os.path.join(straight, "postProcessing", "stress",
                                   "%g" % t, "profiles.dat"))
    y, phi, up = cs.profiles(BINS, [k])
    check("t = %g: phi(y) vs fdmPost" % t, rel(prof[:, 1], phi), 1e-10)
    occupied = phi > 0
    check("t = %g: u_p(y) vs fdmPost" % t,
          rel(prof[occupied, 2], up[occupied]), 1e-10)
    hp_y, c_y = cs.stress_profiles(BINS, [k])
    upper = np.triu_indices(3)
    check("t = %g: Sigma^hp(y) vs fdmPost" % t,
          rel(prof[:, 5:11], hp_y[:, upper[0], upper[1]]), 1e-10)
    check("t = %g: Sigma^c(y) vs fdmPost" % t,
          rel(prof[:, 11:17], c_y[:, upper[0], upper[1]]), 1e-10)
    volume = (4 / 3 * np.pi * cs.a ** 3).sum()
    check("t = %g: profile volume / particle volume - 1" % t,
          abs(prof[:, 1].sum() * SPAN[0] * SPAN[2] * SPAN[1] / BINS / volume
              - 1), 1e-10)

post = rows(straight, "suspensionStress_*.dat")
check("postProcess rows = run-time rows", rel(post[-4:], run), 1e-12)
restarted = rows(os.path.join(work, "restarted"), "suspensionStress*.dat")
check("restarted run: last row = straight run's", rel(restarted[-1], run[-1]),
      1e-10)

checks.finish()
