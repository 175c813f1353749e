"""Dimensional base functions of the sub-grid method (thesis 1, chapter 3).

``base(name, xi, lam)`` returns the ten dimensional base functions of the
sub-grid method (a1 = 1, eta = 1), "21" meaning the force/torque/stresslet on
sphere 2 due to the motion of sphere 1:

    XA21 = 6 pi X12A^(lam)           YA21 = 6 pi Y12A^(lam)
    YB21 = -4 pi lam^2 Y12B^(1/lam)  XC21 = 8 pi X12C^(lam)
    YC11 = 8 pi Y11C^(lam)           XG11 = 4 pi X11G^(lam)
    YG11 = 4 pi Y11G^(lam)           YH21 = 8 pi lam^3 Y12H^(1/lam)
    XP12 = 4 pi X12P^(lam)           XP21 = 4 pi X21P^(lam)

(relabelling the spheres reverses d, hence the minus sign for B, G, P.)
"""

import math

import numpy as np

from . import twoSphere as ts

PI = math.pi


# name -> (hat name, lambda transform (False: lam, True: 1/lam), factor(lam))
BASE = {
    "XA21": ("X12A", False, lambda l: 6 * PI),
    "YA21": ("Y12A", False, lambda l: 6 * PI),
    "YB21": ("Y12B", True, lambda l: -4 * PI * l**2),
    "XC21": ("X12C", False, lambda l: 8 * PI),
    "YC11": ("Y11C", False, lambda l: 8 * PI),
    "XG11": ("X11G", False, lambda l: 4 * PI),
    "YG11": ("Y11G", False, lambda l: 4 * PI),
    "YH21": ("Y12H", True, lambda l: 8 * PI * l**3),
    "XP12": ("X12P", False, lambda l: 4 * PI),
    "XP21": ("X21P", False, lambda l: 4 * PI),
}
BASE_ORDER = ["XA21", "YA21", "YB21", "XC21", "YC11", "XG11", "YG11",
              "YH21", "XP12", "XP21"]


def base_singular(name, lam):
    """Singular coefficients (of 1/xi, ln(1/xi), xi ln(1/xi)) of a base
    function, dimensional."""
    hname, inv, fac = BASE[name]
    ll = 1.0 / lam if inv else lam
    return tuple(fac(lam) * g for g in ts.singular(hname, ll))


def base(name, xi, lam):
    """Dimensional base function (a1 = 1, eta = 1) at gap xi."""
    hname, inv, fac = BASE[name]
    xi = np.asarray(xi, dtype=float)
    ll = 1.0 / lam if inv else lam
    return fac(lam) * ts.hat(hname, xi, ll)


def base_constant(name, lam):
    """O(1) constant of the near-contact form of a base function
    (dimensional)."""
    hname, inv, fac = BASE[name]
    ll = 1.0 / lam if inv else lam
    return fac(lam) * ts.contact_constant(hname, ll)
