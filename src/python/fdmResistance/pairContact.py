"""Two free rough spheres (a1 = 1, a2 = lam) in unbounded simple shear with
the contact law of libfdmParticles (thesis 1, section 4.1.3, case 2): the
reference for the pair-in-shear-with-contact validation.

Hydrodynamics, two interchangeable pair mobilities:
* ExactPair: the exact two-sphere resistance problem of pairShear
  (twin-multipole functions, 22 and 21 blocks by relabelling), tabulated in
  u = ln(xi) with cubic splines, xi = 2|r|/(1 + lam) - 2; force and torque
  balance with the contact loads f_c (F_c on sphere 1, -F_c on sphere 2):
      R x = b + f_c,  x = (U1 - U_inf(x1), U2 - U_inf(x2), W1 - W_inf,
                           W2 - W_inf);
* FunctionPair: the same motion from eight functions of the gap (FUNCTIONS,
  below), tabulated at a few gaps -- what a solver can measure at frozen
  configurations (validation/pairContactShear).

Contact law (the same as contactLaw.C, written again here from thesis 2.6):
surfaces touch while the gap delta' = |r| - (1 + lam) is below h_r;
overlap delta = h_r - delta';

    F_el = k_n delta^3/2 (1 - exp[10(d - 1)])/(1 - exp[10(d - delta'/h_r)])

(eq 2.57, d = gap floor/h_r, floor 1e-5 (a1 + a2)/2), pushing the spheres
apart; tangential spring F_t = -k_t Y on sphere 1, k_t = (2/7) F_el/delta
(eq 2.60), Y the accumulated slip of sphere 1's contact point against
sphere 2's (kept in the tangent plane), capped at mu F_el (eq 2.63) with Y
truncated to -F_t/k_t while sliding; arms l_i = a_i |r|/(a1 + a2) for the
slip velocity and the torques (eq 2.64).  k_n from the thesis rule
6 pi eta gammaDot a1^2 = k_n (eps h_r)^3/2 (eps the mean deformation).

The state (r, Y) is advanced with Heun's scheme at a fixed small step
(the contact is stiff against the lubrication mobility, and the Coulomb
switch is not smooth), the slip truncated after each stage as in the
solver; halving the steps changes the exit offset by 3e-5.  Conventions
as pairShear: r = x2 - x1, ambient u = y e_x, a1 = eta = gammaDot = 1.

Checks (test_pairContact.py): the eight functions reproduce the full
motion; a smooth pair is fore-aft symmetric; rough pairs from offsets 0.25
and 1 leave on the same streamline (Da Cunha & Hinch 1996).
"""

import math

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq

from . import pairShear as ps

PI = math.pi


class SplinedScalars:
    """The scalars of pairShear.scalars(xi, lam) as cubic splines in ln xi
    (xi = 1e-7 ... 200; relative error < 1e-6 against the direct values)."""

    def __init__(self, lam, n=600):
        self.lam = lam
        u = np.linspace(math.log(1e-7), math.log(200.0), n)
        xi = np.exp(u)
        S = ps.scalars(xi, lam=lam)
        # the 1/xi (squeeze) singularities are splined as xi f
        self.spl = {f: CubicSpline(u, xi * v, axis=-1) for f, v in S.items()}

    def __call__(self, xi):
        u = math.log(xi)
        return {f: (s(u) / xi)[..., None] for f, s in self.spl.items()}


class ContactLaw:
    """Rough Hertz contact with barrier and Coulomb friction (module doc)."""

    def __init__(self, roughness=5e-3, friction=0.5, mean_deformation=0.2,
                 gap_floor=1e-5, lam=1.4):
        self.hr = roughness
        self.mu = friction
        self.kn = 6 * PI / (mean_deformation * roughness) ** 1.5
        self.floor = gap_floor * (1 + lam) / 2

    def normal(self, gap):
        """F_el and delta at surface gap `gap` (0 when apart)."""
        if gap >= self.hr:
            return 0.0, 0.0
        d = self.floor / self.hr
        x = max(gap / self.hr - d, 1e-6)
        delta = self.hr - gap
        return (self.kn * delta**1.5 * (1 - math.exp(10 * (d - 1)))
                / -math.expm1(-10 * x)), delta

    def overlap_under(self, force):
        """The overlap delta at which F_el equals `force` > 0 (eq 2.57
        inverted between the gap floor and h_r): the contact's equilibrium
        under a steady normal load."""
        gap = brentq(lambda g: self.normal(g)[0] - force,
                     self.floor * (1 + 1e-9), self.hr * (1 - 1e-12),
                     xtol=1e-16, rtol=1e-15, maxiter=500)
        return self.hr - gap

    def truncate(self, Y, n, delta):
        """The slip turned into the tangent plane (length kept) and
        truncated to the Coulomb cap: |F_t| = (2/7)(F_el/delta)|Y| <=
        mu F_el means |Y| <= (7/2) mu delta; zero when apart."""
        if delta <= 0:
            return np.zeros(3)
        mag = np.linalg.norm(Y)
        Y = Y - (Y @ n) * n
        tmag = np.linalg.norm(Y)
        if tmag > 0:
            Y *= mag / tmag
        cap = 3.5 * self.mu * delta
        mag = np.linalg.norm(Y)
        return Y * (cap / mag) if mag > cap else Y

    def tangential(self, f_el, delta, Y):
        """F_t on sphere 1 from the (truncated) slip Y."""
        if f_el <= 0 or delta <= 0:
            return np.zeros(3)
        return -(2.0 / 7.0) * f_el / delta * Y


class ExactPair:
    """Pair mobility from the full exact resistance matrices."""

    def __init__(self, lam=1.4, scal=None):
        self.lam = lam
        self.scal = scal or SplinedScalars(lam)

    def motion(self, r_vec, F1, T1, T2):
        """U2 - U1, W1, W2 for loads F1 on sphere 1, -F1 on sphere 2 and
        torques T1, T2, in the ambient shear."""
        xi = 2 * float(np.linalg.norm(r_vec)) / (1 + self.lam) - 2
        U1, U2, W1, W2 = ps.free_motion(
            r_vec, S=self.scal(xi), k=0, lam=self.lam,
            loads=np.concatenate([F1, -F1, T1, T2]))
        return U2 - U1, W1, W2


# The pair's linear response, by symmetry eight functions of the gap:
#   shear     U2 - U1 = W x r + E.r - [A d d + B (I - d d)].E.r
#             W_i = W_inf + c_i d x (E.d)
#   loads     normal pair load f (F1 = -f d): U2 - U1 = m_n f d
#             tangential pair load F_t (F1 = F_t, torques l_i d x F_t):
#             U2 - U1 = -m_t F_t,  W_i = w_i d x F_t
FUNCTIONS = ("A", "B", "c1", "c2", "mn", "mt", "w1", "w2")


PROBES = ("shear45", "shear0", "normal", "tangential")


def probe_set_up(kind, gap, lam):
    """One probe of the eight functions at surface gap `gap`: the branch
    direction d (r = x2 - x1 along d), whether the ambient shear acts, and
    the loads F1 (on sphere 1, -F1 on sphere 2), T1, T2.  A comes from the
    pair at 45 degrees in shear, B and the c_i from the pair along x in
    shear, the load functions from a unit normal and a unit tangential pair
    load (with its torques l_i d x F_t) on the pair along x without shear."""
    dist = gap + 1 + lam
    l1, l2 = dist / (1 + lam), lam * dist / (1 + lam)
    zero = np.zeros(3)
    ex, ey, ez = np.eye(3)
    if kind == "shear45":
        return np.array([1.0, 1.0, 0.0]) / math.sqrt(2), True, zero, zero, zero
    if kind == "shear0":
        return ex, True, zero, zero, zero
    if kind == "normal":
        return ex, False, -ex, zero, zero
    return ex, False, ey, l1 * ez, l2 * ez


def functions_from_probes(gap, lam, probes):
    """The eight functions from the probes' (U2 - U1, W1, W2), a dict
    kind -> motion (the load probes without shear; NaN for the load
    functions when those probes are missing)."""
    dist = gap + 1 + lam
    out = dict.fromkeys(FUNCTIONS, np.nan)
    V, _, _ = probes["shear45"]
    out["A"] = 1 - V @ probe_set_up("shear45", gap, lam)[0] / (dist / 2)
    V, W1, W2 = probes["shear0"]
    out["B"] = 1 - (V[1] + dist / 2) / (dist / 2)
    out["c1"], out["c2"] = 2 * (W1[2] + 0.5), 2 * (W2[2] + 0.5)
    if "normal" in probes:
        out["mn"] = probes["normal"][0][0]
        V, W1, W2 = probes["tangential"]
        out["mt"], out["w1"], out["w2"] = -V[1], W1[2], W2[2]
    return out


def pair_functions(motion, gap, lam):
    """The eight functions at surface gap `gap` from a pair mobility
    `motion(r, F1, T1, T2)`, which always includes the shear: the load
    probes subtract the unloaded motion."""
    dist = gap + 1 + lam
    probes = {}
    for kind in PROBES:
        d, _, F1, T1, T2 = probe_set_up(kind, gap, lam)
        probes[kind] = motion(dist * d, F1, T1, T2)
    sheared = probes["shear0"]
    for kind in ("normal", "tangential"):
        probes[kind] = tuple(a - b for a, b in zip(probes[kind], sheared))
    return functions_from_probes(gap, lam, probes)


class FunctionPair:
    """Pair mobility from the eight functions tabulated at some gaps,
    interpolated linearly in ln(gap) (m_n as m_n/gap, the squeeze)."""

    def __init__(self, gaps, values, lam=1.4):
        """values: dict function -> array over gaps (NaN where not
        measured: the remaining points are used)."""
        self.lam = lam
        self.table = {}
        for f in FUNCTIONS:
            v = np.asarray(values[f], float)
            g = np.asarray(gaps, float)
            ok = np.isfinite(v)
            if f == "mn":
                v = v / g
            self.table[f] = (np.log(g[ok]), v[ok])

    def value(self, f, gap):
        u, v = self.table[f]
        x = np.interp(math.log(gap), u, v)
        return x * gap if f == "mn" else x

    def motion(self, r_vec, F1, T1, T2):
        dist = float(np.linalg.norm(r_vec))
        d = r_vec / dist
        gap = dist - (1 + self.lam)
        f = {k: self.value(k, gap) for k in FUNCTIONS}
        V = ps.bg_velocity(r_vec, f["A"], f["B"])
        spin = np.cross(d, ps.E_INF @ d)
        W1 = ps.W_INF + f["c1"] * spin
        W2 = ps.W_INF + f["c2"] * spin
        # the contact loads: F1 = -f_n d + F_t with the torques l_i d x F_t
        fn = -(F1 @ d)
        Ft = F1 + fn * d
        V = V + f["mn"] * fn * d - f["mt"] * Ft
        W1 = W1 + f["w1"] * np.cross(d, Ft)
        W2 = W2 + f["w2"] * np.cross(d, Ft)
        return V, W1, W2


def _velocities(r_vec, Y, pair, law):
    """U2 - U1, the slip velocity of 1's contact point against 2's, the
    (truncated) slip and F_el at configuration r_vec with slip Y."""
    lam = pair.lam
    dist = float(np.linalg.norm(r_vec))
    n = r_vec / dist
    f_el, delta = law.normal(dist - (1 + lam))
    Y = law.truncate(Y, n, delta)
    Ft = law.tangential(f_el, delta, Y)
    l1, l2 = dist / (1 + lam), lam * dist / (1 + lam)
    V, W1, W2 = pair.motion(r_vec, -f_el * n + Ft, l1 * np.cross(n, Ft),
                            l2 * np.cross(n, Ft))
    slip = -V - l1 * np.cross(n, W1) - l2 * np.cross(n, W2)
    return V, slip - (slip @ n) * n, Y, f_el


def trajectory(x0, y0, pair, law=None, dt=2e-3, dt_contact=2e-4,
               max_time=500.0):
    """Relative trajectory from r = (x0, y0, 0) (x0 < 0) until r_x = -x0,
    Heun's scheme (second order) with the slip advanced by the same average
    and truncated (return mapping) after each stage, as the solver does;
    the step drops to dt_contact within 0.5 h_r of contact.  `pair` gives
    the mobility (ExactPair or FunctionPair).  Returns a dict with t,
    r (N x 3), gap (N) and the elastic contact force F_el (N)."""
    law = law or ContactLaw(lam=pair.lam)
    r = np.array([x0, y0, 0.0])
    Y = np.zeros(3)
    t = 0.0
    out = {"t": [], "r": [], "gap": [], "contactForce": []}
    while r[0] < -x0 and t < max_time:
        V, vs, Y, f_el = _velocities(r, Y, pair, law)
        gap = np.linalg.norm(r) - (1 + pair.lam)
        for k, v in zip(out, (t, r.copy(), gap, f_el)):
            out[k].append(v)
        h = dt_contact if gap < 1.5 * law.hr else dt
        V2, vs2, _, _ = _velocities(r + h * V, Y + h * vs, pair, law)
        r = r + 0.5 * h * (V + V2)
        Y = Y + 0.5 * h * (vs + vs2)
        t += h
    return {k: np.array(v) for k, v in out.items()}
