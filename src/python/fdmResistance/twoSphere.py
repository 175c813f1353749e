"""Exact two-sphere resistance functions (twin-multipole solution).

Method
------
Jeffrey & Onishi (1984, J. Fluid Mech. 139, 261) for X^A, Y^A, Y^B, Y^C and
Jeffrey (1992, Phys. Fluids A 4, 16) for X^G, Y^G, Y^H: the multipole
coefficients P_npq, V_npq, Q_npq of the twin-multipole expansion are generated
by their recurrence relations (as corrected by Townsend 2018,
arXiv:1802.08226) and summed into the series

    F(s) = c_0 + sum_{m in parity} c_m t^m ,   t = 2/s ,  s = 2r/(a1+a2) = xi+2,
    c_m  = f_m(lambda) / (2(1+lambda))^m .

As in Jeffrey & Onishi, the slowly convergent part of the series is summed in
closed form: c_m -> g1 + 2 g2/m - 4 g3/(m(m+2)) for m -> inf, and

    sum_m t^m, sum_m (2/m) t^m, sum_m 4/(m(m+2)) t^m

are known functions of t whose expansions at t -> 1 (contact) give exactly the
singular terms g1/xi + g2 ln(1/xi) + g3 xi ln(1/xi).  The remaining series
sum_m (c_m - g1 - 2g2/m + 4g3/(m(m+2))) t^m converges absolutely at t = 1, so
the same expression is accurate for every xi > 0 (far field and near contact);
no switching between a far-field series and a lubrication formula is needed.

Implementation notes
--------------------
The recurrences are evaluated numerically for a given lambda, collapsing the
(p, q) double index into k = p+q with the two weightings
W_nk = sum_{p+q=k} X_npq lambda^q and U_nk = sum_{p+q=k} X_npq lambda^p
(the recurrence swaps the roles of p and q), and scaled by (1+lambda)^-k.
This costs O(K^3) per problem instead of O(K^4) and is written from the
equations, not from any existing code.

Normalisation
-------------
``hat(name, xi, lam)`` returns the dimensionless scalars in the convention of
the reference table data/resistance/reference (Townsend / Wilson): A by
6 pi a1, B and G by 4 pi a1^2, C and H by 8 pi a1^3, for both the 11 and the 12
rows (the pressure moments X12P, X21P, not in the reference: by 4 pi a1^2),
viscosity eta = 1, sign convention F = -eta R.U (X11A > 0, X12A < 0).
The dimensional base functions of the sub-grid method built from them are
in subGridBase; X^C comes from rotletImages, the near-contact coefficients
from nearContact.

Pressure moments X^P
--------------------
X^P_ab: trace s_a of the force dipole  oint (sigma.n)(x - x_a) dS  of sphere a
due to the translation of sphere b along d (d from sphere 1 to sphere 2),
s_a = -eta X^P_ab d.U_b (Jeffrey, Morris & Brady 1993, Phys. Fluids A 5,
2317; the sub-grid method needs X^P_12 and X^P_21).  Derived here, not taken
from JMB's recurrences:

* on a rigid surface n.e.n = 0, so s_a = -a_a oint p dS;
* split p = p_a + p_b into the Lamb expansions about the two centres; the
  singular harmonics p_a (n >= 1) integrate to zero over sphere a and p_b is
  harmonic inside sphere a, so by the mean-value theorem
      s_a = -4 pi a_a^3 p_b(x_a)   (Faxen law for the dipole trace);
* p_b(x_a) follows from the X^A twin-multipole coefficients already solved,
  p_b(x_a) = (3/2) eta U sum_n P_n^b (a_b/R)^(n+1) / a_b  (JO normalisation,
  P_1 = X11A; checked for n = 2 against X^G), reordered as a series in
  t^m / (1+lam)^m, m = k + n + 1 (see _xp_coeffs).  Even m belongs to the
  motion of sphere b itself (X21P, X12P), odd m to sphere a's (X11P, X22P,
  not exported).
The coefficients approach g1 + 2g2/m - 4g3/(m(m+2)) with exactly the g of
the near-contact forms of thesis 1 eq B.1 (residual ~1e-7 at m = 240), so the
singular terms are summed in closed form as for the other functions and the
O(1) constants P12X, P21X follow (contact_constant, subGridBase).
Independent check (test_resistance.py): a least-squares boundary-collocation
solution with Lamb's harmonics about both centres and the trace integrated
over the surface agrees to < 2e-7 for xi = 0.01 .. 3; extrapolating its
remainder to xi -> 0 reproduces the constants to ~1e-4.  Symmetry
X12P^(lam) = -lam^2 X21P^(1/lam) holds to 1e-14.  Far field:
XP21 = 6 pi lam^3 X11A^/R^2 + O(R^-6).
"""

import math
from functools import lru_cache

import numpy as np

from .nearContact import coefficients
from .rotletImages import xc_hat

XP_CONSTANT_KNOWN = True   # X^P series exact, O(1) constants determined

# default truncation order of the twin-multipole series
KMAX = 240

# working precision of the recurrences (np.longdouble was tested: the
# coefficients agree with float64 to ~1e-14, so float64 is kept for speed)
LD = np.float64


# ---------------------------------------------------------------------------
# recurrence engine
# ---------------------------------------------------------------------------

def _binom_table(nmax):
    """table[n, s] = C(n+s, n) and C(n+s, n+1), exact integers rounded to
    long double."""
    b0 = np.zeros((nmax + 1, nmax + 1), dtype=LD)
    b1 = np.zeros((nmax + 1, nmax + 1), dtype=LD)
    for n in range(nmax + 1):
        for s in range(nmax + 1):
            b0[n, s] = LD(str(math.comb(n + s, n)))
            b1[n, s] = LD(str(math.comb(n + s, n + 1)))
    return b0, b1


def _terms(kind, n, s):
    """Recurrence terms for target order n (scalar) and source orders s
    (array).  Each term is (coef(s), source, alpha, beta) meaning
    coef * X_src(s, q - s - alpha, p - n + beta).  Returns dict target->list.
    """
    n = LD(n)
    sf = s.astype(LD)
    out = {}
    if kind == "X":
        b = _B0[int(n), s]
        a = n * (2 * n + 1) * (2 * n * sf - n - sf + 2) / (
            2 * (n + 1) * (2 * sf - 1) * (n + sf))
        out["P"] = [
            (b * a, "P", 0, 1),
            (-b * n * (2 * n - 1) / (2 * (n + 1)), "P", 0, -1),
            (-b * n * (4 * n * n - 1) / (2 * (n + 1) * (2 * sf + 1)), "V", 2, 1),
        ]
        out["Vx"] = [(-b * 2 * n / ((n + 1) * (2 * n + 3)), "P", 0, -1)]
    else:
        b = _B1[int(n), s]
        a = (2 * n + 1) / (2 * (n + 1)) * (
            3 * (n + sf) - (n * sf + 1) * (2 * n * sf - sf - n + 2)) / (
            sf * (n + sf) * (2 * sf - 1))
        out["P"] = [
            (b * a, "P", 0, 1),
            (b * n * (2 * n - 1) / (2 * (n + 1)), "P", 0, -1),
            (b * n * (4 * n * n - 1) / (2 * (n + 1) * (2 * sf + 1)), "V", 2, 1),
            (-b * 2 * (4 * n * n - 1) / (3 * (n + 1)), "Q", 1, 1),
        ]
        out["Q"] = [
            (b * sf / (n + 1), "Q", 1, 0),
            (-b * 3 / (2 * n * sf * (n + 1)), "P", 0, 0),
        ]
        out["Vx"] = [(b * 2 * n / ((n + 1) * (2 * n + 3)), "P", 0, -1)]
    return out


_B0, _B1 = _binom_table(KMAX + 4)


@lru_cache(maxsize=64)
def _solve(problem, lam, K=KMAX):
    """Solve the twin-multipole recurrences for one problem.

    problem: 'XA' (axisymmetric translation), 'YA' (transverse translation),
             'YC' (transverse rotation).
    Returns dict of arrays W[src][n, k] (scaled by (1+lam)^-k), src in P,V,Q.
    """
    kind = "X" if problem == "XA" else "Y"
    N = K + 3
    srcs = ["P", "V"] + (["Q"] if kind == "Y" else [])
    W = {x: np.zeros((N, K + 1), dtype=LD) for x in srcs}
    U = {x: np.zeros((N, K + 1), dtype=LD) for x in srcs}
    if problem in ("XA", "YA"):
        for x in ("P", "V"):
            W[x][1, 0] = U[x][1, 0] = 1.0
    else:  # YC
        W["Q"][1, 0] = U["Q"][1, 0] = 1.0
    lam = LD(lam)
    lp = LD(1) + lam
    # cache of coefficient lists per n (independent of k)
    cache = {}
    for k in range(1, K + 1):
        nmax = min(K - k + 2, N - 1)
        for stage in (("P", "Q"), ("Vx",)):
            for n in range(1, nmax + 1):
                for tgt in stage:
                    if tgt == "Q" and kind == "X":
                        continue
                    key = (n, tgt)
                    if key not in cache:
                        s_all = np.arange(1, N)
                        cache[key] = _terms(kind, n, s_all).get(tgt, [])
                    w = LD(0)
                    u = LD(0)
                    for coef, src, al, be in cache[key]:
                        # k' = k - n - s - al + be  >= 0
                        smax = k - n - al + be
                        if smax < 1:
                            continue
                        s = np.arange(1, smax + 1)
                        kp = k - n - s - al + be
                        c = coef[:smax]
                        sc = lp ** (-(k - kp).astype(LD))
                        w += np.sum(c * lam ** (s + al) * sc * U[src][s, kp])
                        u += np.sum(c * lam ** (n - be) * sc * W[src][s, kp])
                    if tgt == "Vx":
                        W["V"][n, k] = W["P"][n, k] + w
                        U["V"][n, k] = U["P"][n, k] + u
                    else:
                        W[tgt][n, k] = w
                        U[tgt][n, k] = u
    # the U weighting gives the coefficients of sphere 2 (lambda^p), needed
    # for the pressure moment X12P
    W = dict(W)
    W["P_2"] = U["P"]
    return W


def _coeffs(fun, lam, K=KMAX):
    """c_m = f_m / (2(1+lam))^m, m = 0..K, for the given series."""
    return _coeffs_ld(fun, lam, K).astype(float)


def _coeffs_ld(fun, lam, K=KMAX):
    m = np.arange(K + 1)
    odd = (m % 2).astype(LD)
    lam = LD(lam)
    if fun == "XA":
        return _solve("XA", lam, K)["P"][1]
    if fun == "YA":
        return _solve("YA", lam, K)["P"][1]
    if fun == "YB":
        return 2.0 * _solve("YA", lam, K)["Q"][1]
    if fun == "YC":
        return lam ** odd * _solve("YC", lam, K)["Q"][1]
    if fun == "XG":
        return 0.75 * _solve("XA", lam, K)["P"][2]
    if fun == "YG":
        return 0.75 * _solve("YA", lam, K)["P"][2]
    if fun == "YH":
        return -0.375 * lam ** odd * _solve("YC", lam, K)["P"][2]
    if fun in ("XP21", "XP12"):
        return _xp_coeffs(fun, lam, K)
    raise KeyError(fun)


def _xp_coeffs(fun, lam, K=KMAX):
    """Series coefficients of the pressure moments (see module docstring):
    the pressure of the other sphere's Lamb expansion at the centre of
    sphere alpha,  p_beta(x_alpha) = (3/2) eta U sum_n P_n^beta
    (a_beta/R)^(n+1) / a_beta  (a1 = 1), reordered as a series in
    t^m / (1+lam)^m with m = k + n + 1.

    XP21 (trace on 2, sphere 1 moves): c_m = (3/2) lam^3 sum_n W_n,m-n-1
          (1+lam)^-(n+1)             -> X21P^ = sum_{m even} c_m t^m
    XP12 (trace on 1, sphere 2 moves): c_m = (3/2) sum_n U_n,m-n-1
          lam^n (1+lam)^-(n+1)       -> X12P^ = -sum_{m even} c_m t^m
    (W, U: the lambda^q and lambda^p weightings = sphere 1 and sphere 2
    coefficients; even m = motion of the sphere that carries the harmonics,
    in its own frame whose axis points to the other sphere)."""
    S = _solve("XA", lam, K)
    lam = LD(lam)
    if fun == "XP21":
        C, fac = S["P"], 1.5 * lam ** 3
        wn = lambda n: LD(1)
    else:
        C, fac = S["P_2"], LD(1.5)
        wn = lambda n: lam ** n
    c = np.zeros(K + 1, dtype=LD)
    lp = LD(1) + lam
    for n in range(1, K):
        k = np.arange(0, K - n)              # m = k + n + 1 <= K
        c[k + n + 1] += wn(n) * lp ** (-(n + 1)) * C[n, k]
    return fac * c


# hat function -> (coefficient series, g-set, parity, sign, include c0)
_SPEC = {
    "X11A": ("XA", "XA", 0, +1, True),
    "X12A": ("XA", "XA", 1, -1, False),
    "Y11A": ("YA", "YA", 0, +1, True),
    "Y12A": ("YA", "YA", 1, -1, False),
    "Y11B": ("YB", "YB", 1, +1, False),
    "Y12B": ("YB", "YB", 0, -1, False),
    "Y11C": ("YC", "YC11", 0, +1, True),
    "Y12C": ("YC", "YC12", 1, +1, False),
    "X11G": ("XG", "XG", 1, +1, False),
    "X12G": ("XG", "XG", 0, -1, False),
    "Y11G": ("YG", "YG", 1, +1, False),
    "Y12G": ("YG", "YG", 0, -1, False),
    "Y11H": ("YH", "YH11", 0, +1, False),
    "Y12H": ("YH", "YH12", 1, +1, False),
    "X21P": ("XP21", "XP21", 0, +1, False),
    "X12P": ("XP12", "XP12", 0, -1, False),
}


def _closed_sums(xi, parity):
    """E1 = sum t^m, E2 = sum 2/m t^m, E3 = sum 4/(m(m+2)) t^m over the
    parity class (even: m>=2, odd: m>=1), t = 2/(2+xi).  Written in xi to
    avoid the cancellation in 1 - t^2 near contact."""
    xi = np.asarray(xi, dtype=float)
    q = xi * (4.0 + xi)                      # = 4 (1 - t^2) / t^2
    if parity == 0:
        L = np.log((2.0 + xi) ** 2 / q)      # -ln(1 - t^2)
        return 4.0 / q, L, 1.0 - 0.25 * q * L
    L = np.log((4.0 + xi) / xi)              # ln((1+t)/(1-t))
    return 2.0 * (2.0 + xi) / q, L, (2.0 + xi) - 0.25 * q * L


def _residual_coeffs(name, lam, K=KMAX):
    fun, gname, par, sign, c0 = _SPEC[name]
    c = _coeffs(fun, lam, K)
    g1, g2, g3 = coefficients(gname, lam)
    m = np.arange(K + 1, dtype=float)
    mm = np.where(m > 0, m, 1.0)
    e = c - g1 - 2 * g2 / mm + 4 * g3 / (mm * (mm + 2))
    sel = (np.arange(K + 1) % 2 == par) & (np.arange(K + 1) > 0)
    return c, e, sel, (g1, g2, g3)


def _tail_correction(e, sel, t):
    """Estimate of sum_{m>K} e_m t^m assuming e_m ~ C m^-p (fitted on the
    last coefficients).  Small; reduces truncation error at t -> 1."""
    idx = np.nonzero(sel)[0]
    m1, m2 = idx[-20], idx[-1]
    e1, e2 = e[m1], e[m2]
    if e1 == 0.0 or e2 == 0.0 or np.sign(e1) != np.sign(e2) or abs(e2) >= abs(e1):
        return 0.0
    p = math.log(e1 / e2) / math.log(m2 / m1)
    if p <= 1.5:
        return 0.0
    C = e2 * m2 ** p
    mt = np.arange(m2 + 2, m2 + 20002, 2, dtype=float)
    w = C * mt ** (-p)
    t = np.atleast_1d(np.asarray(t, dtype=float))
    return np.array([np.sum(w * ti ** mt) for ti in t])


def hat(name, xi, lam, K=KMAX, tail=True):
    """Dimensionless scalar `name` (e.g. 'X11A', 'Y12H', 'X12C') at gap xi."""
    xi = np.asarray(xi, dtype=float)
    if name in ("X11C", "X12C"):
        return xc_hat(name, xi, lam)
    fun, gname, par, sign, inc0 = _SPEC[name]
    c, e, sel, (g1, g2, g3) = _residual_coeffs(name, lam, K)
    t = 2.0 / (2.0 + xi)
    E1, E2, E3 = _closed_sums(xi, par)
    m = np.arange(K + 1)[sel]
    tt = np.atleast_1d(t)[:, None] ** m[None, :]
    ser = tt @ e[sel]
    if tail:
        ser = ser + _tail_correction(e, sel, np.atleast_1d(t))
    val = g1 * E1 + g2 * E2 - g3 * E3 + ser.reshape(np.shape(t))
    if inc0:
        val = val + c[0]
    return sign * val


def singular(name, lam):
    """Near-contact singular coefficients (g1, g2, g3) of the hat function:
    hat = g1/xi + g2 ln(1/xi) + g3 xi ln(1/xi) + const + o(1)."""
    if name == "X11C":
        return (0.0, 0.0, -lam**2 / (4 * (1 + lam)))
    if name == "X12C":
        return (0.0, 0.0, lam**2 / (4 * (1 + lam)))
    fun, gname, par, sign, inc0 = _SPEC[name]
    g = coefficients(gname, lam)
    return tuple(sign * x for x in g)


def contact_constant(name, lam, K=KMAX):
    """O(1) constant of the near-contact form of the hat function,
    evaluated in closed form at t = 1 (xi = 0)."""
    if name in ("X11C", "X12C"):
        from scipy.special import zeta
        r = lam / (1.0 + lam)
        if name == "X11C":
            return float(r**3 * zeta(3, r))
        return float(-r**3 * zeta(3, 1.0))
    fun, gname, par, sign, inc0 = _SPEC[name]
    c, e, sel, (g1, g2, g3) = _residual_coeffs(name, lam, K)
    ser = np.sum(e[sel]) + float(np.sum(_tail_correction(e, sel, 1.0)))
    if par == 0:   # E1 - 1/xi -> -1/4, E2 - ln(1/xi) -> 0, E3 -> 1
        val = -0.25 * g1 - g3 + ser
    else:          # O1 - 1/xi -> 1/4, O2 - ln(1/xi) -> 2 ln 2, O3 -> 2
        val = 0.25 * g1 + 2 * math.log(2.0) * g2 - 2 * g3 + ser
    if inc0:
        val += c[0]
    return float(sign * val)
