"""Sphere-wall resistance functions (sphere radius a = 1, viscosity eta = 1).

Gap variable: eps = h/a - 1 (h: distance centre-wall).  Tensor forms as for
the (11) pair tensors with d = unit normal pointing INTO the wall
(thesis 1, appendix A); sign convention F = -eta R.U (X^A, Y^A, X^C, Y^C > 0).

* Lubrication forms (thesis 1 eq B.2, compilation of Yeo & Maxey 2010;
  X^G, X^P from the pair forms with lambda -> inf, constants of Jeffrey 1992
  at lambda = 100 as chosen in the thesis):
      X^A/(6 pi)  =  1/eps + (1/5) ln(1/eps) + (1/21) eps ln(1/eps) + 0.8193
      X^C/(8 pi)  = -(1/2) eps ln(1/eps) + 1.2021            (1.2021 = zeta(3))
      X^G/(4 pi)  =  (3/2)/eps - (6/5) ln(1/eps) + 0.3912
      X^P/(4 pi)  =  (3/2)/eps - (6/5) ln(1/eps) - 0.552     (constant UNVERIFIED)
      Y^A/(6 pi)  =  (8/15) ln(1/eps) + (64/375) eps ln(1/eps) + 0.9557
      Y^B/(4 pi)  = -(3/15) ln(1/eps) - (43/125) eps ln(1/eps) + 0.3852
      Y^C/(8 pi)  =  (2/5) ln(1/eps) + (66/125) eps ln(1/eps) + 0.3720
      Y^G/(4 pi)  =  (7/10) ln(1/eps) + (221/250) eps ln(1/eps) - 0.923
      Y^H/(8 pi)  = -(1/10) ln(1/eps) + (2/250) eps ln(1/eps) + 0.0916
  valid for eps <~ 0.01 (only the singular terms are exact).
* Chaoui & Feuillebois (2003) expansions (thesis 1 eq B.1) for Y^A, Y^B,
  Y^C, note ln(eps) not ln(1/eps):
      Y^A/(6 pi)  = sum_j phi_j eps^j ln eps + f_j eps^j
      Y^B/(-8 pi) = sum_j gam_j eps^j ln eps + c_j eps^j
      Y^C/(8 pi)  = sum_j gr_j  eps^j ln eps + cr_j eps^j
  Their j = 0, 1 logarithmic terms coincide with the lubrication forms.
  The expansions are intended for small gaps; accuracy beyond eps ~ 0.5 is
  not checked here.
"""

import math

import numpy as np

PI = math.pi

CF = {
    "phi_t": [-8 / 15, -64 / 375, 0.011595712294862, -0.002559314461340,
              0.002165777707452, 0.000351260314552],
    "f_t": [0.954293724783876, 0.429450132564500, -0.001897844702304,
            0.002058408405495, 0.000096108639584, -0.001248147281379],
    "gam_t": [-1 / 10, -43 / 250, -0.036913066460225, 0.001486892317125,
              0.000012689734456, 0.000103798994187],
    "c_t": [-0.192952745666190, 0.100579155700110, 0.094493729126963,
            0.003821112414990, -0.000819028830091, -0.000097511506358],
    "gam_r": [-2 / 5, -0.528001276176667, -0.212879560114862,
              -0.035965644690736, -0.006385459746252, 0.000167620439255],
    "c_r": [0.370892565890165, 0.340079923061464, 0.225531274283815,
            0.097897336215370, 0.005878696055717, 0.001503759398496],
}

# lubrication forms: name -> (scale, (c_1/eps, c_ln, c_eps_ln, const))
LUB = {
    "XA": (6 * PI, (1.0, 1 / 5, 1 / 21, 0.8193)),
    "XC": (8 * PI, (0.0, 0.0, -1 / 2, 1.2021)),
    "XG": (4 * PI, (3 / 2, -6 / 5, 0.0, 0.3912)),
    "XP": (4 * PI, (3 / 2, -6 / 5, 0.0, -0.552)),
    "YA": (6 * PI, (0.0, 8 / 15, 64 / 375, 0.9557)),
    "YB": (4 * PI, (0.0, -3 / 15, -43 / 125, 0.3852)),
    "YC": (8 * PI, (0.0, 2 / 5, 66 / 125, 0.3720)),
    "YG": (4 * PI, (0.0, 7 / 10, 221 / 250, -0.923)),
    "YH": (8 * PI, (0.0, -1 / 10, 2 / 250, 0.0916)),
}

# Chaoui-Feuillebois: name -> (scale, log coefficients, regular coefficients)
_CFSET = {
    "YA": (6 * PI, CF["phi_t"], CF["f_t"]),
    "YB": (-8 * PI, CF["gam_t"], CF["c_t"]),
    "YC": (8 * PI, CF["gam_r"], CF["c_r"]),
}

TABLE_FUNCTIONS = ["XA", "YA", "YB", "XC", "YC", "XG", "XP"]


def lubrication(name, eps):
    """Lubrication form (dimensional)."""
    sc, (a, b, c, d) = LUB[name]
    eps = np.asarray(eps, dtype=float)
    li = np.log(1.0 / eps)
    return sc * (a / eps + b * li + c * eps * li + d)


def chaoui_feuillebois(name, eps):
    """Chaoui & Feuillebois (2003) expansion (dimensional), YA, YB, YC."""
    sc, lg, rg = _CFSET[name]
    eps = np.asarray(eps, dtype=float)
    le = np.log(eps)
    return sc * sum(lg[j] * eps**j * le + rg[j] * eps**j for j in range(6))


def singular(name):
    """(c_1/eps, c_ln(1/eps), c_eps ln(1/eps)) of the table split."""
    if name in _CFSET:
        sc, lg, rg = _CFSET[name]
        # lg_j eps^j ln eps = -lg_j eps^j ln(1/eps)
        return (0.0, -sc * lg[0], -sc * lg[1])
    sc, (a, b, c, d) = LUB[name]
    return (sc * a, sc * b, sc * c)


def function(name, eps):
    """Function used for the table: CF for YA, YB, YC, lubrication else."""
    if name in _CFSET:
        return chaoui_feuillebois(name, eps)
    return lubrication(name, eps)


def remainder(name, eps):
    """function - singular part; finite at eps = 0."""
    eps = np.asarray(eps, dtype=float)
    if name in _CFSET:
        sc, lg, rg = _CFSET[name]
        out = sc * sum(rg[j] * eps**j for j in range(6))
        with np.errstate(divide="ignore", invalid="ignore"):
            le = np.where(eps > 0, np.log(np.where(eps > 0, eps, 1.0)), 0.0)
        out = out + sc * sum(lg[j] * eps**j * le for j in range(2, 6))
        return out
    sc, (a, b, c, d) = LUB[name]
    return sc * d + 0.0 * eps
