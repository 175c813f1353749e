#!/usr/bin/env python3
"""Checks of poiseuilleSuspension.sh (10 steps of the Poiseuille tutorial).

References: conservation of x momentum over the whole channel (the
pressure-gradient force -V dP0/dx leaves through the walls: the fluid's
wall shear plus the particles' lambda, which the particles pass on by
sub-grid lubrication and contacts with the walls; thesis eqs 4.14-4.16),
to the coupling tolerance; and the slope of the shear-stress profile
Sigma_xy(y) = eta dU/dy + Sigma^hp_xy + Sigma^c_xy (eqs 6.13, 6.18-6.19)
against dP0/dx (eq F.6a) on the a1 bins away from the walls, within 15 %
(the particle stresslets are spread over a diameter; the tutorial's run
gives 1-6 %).  The particle system solved by subdomain against solved
whole on every rank (first 5 steps): positions within 2e-4 a, velocities
and stresslets within 5e-3 of their largest values (both runs stop at a
lambda residual of 1e-3 by different preconditioners: measured 3e-5 a,
1.0e-3 and 8.8e-4; a contribution lost across the processor boundary
would change a straddling sphere's velocity by order one).
"""

import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost import channelFlow as cf  # noqa: E402
from fdmPost.checks import Checks, rel_linf  # noqa: E402

work = sys.argv[1]
checks = Checks()

cs, L, n, eta, G = cf.read_case(work)
fluid, particles, residual = cf.global_balance(work, 0.0)
print(f"fluid wall shear {fluid:.3f}, particles {particles:.3f} of the drive")
checks.check("x momentum: |wall + lambda + drive| / |drive|", residual, 1e-2)

nb = int(round(L[1]))
edges = np.linspace(0, L[1], nb + 1)
yb = 0.5 * (edges[1:] + edges[:-1])
U = cf.mean_layers(work, "U", (0.025, 0.05), n)[:, 0]
hp, c = cs.stress_profiles(nb, range(len(cs.t)))
sxy = eta * cf.shear_rate_bins(U, edges, L[1]) + hp[:, 0, 1] + c[:, 0, 1]
slope, level = cf.shear_stress_line(yb, sxy, L[1], (yb > 1) & (yb < L[1] - 1))
print(f"dSigma_xy/dy {slope:.4f}, dP0/dx {G:g}, level {level:.3f}")
checks.check("shear stress slope: |dSigma_xy/dy - dP0/dx| / |dP0/dx|",
             abs(slope - G) / abs(G), 0.15)

with h5py.File(os.path.join(work, "postProcessing", "particles.h5"),
               "r") as whole, \
        h5py.File(os.path.join(work, "distributed", "postProcessing",
                               "particles.h5"), "r") as owned:
    m = len(owned["time"])
    checks.check("by subdomain: records of 5 steps (count error)",
                 abs(m - 6) + abs(owned["time"][-1] - whole["time"][m - 1]), 0)
    checks.check("by subdomain: position against whole (max, a)",
                 np.abs(owned["position"][:] - whole["position"][:m]).max(),
                 2e-4)
    for key in ("velocity", "stresslet"):
        checks.check("by subdomain: %s against whole (rel. max)" % key,
                     rel_linf(owned[key][:], whole[key][:m]), 5e-3)
checks.finish()
