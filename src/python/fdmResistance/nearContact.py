"""Near-contact coefficients of the two-sphere resistance functions.

The singular terms g1/xi + g2 ln(1/xi) + g3 xi ln(1/xi) of the hat
functions of twoSphere (Jeffrey & Onishi 1984, Jeffrey 1992, as corrected
by Townsend 2018), in the hat normalisation of the 11 rows (for 12 rows the
same g multiply the series; see twoSphere._SPEC), and the X^P forms of
thesis 1 eq B.1 (Jeffrey, Morris & Brady 1993).
"""

import math

PI = math.pi


def coefficients(name, l):
    """(g1, g2, g3) of the coefficient set `name` at lambda = l."""
    p3 = (1 + l) ** 3
    p2 = (1 + l) ** 2
    p1 = 1 + l
    if name == "XA":
        return (2 * l**2 / p3, l * (1 + 7 * l + l**2) / (5 * p3),
                (1 + 18 * l - 29 * l**2 + 18 * l**3 + l**4) / (42 * p3))
    if name == "YA":
        return (0.0, 4 * l * (2 + l + 2 * l**2) / (15 * p3),
                2 * (16 - 45 * l + 58 * l**2 - 45 * l**3 + 16 * l**4) / (375 * p3))
    if name == "YB":
        return (0.0, -l * (4 + l) / (5 * p2),
                -(32 - 33 * l + 83 * l**2 + 43 * l**3) / (250 * p2))
    if name == "YC11":
        return (0.0, 2 * l / (5 * p1), (8 + 6 * l + 33 * l**2) / (125 * p1))
    if name == "YC12":
        return (0.0, l**2 / (10 * p1), l * (43 - 24 * l + 43 * l**2) / (500 * p1))
    if name == "XG":
        return (3 * l**2 / p3, 3 * (l + 12 * l**2 - 4 * l**3) / (10 * p3),
                (5 + 181 * l - 453 * l**2 + 566 * l**3 - 65 * l**4) / (140 * p3))
    if name == "YG":
        return (0.0, (4 * l - l**2 + 7 * l**3) / (10 * p3),
                (32 - 179 * l + 532 * l**2 - 356 * l**3 + 221 * l**4) / (500 * p3))
    if name == "YH11":
        return (0.0, (2 * l - l**2) / (10 * p2),
                (16 - 61 * l + 180 * l**2 + 2 * l**3) / (500 * p2))
    if name == "YH12":
        return (0.0, (l**2 + 7 * l**3) / (20 * p2),
                (43 * l + 147 * l**2 - 185 * l**3 + 221 * l**4) / (1000 * p2))
    if name == "XP21":   # thesis 1 eq B.1 / (4 pi a1^2)
        return tuple(x / (4 * PI) for x in xp_singular("XP21", l))
    if name == "XP12":   # the series carries sign -1 (see _SPEC)
        return tuple(-x / (4 * PI) for x in xp_singular("XP12", l))
    raise KeyError(name)


def xp_singular(name, lam):
    """Singular terms of the near-contact X^P forms of thesis 1 eq B.1
    (Jeffrey, Morris & Brady 1993), dimensional (a1 = 1).  The series of
    twoSphere._xp_coeffs reproduces them (test_residual_coefficients_decay)."""
    A = PI * (1 + lam) ** 2
    if name == "XP12":
        l = lam
        return (A * (-12 * l**2 / (1 + l) ** 5),
                A * (-12 * (l - 4 * l**2) / (10 * (1 + l) ** 4)),
                A * (-4 * (5 - 97 * l + 64 * l**2 - 44 * l**3 + l**4)
                     / (140 * (1 + l) ** 4)))
    m = 1.0 / lam
    return (A * (12 * m**2 / (1 + m) ** 5),
            A * (12 * (m - 4 * m**2) / (10 * (1 + m) ** 4)),
            A * (4 * (5 - 97 * m + 64 * m**2 - 44 * m**3 + m**4)
                 / (140 * (1 + m) ** 4)))
