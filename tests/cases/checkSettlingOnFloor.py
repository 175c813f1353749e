"""Checks of the settlingOnFloor case test (see settlingOnFloor.sh)."""

import math
import sys

import h5py
import numpy as np

from fdmPost.checks import Checks
from fdmResistance.pairContact import ContactLaw

# Case data: a = 1, eta = rho = 1, buoyant weight W = 6 pi eta a^2 (1/s)
# along -y, Stokes velocity W/(6 pi eta a) = 1, h_r = 5e-3, gapFloor 1e-5
W = 6 * np.pi
N = 3
hr, floor = 5e-3, 1e-5
LAW = ContactLaw(roughness=hr, friction=0.5, mean_deformation=0.2,
                 gap_floor=floor, lam=1)
# Gaps where the lubricated approach is compared with Brenner's drag: the
# squeeze film dominates (drag 50 to 200 times Stokes'), beside which the
# far field of this box (the lid, the periodic images, the flow of the
# other spheres, 2 % on the lowest sphere while the others fall) is small,
# and the contact is not yet reached
APPROACH = (0.005, 0.02)


def brenner(d):
    """Drag on a sphere moving normal to a no-slip plane wall over its
    Stokes drag, centre d radii from the wall (H. Brenner, Chem. Eng. Sci.
    16 (1961) 242), the terms of the series divided by
    exp((2n+1) alpha) so that they stay finite."""
    alpha = math.acosh(d)
    total = 0.0
    for n in range(1, 100000):
        k = 2 * n + 1
        e = math.exp(-k * alpha)
        num = 1 - e * e + k * math.sinh(2 * alpha) * e
        den = (1 - e) ** 2 - k * k * math.sinh(alpha) ** 2 * e
        term = n * (n + 1) / ((2 * n - 1) * (2 * n + 3)) * (num / den - 1)
        total += term
        if abs(term) < 1e-13 * abs(total):
            break
    return 4.0 / 3.0 * math.sinh(alpha) * total


def records(case):
    with h5py.File(f"{case}/postProcessing/particles.h5", "r") as f:
        return {k: f[k][:] for k in ("time", "position", "velocity",
                                     "contactForce", "force")}


def fluid_balance(case):
    """Integral of lambda and force of the walls on the fluid at each step
    (momentumBalance.dat)."""
    table = np.loadtxt(f"{case}/postProcessing/momentumBalance/0/"
                       "momentumBalance.dat")
    return table[:, 1:4], table[:, 7:10]


def approach_error(r):
    """Largest |U_y / (-U_s/lambda_Brenner) - 1| over the records with the
    gap in APPROACH, and how many records that was."""
    gap = r["position"][:, :, 1] - 1
    inside = (gap > APPROACH[0]) & (gap < APPROACH[1])
    expected = np.array([-1 / brenner(1 + g) for g in gap[inside]])
    measured = r["velocity"][:, :, 1][inside]
    return np.abs(measured / expected - 1).max(), int(inside.sum())


def main(case):
    r = records(case)
    lambda_v, wall = fluid_balance(case)
    end = {k: v[-1] for k, v in r.items()}
    gap = end["position"][:, 1] - 1
    body = np.array([0, -W, 0])

    c = Checks(width=62)
    # The series against its limits: the reflections far from the wall
    # (Lorentz), the lubrication expansion near it (Cox & Brenner 1967)
    c.check("Brenner at d = 100 against 1/(1 - 9/(8 d) + 1/(2 d^3))",
            abs(brenner(100) * (1 - 9 / 800 + 0.5e-6) - 1), 1e-5)
    c.check("Brenner at h = 1e-3 a against a/h + ln(a/h)/5 + 0.971",
            abs(brenner(1.001) / (1e3 + math.log(1e3) / 5 + 0.971) - 1),
            1e-5)

    c.check("rest: max |overlap / eq 2.57 equilibrium under W - 1|",
            np.abs((hr - gap) / LAW.overlap_under(W) - 1).max(), 1e-2)
    c.check("rest: max |normal contact force / W - 1|",
            np.abs(end["contactForce"][:, 1] / W - 1).max(), 1e-2)
    c.check("rest: max |U| / Stokes velocity",
            np.abs(end["velocity"]).max(), 1e-4)
    # To the lambda residual (1e-3) where the fluid carries the load
    c.check("all steps: max |F^h + F^c + F_b| / W (eq 4.17)",
            np.abs(r["force"] + r["contactForce"] + body).max() / W, 2e-3)

    # The walls carry the buoyant weight: at the start through the fluid
    # alone (no gap within the sub-grid cut-off, no contact), at the end
    # through the contacts (above); the fluid's balance at every step
    c.check("start: |walls' force on the fluid / (N W) - (0 1 0)|",
            np.abs(wall[0] / (N * W) - [0, 1, 0]).max(), 2e-3)
    c.check("all steps: max |walls' force + lambda| / (N W) (eq 4.14)",
            np.abs(wall + lambda_v).max() / (N * W), 2e-3)

    err, n = approach_error(r)
    print(f"   approach: {n} records with the gap in {APPROACH}")
    c.check("approach: max |U_y / Brenner - 1|", err, 3e-2)
    c.finish()


if __name__ == "__main__":
    main(sys.argv[1])
