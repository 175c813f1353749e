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
The 12 x 12 resistance problem is solved directly.  With Kim & Karrila
(1991) / Jeffrey & Onishi (1984) / Jeffrey (1992) conventions (spec
Appendix A, /work/shared/spec/seed1-method.md section 9):

    F^a = sum_b [ A^ab (U_inf(x_b) - U^b) + Bt^ab (W_inf - W^b) + Gt^ab : E ]
    T^a = sum_b [ B^ab (U_inf(x_b) - U^b) + C^ab  (W_inf - W^b) + Ht^ab : E ]

    A_ij  = X^A d_i d_j + Y^A (delta_ij - d_i d_j)         (C alike)
    B_ij  = Y^B eps_ijk d_k
    G_ijk = X^G (d_i d_j - delta_ij/3) d_k + Y^G (d_i delta_jk + d_j delta_ik
            - 2 d_i d_j d_k)
    H_ijk = Y^H (d_i eps_jkm d_m + d_j eps_ikm d_m)
    Lorentz reciprocity: Bt^ab_ij = B^ba_ji, Gt^ab_ijk = G^ba_jki,
                         Ht^ab_ijk = H^ba_jki.

F = T = 0 for both spheres gives 12 linear equations for (U^a - U_inf(x_a),
W^a - W_inf).  Scalars: twoSphere.hat (lambda = 1), dimensional for a = 1:
A by 6 pi, B and G by 4 pi, C and H by 8 pi; 22 and 21 blocks from the
geometric symmetry (spec 9.3) at lambda = 1: X^A, Y^A, X^C, Y^C, Y^H even
(22 = 11, 21 = 12), Y^B, X^G, Y^G odd (22 = -11, 21 = -12).  The axial
rotation decouples exactly (the B, H contractions are normal to d), so X^C
never affects the translational velocities (checked in the tests).

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

# ambient simple shear u = y e_x (gamma_dot = 1)
E_INF = np.array([[0.0, 0.5, 0.0], [0.5, 0.0, 0.0], [0.0, 0.0, 0.0]])
W_INF = np.array([0.0, 0.0, -0.5])

_EPS = np.zeros((3, 3, 3))
_EPS[0, 1, 2] = _EPS[1, 2, 0] = _EPS[2, 0, 1] = 1.0
_EPS[0, 2, 1] = _EPS[2, 1, 0] = _EPS[1, 0, 2] = -1.0
_I = np.eye(3)

# hat name -> dimensional factor (a = 1, lambda = 1)
_FAC = {"A": 6 * PI, "B": 4 * PI, "G": 4 * PI, "C": 8 * PI, "H": 8 * PI}
# parity of the function under relabelling (lambda = 1): 22 = p*11, 21 = p*12
# power of the length scale in each function's dimension (A ~ a, ...)
_LENGTH_POWER = {"A": 1, "B": 2, "G": 2, "C": 3, "H": 3}
_PAR = {"XA": 1, "YA": 1, "YB": -1, "XC": 1, "YC": 1, "XG": -1, "YG": -1,
        "YH": 1}


def scalars(xi, xc=True, lam=LAM):
    """Dimensional resistance scalars (a1 = 1, a2 = lam, eta = 1) at gaps
    xi = 2|r|/(1 + lam) - 2 (array): dict name -> array of shape (2, 2, n),
    [alpha-1, beta-1].  The 22 and 21 blocks are the 11 and 12 functions
    of the relabelled pair (ratio 1/lam, lengths in a2 = lam, d reversed):
    f22 = p lam^k f11^(1/lam), f21 = p lam^k f12^(1/lam), with k = 1 for A,
    2 for B, G, 3 for C, H and p the parity (-1 for B, G; Jeffrey & Onishi
    1984, Jeffrey 1992); at lam = 1 simply 22 = p 11, 21 = p 12.
    xc=False replaces X^C by its isolated-sphere values (8 pi, 0); it does
    not change the translational velocities (axial rotation decouples)."""
    xi = np.atleast_1d(np.asarray(xi, dtype=float))
    out = {}
    for f, p in _PAR.items():
        letter = f[1]

        def pair(ratio):
            if f == "XC" and not xc:
                return np.ones_like(xi), np.zeros_like(xi)
            return (np.atleast_1d(ts.hat(f[0] + "11" + letter, xi, ratio)),
                    np.atleast_1d(ts.hat(f[0] + "12" + letter, xi, ratio)))
        s11, s12 = pair(lam)
        if lam == 1.0:
            s22, s21 = s11, s12
        else:
            s22, s21 = pair(1.0 / lam)
            if f == "XC" and not xc:
                s22 = s22 * lam**3
            else:
                scale = lam ** _LENGTH_POWER[letter]
                s22, s21 = scale * s22, scale * s21
        fac = _FAC[letter]
        out[f] = fac * np.array([[s11, s12], [p * s21, p * s22]])
    return out


def _tensors(d, S, k):
    """Blocks for pair orientation d and scalar set S (index k of the
    arrays).  Returns A, Bt, B, C [a, b, 3, 3] and Gt, Ht [a, b, 3, 3, 3]."""
    dd = np.outer(d, d)
    ed = _EPS @ d                                    # eps_ijk d_k
    A = np.empty((2, 2, 3, 3))
    B = np.empty_like(A)
    C = np.empty_like(A)
    G = np.empty((2, 2, 3, 3, 3))
    H = np.empty_like(G)
    ddd = np.einsum("i,j,k->ijk", d, d, d)
    dI = np.einsum("i,jk->ijk", d, _I)
    for a in range(2):
        for b in range(2):
            g = lambda f: S[f][a, b, k]
            A[a, b] = g("XA") * dd + g("YA") * (_I - dd)
            C[a, b] = g("XC") * dd + g("YC") * (_I - dd)
            B[a, b] = g("YB") * ed
            G[a, b] = (g("XG") * np.einsum("ij,k->ijk", dd - _I / 3.0, d)
                       + g("YG") * (dI + dI.transpose(1, 0, 2) - 2 * ddd))
            # d_i eps_jkm d_m + d_j eps_ikm d_m
            t = np.einsum("i,jk->ijk", d, ed)
            H[a, b] = g("YH") * (t + t.transpose(1, 0, 2))
    # reciprocity: Bt^ab_ij = B^ba_ji ; Gt^ab_ijk = G^ba_jki ; same for H
    Bt = B.transpose(1, 0, 3, 2)
    Gt = np.einsum("bajki->abijk", G)
    Ht = np.einsum("bajki->abijk", H)
    return A, Bt, B, C, Gt, Ht


def grand_resistance(r_vec, E=E_INF, xc=True, S=None, k=0, lam=LAM):
    """(R, b): R (12 x 12) acting on (U1', U2', W1', W2') (velocities minus
    ambient; a1 = 1, a2 = lam) and right-hand side b = (Gt:E, Ht:E) of the
    force- and torque-free equations R x = b."""
    r_vec = np.asarray(r_vec, dtype=float)
    r = float(np.linalg.norm(r_vec))
    d = r_vec / r
    if S is None:
        S = scalars(np.array([2.0 * r / (1.0 + lam) - 2.0]), xc=xc, lam=lam)
        k = 0
    A, Bt, B, C, Gt, Ht = _tensors(d, S, k)
    R = np.zeros((12, 12))
    rhs = np.zeros(12)
    for a in range(2):
        for b in range(2):
            R[3 * a:3 * a + 3, 3 * b:3 * b + 3] = A[a, b]
            R[3 * a:3 * a + 3, 6 + 3 * b:9 + 3 * b] = Bt[a, b]
            R[6 + 3 * a:9 + 3 * a, 3 * b:3 * b + 3] = B[a, b]
            R[6 + 3 * a:9 + 3 * a, 6 + 3 * b:9 + 3 * b] = C[a, b]
            rhs[3 * a:3 * a + 3] += np.einsum("ijk,jk->i", Gt[a, b], E)
            rhs[6 + 3 * a:9 + 3 * a] += np.einsum("ijk,jk->i", Ht[a, b], E)
    return R, rhs


def free_motion(r_vec, E=E_INF, W=W_INF, xc=True, S=None, k=0, lam=LAM,
                loads=None):
    """Velocities of the two spheres (a1 = 1, a2 = lam), x1 = -r/2,
    x2 = +r/2, free or under external loads (F1, F2, T1, T2; 12 values):
    returns U1, U2, W1, W2 (ambient linear flow W x x + E.x)."""
    r_vec = np.asarray(r_vec, dtype=float)
    R, rhs = grand_resistance(r_vec, E, xc, S, k, lam)
    if loads is not None:
        rhs = rhs + loads
    sol = np.linalg.solve(R, rhs)
    x1, x2 = -0.5 * r_vec, 0.5 * r_vec
    U1 = sol[0:3] + np.cross(W, x1) + E @ x1
    U2 = sol[3:6] + np.cross(W, x2) + E @ x2
    return U1, U2, sol[6:9] + W, sol[9:12] + W


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
    Ea = np.outer(d, d) - _I / 3.0
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
    for f, p in _PAR.items():
        letter = f[1]
        if f == "XC":
            v = [1.0, 0.0]
        else:
            v = []
            for ab in ("11", "12"):
                name = f[0] + ab + letter
                g1, g2, g3 = ts.singular(name, LAM)
                v.append(g1 / xi_sq + g2 * L + ts.contact_constant(name, LAM))
        s11, s12 = v[0] * _FAC[letter], v[1] * _FAC[letter]
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
