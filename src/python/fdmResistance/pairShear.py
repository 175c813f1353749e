"""Two free (force- and torque-free) equal spheres in unbounded simple shear.

Reference solution for thesis 1, section 4.1.3 (Fig. 4.9): ambient flow
u_inf = gamma_dot y e_x, spheres of radius a = 1, gamma_dot = 1, viscosity 1.

Convention
----------
r = x2 - x1 (centre of sphere 2 minus centre of sphere 1), d = r/|r|,
V = dr/dt = U2 - U1.  (The thesis writes r_x = x1 - x2; its curves are the
point reflection r -> -r of ours, which maps every trajectory of this flow
onto a trajectory, so the pictures coincide up to the labelling of the
spheres.)  Gap xi = |r| - 2 (= 2r/(a1+a2) - 2 of twoSphere for a = 1).

Method (no mobility-function formulas)
--------------------------------------
The 12 x 12 resistance problem is solved directly (pairResistance, whose
E_INF, W_INF, scalars, grand_resistance and free_motion are re-exported
here).
The Batchelor & Green (1972) functions follow from the solution without any
further formula: V = W_inf x r + E.r - [A d d + B (I - d d)].E.r, so A is
read from a pure straining along d (E = d d - I/3: E.r = (2/3) r d) and B
from E = (e d + d e)/2 with e normal to d (E.r = r e / 2).

Trajectories integrate dr/dt = V(r) with scipy's DOP853 (rtol 1e-12); for
speed V uses A(r), B(r) from cubic splines in u = ln(xi) (801 nodes,
xi = 1e-12 .. 98; (1 - A)(1 + xi)/xi and B are splined) tabulated from the
direct solve; |error| < 5e-10 in A, B for 1e-8 < xi < 50 (up to 1.5e-8 in B
at xi ~ 1e-11, where the direct solve itself is at round-off);
relative_velocity(r, exact=True) is the direct solve itself.

Verification (test_pairShear.py)
--------------------------------
* far field: Batchelor & Green (1972) series (AB_far) reproduced to 2e-15
  (A) / 5e-16 (B) at r = 20 and 2e-11 / 5e-13 at r = 10 (omitted r^-13);
* near contact: (1 - A)/xi = 4.07742 (B & G: 4.077); B(2) = 0.405932
  (B_contact; B & G: 0.4060); B converges like 1/ln(1/xi)
  (B = 0.3158 at xi = 1e-4, 0.3432 at 1e-6, 0.3669 at 1e-10);
* trajectories from (-6, y0, 0): r_y at r_x = +6 equals y0 to < 5e-9
  for y0 >= 0.01; minimum gap (at r_x = 0) 7.076e-3 (y0 = 1), 2.523e-4
  (0.5), 6.841e-5 (0.25), 4.470e-5 (0.1), 4.110e-5 (0.01), -> 4.107e-5
  for y0 -> 0 (the grazing limit, Zarraga & Leighton's ~4e-5 a).  Below
  y0 ~ 1e-3 neighbouring orbits differ by < 1e-10 in gap near contact and
  the integration jumps between them (trajectory raises).
"""

import math
import time

import numpy as np

from . import twoSphere as ts

PI = math.pi
LAM = 1.0

from .pairResistance import (E_INF, FACTOR, PARITY, W_INF,  # noqa: F401
                             free_motion, grand_resistance, scalars)

def relative_velocity(r_vec, exact=False):
    """V = dr/dt = U2 - U1 for r = x2 - x1 in u_inf = y e_x (a = gamma_dot
    = 1).  exact=True: direct resistance solve; otherwise the Batchelor-Green
    form with the tabulated A(r), B(r) (same values to < 1e-9)."""
    r_vec = np.asarray(r_vec, dtype=float)
    if exact:
        U1, U2, _, _ = free_motion(r_vec, xc=False)
        return U2 - U1
    r = float(np.linalg.norm(r_vec))
    A, B = AB_interp(r)
    return bg_velocity(r_vec, A, B)


def bg_velocity(r_vec, A, B):
    r = np.linalg.norm(r_vec)
    d = r_vec / r
    Er = E_INF @ r_vec
    dEr = d @ Er
    return np.cross(W_INF, r_vec) + Er - (A * dEr * d + B * (Er - dEr * d))


def AB_exact(r):
    """Batchelor & Green A(r), B(r) from the direct solve (array r)."""
    r = np.atleast_1d(np.asarray(r, dtype=float))
    S = scalars(r - 2.0, xc=False)
    d = np.array([0.0, 0.0, 1.0])
    e = np.array([1.0, 0.0, 0.0])
    Ea = np.outer(d, d) - np.eye(3) / 3.0
    Eb = 0.5 * (np.outer(e, d) + np.outer(d, e))
    A = np.empty_like(r)
    B = np.empty_like(r)
    zero = np.zeros(3)
    for k, rk in enumerate(r):
        U1, U2, _, _ = free_motion(rk * d, Ea, zero, S=S, k=k)
        A[k] = 1.0 - (U2 - U1) @ d / (2.0 * rk / 3.0)
        U1, U2, _, _ = free_motion(rk * d, Eb, zero, S=S, k=k)
        B[k] = 1.0 - (U2 - U1) @ e / (rk / 2.0)
    return A, B


def B_contact(L=1e10):
    """B at contact (xi -> 0).  B converges like 1/ln(1/xi), too slowly to
    read off the series, so the scalars are replaced by their near-contact
    forms g1/xi + g2 L + const (twoSphere.singular, contact_constant) with
    L = ln(1/xi) -> infinity (the 1/xi terms, radial squeeze, do not enter
    the B problem: its relative velocity is normal to d by symmetry).
    The error is O(1/L)."""
    xi_sq = 1e-12
    S = {}
    for f, p in PARITY.items():
        letter = f[1]
        if f == "XC":
            v = [1.0, 0.0]
        else:
            v = []
            for ab in ("11", "12"):
                name = f[0] + ab + letter
                g1, g2, g3 = ts.singular(name, LAM)
                v.append(g1 / xi_sq + g2 * L + ts.contact_constant(name, LAM))
        s11, s12 = v[0] * FACTOR[letter], v[1] * FACTOR[letter]
        S[f] = np.array([[[s11], [s12]], [[p * s12], [p * s11]]])
    d = np.array([0.0, 0.0, 1.0])
    e = np.array([1.0, 0.0, 0.0])
    Eb = 0.5 * (np.outer(e, d) + np.outer(d, e))
    U1, U2, _, _ = free_motion(2.0 * d, Eb, np.zeros(3), S=S, k=0)
    return 1.0 - (U2 - U1) @ e


# ---------------------------------------------------------------------------
# far field (Batchelor & Green 1972, eqs. for A and B; r in units of a)
# ---------------------------------------------------------------------------

def AB_far(r):
    """Batchelor & Green (1972) far-field series, equal spheres, r = R/a:
    A = 5/r^3 - 8/r^5 + 25/r^6 - 35/r^8 + 125/r^9 - 102/r^10 + 12.5/r^11
        + 430/r^12 + O(r^-13)
    B = (16/r^5 + 10/r^8 - 36/r^10 - 25/r^11 - 36/r^12)/3 + O(r^-13)."""
    r = np.asarray(r, dtype=float)
    A = (5 / r**3 - 8 / r**5 + 25 / r**6 - 35 / r**8 + 125 / r**9
         - 102 / r**10 + 12.5 / r**11 + 430 / r**12)
    B = (16 / r**5 + 10 / r**8 - 36 / r**10 - 25 / r**11 - 36 / r**12) / 3.0
    return A, B


# ---------------------------------------------------------------------------
# tabulation (cubic spline in u = ln xi) for the trajectory integration
# ---------------------------------------------------------------------------

_U_MIN, _U_MAX, _NU = math.log(1e-12), math.log(98.0), 801
_TAB = {}


def _table():
    if not _TAB:
        from scipy.interpolate import CubicSpline
        u = np.linspace(_U_MIN, _U_MAX, _NU)
        xi = np.exp(u)
        A, B = AB_exact(2.0 + xi)
        # (1 - A)(1 + xi)/xi -> 4.077 at contact, -> 1 far away: keeps the
        # relative accuracy of the radial velocity near contact
        _TAB["A"] = CubicSpline(u, (1.0 - A) * (1.0 + xi) / xi)
        _TAB["B"] = CubicSpline(u, B)
    return _TAB


def AB_interp(r):
    """A(r), B(r) interpolated (scalar r); direct solve outside the table
    (xi < 1e-12 or r > 100)."""
    xi = r - 2.0
    if xi <= 0.0:
        raise ValueError("spheres overlap: r = %r" % r)
    u = math.log(xi)
    if u < _U_MIN or u > _U_MAX:
        A, B = AB_exact(np.array([r]))
        return float(A[0]), float(B[0])
    T = _table()
    return 1.0 - xi / (1.0 + xi) * float(T["A"](u)), float(T["B"](u))


# ---------------------------------------------------------------------------
# trajectories
# ---------------------------------------------------------------------------

def _integrate(x0, y0, z0, rtol, atol, exact, max_time, AB=None):
    from scipy.integrate import solve_ivp
    if x0 >= 0.0 or y0 <= 0.0:
        raise ValueError("need x0 < 0 and y0 > 0")
    xend = abs(x0)

    def rhs(t, y):
        if AB is not None:
            return bg_velocity(y, *AB(float(np.linalg.norm(y))))
        return relative_velocity(y, exact=exact)

    def done(t, y):
        return y[0] - xend
    done.terminal = True
    done.direction = 1.0

    def wrapped(t, y):          # crossed the x axis: went round the sphere
        return y[1]
    wrapped.terminal = True
    wrapped.direction = -1.0

    sol = solve_ivp(rhs, (0.0, max_time), [x0, y0, z0], method="DOP853",
                    rtol=rtol, atol=atol, events=(done, wrapped),
                    dense_output=True)
    if sol.status != 1 or len(sol.t_events[0]) == 0:
        raise RuntimeError(
            "trajectory from (%g, %g, %g) did not reach r_x = %g (%s); for "
            "y0 below ~1e-3 at |x0| = 6 neighbouring orbits differ by < 1e-10 "
            "in gap and the integration cannot follow them"
            % (x0, y0, z0, xend, sol.message))
    return sol


def trajectory(x0, y0, z0=0.0, rtol=1e-12, atol=1e-14, exact=False,
               max_time=1e4, AB=None):
    """Relative trajectory from r = (x0, y0, z0), x0 < 0, y0 > 0 (sphere 2
    upstream of sphere 1, moving in +x), until r_x = |x0|.
    Returns (t, rx, ry, rz, gap) at the DOP853 steps; the last point is the
    event point r_x = |x0|.  exact=True evaluates V by the direct solve at
    every stage (about 1 ms each) instead of the A, B splines; AB, a
    callable r -> (A, B), replaces both (trajectories of measured
    mobility functions)."""
    sol = _integrate(x0, y0, z0, rtol, atol, exact, max_time, AB)
    te, ye = sol.t_events[0][0], sol.y_events[0][0]
    keep = sol.t < te
    t = np.append(sol.t[keep], te)
    Y = np.column_stack([sol.y[:, keep], ye])
    gap = np.linalg.norm(Y, axis=0) - 2.0
    return t, Y[0], Y[1], Y[2], gap


def trajectory_summary(x0, y0, z0=0.0, **kw):
    """dict: ry_end, rz_end, t_end, min_gap (minimum of |r| - 2 refined on
    the dense output by golden-section search), r_at_min.  Keywords as
    trajectory()."""
    sol = _integrate(x0, y0, z0, kw.get("rtol", 1e-12), kw.get("atol", 1e-14),
                     kw.get("exact", False), kw.get("max_time", 1e4),
                     kw.get("AB"))
    te, ye = sol.t_events[0][0], sol.y_events[0][0]
    ts_ = sol.t[sol.t < te]
    gaps = np.linalg.norm(sol.y[:, sol.t < te], axis=0) - 2.0
    i = int(np.argmin(gaps))
    a, b = ts_[max(i - 1, 0)], (ts_[i + 1] if i + 1 < len(ts_) else te)
    f = lambda s: float(np.linalg.norm(sol.sol(s)) - 2.0)
    g = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(100):
        c, e = b - g * (b - a), a + g * (b - a)
        if f(c) < f(e):
            b = e
        else:
            a = c
    tm = 0.5 * (a + b)
    return {"ry_end": float(ye[1]), "rz_end": float(ye[2]), "t_end": float(te),
            "min_gap": min(f(tm), float(gaps[i])), "r_at_min": sol.sol(tm)}


def _main():
    t0 = time.time()
    rs = np.array([2.0001, 2.01, 2.1, 2.5, 3.0, 4.0, 6.0])
    A, B = AB_exact(rs)
    Af, Bf = AB_far(rs)
    print("Batchelor-Green functions, equal spheres (direct 12x12 solve)")
    print("%8s %14s %14s %14s %14s" % ("r/a", "A", "B", "A far-field",
                                       "B far-field"))
    for k, r in enumerate(rs):
        print("%8.4f %14.8f %14.8f %14.8f %14.8f" % (r, A[k], B[k], Af[k],
                                                      Bf[k]))
    print("(1 - A)/xi at xi = 1e-6: %.5f" % ((1 - AB_exact([2 + 1e-6])[0][0])
                                            / 1e-6))
    print("B at xi = 1e-6, 1e-10: %.6f %.6f; contact limit B(2) = %.6f"
          % (AB_exact([2 + 1e-6])[1][0], AB_exact([2 + 1e-10])[1][0],
             B_contact()))
    print("\nTrajectories in the shear plane, r from (-6, y0, 0) to "
          "r_x = +6 (a = 1)")
    print("%6s %14s %14s %12s %10s" % ("y0", "ry(end)", "ry(end)-y0",
                                       "min gap", "t_end"))
    for y0 in (0.25, 0.5, 1.0):
        s = trajectory_summary(-6.0, y0)
        print("%6.2f %14.10f %14.3e %12.4e %10.3f"
              % (y0, s["ry_end"], s["ry_end"] - y0, s["min_gap"], s["t_end"]))
    print("\nruntime %.1f s" % (time.time() - t0))


if __name__ == "__main__":
    _main()
