"""Three (or more) equal spheres in Stokes flow: the clusters of thesis 1,
sections 4.1.5-4.1.6, and their reference velocities.

cluster         sphere centres of the triangle / aligned / L configurations
grand_mobility  far-field (Rotne-Prager level) force-torque-stresslet
                mobility of unit spheres
velocities      Stokesian dynamics with the exact two-sphere functions:
                velocities of spheres under forces in a linear flow
"""

import functools
import math

import numpy as np


def cluster(kind, s):
    """Centres (3 x 3, radius 1) of a three-sphere cluster.
    'triangle': equilateral triangle of side s in the x-y plane, centroid at
    the origin, sphere 0 at (-s/sqrt3, 0, 0) so that +x points from it to
    the centroid.  'aligned': spheres on the line d = (cos 30, -sin 30, 0)
    (compressional quadrant of u = y e_x), spacing s, sphere 1 (B) at the
    origin.  'L': B at the origin, A at -s e_x, C at +s e_y."""
    if kind == "triangle":
        R = s / math.sqrt(3.0)
        return np.array([[-R, 0.0, 0.0], [R / 2, s / 2, 0.0],
                         [R / 2, -s / 2, 0.0]])
    if kind == "aligned":
        d = np.array([math.cos(math.radians(30)), -math.sin(math.radians(30)),
                      0.0])
        return np.array([-s * d, 0.0 * d, s * d])
    if kind == "L":
        return np.array([[-s, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, s, 0.0]])
    raise ValueError("unknown cluster '%s' (triangle, aligned, L)" % kind)


# --------------------------------------------------------------------------
# Far-field grand mobility (Rotne-Prager level, force-torque-stresslet)
# --------------------------------------------------------------------------
# Orthonormal basis of symmetric traceless tensors (B_k : B_l = delta_kl):
# a stresslet or strain rate is stored as its 5 coefficients X : B_k.
_S2, _S6 = math.sqrt(2.0), math.sqrt(6.0)
BASIS = np.array([
    [[1, 0, 0], [0, -1, 0], [0, 0, 0]],
    [[1, 0, 0], [0, 1, 0], [0, 0, -2]],
    [[0, 1, 0], [1, 0, 0], [0, 0, 0]],
    [[0, 0, 1], [0, 0, 0], [1, 0, 0]],
    [[0, 0, 0], [0, 0, 1], [0, 1, 0]]], float) / np.array(
        [_S2, _S6, _S2, _S2, _S2])[:, None, None]


@functools.lru_cache(maxsize=None)
def _coupling_function():
    """Derive (sympy) the 11 x 11 far-field coupling block between two unit
    spheres (eta = 1) whose centres differ by (x, y, z): velocity, angular
    velocity and strain rate (5 coefficients) at the receiving sphere
    (Faxen laws: U = (1 + lap/6) u, Omega = curl u / 2, E = (1 + lap/10)
    sym grad u) caused by a force, torque and stresslet (5 coefficients)
    exerted on the fluid by the sending sphere, whose disturbance is
    (1 + lap/6) Stokeslet + rotlet + (1 + lap/10) stresslet (the exact
    fields of an isolated translating, rotating or strained rigid sphere),
    so the block is the Rotne-Prager / Stokesian-dynamics far field
    (Durlofsky, Brady & Bossis 1987).  test_threeSphere checks it against
    the exact two-sphere functions (the deviation falls as r^-6 and r^-7).
    Derived once per process (about 15 s).  Returns a numpy function
    f(x, y, z) -> 11 x 11 array."""
    import sympy as sp
    X = sp.symbols("x y z", real=True)
    r = sp.Symbol("r", positive=True)       # |x|, differentiated by hand:
    # d/dx_i = partial_i + (x_i / r) partial_r keeps every expression a
    # polynomial in x, y, z and 1/r (sqrt(x^2 + ...) swells by orders of
    # magnitude under nested derivatives)

    def d(f, i):
        return sp.expand(sp.diff(f, X[i]) + X[i] / r * sp.diff(f, r))

    def lap(f):
        return sum(d(d(f, c), c) for c in range(3))

    def stokeslet(j):
        return [(sp.KroneckerDelta(i, j) / r + X[i] * X[j] / r**3)
                / (8 * sp.pi) for i in range(3)]

    def rotlet(j):
        e = [0, 0, 0]
        e[j] = 1
        L = sp.Matrix(e)
        return list(L.cross(sp.Matrix(X)) / (8 * sp.pi * r**3))

    def stresslet(k):
        B = sp.Matrix(BASIS[k].tolist()).applyfunc(sp.nsimplify)
        xv = sp.Matrix(X)
        q = (xv.T * B * xv)[0]
        return [3 * X[i] * q / (8 * sp.pi * r**5) for i in range(3)]

    fields = [[f + lap(f) / 6 for f in stokeslet(j)] for j in range(3)]
    fields += [rotlet(j) for j in range(3)]
    fields += [[f + lap(f) / 10 for f in stresslet(k)] for k in range(5)]
    Bs = [sp.Matrix(BASIS[k].tolist()).applyfunc(sp.nsimplify)
          for k in range(5)]
    rows = []
    for u in fields:                       # one column per input
        U = [ui + lap(ui) / 6 for ui in u]
        W = [(d(u[(i + 2) % 3], (i + 1) % 3)
              - d(u[(i + 1) % 3], (i + 2) % 3)) / 2 for i in range(3)]
        G = sp.Matrix(3, 3, lambda i, j: d(u[i], j))
        E = (G + G.T) / 2
        E = E + E.applyfunc(lap) / 10
        e = [sum(E[i, j] * Bs[k][i, j] for i in range(3) for j in range(3))
             for k in range(5)]
        rows.append(U + W + e)
    M = sp.Matrix(rows).T                  # outputs x inputs
    f = sp.lambdify(X + (r,), M, "numpy", cse=True)
    return lambda x, y, z: np.array(f(x, y, z, math.sqrt(x * x + y * y
                                                         + z * z)), float)


def _coupling(dx):
    return _coupling_function()(*dx)


SELF = np.diag([1 / (6 * math.pi)] * 3 + [1 / (8 * math.pi)] * 3
               + [3 / (20 * math.pi)] * 5)


def grand_mobility(x):
    """Far-field grand mobility (11N x 11N) of unit spheres at centres x:
    per sphere (U - U_inf, Omega - Omega_inf, -E_inf) = M (F, T, S), with
    F, T, S exerted on the fluid (eta = 1)."""
    n = len(x)
    M = np.zeros((11 * n, 11 * n))
    for a in range(n):
        M[11 * a:11 * a + 11, 11 * a:11 * a + 11] = SELF
        for b in range(n):
            if a != b:
                M[11 * a:11 * a + 11, 11 * b:11 * b + 11] = _coupling(
                    np.asarray(x[a], float) - np.asarray(x[b], float))
    return M


# --------------------------------------------------------------------------
# Stokesian dynamics with exact pairs: the reference velocities
# --------------------------------------------------------------------------
def _strain_coefficients(E):
    return np.einsum("kij,ij->k", BASIS, E)


def _isolated_mobility(x):
    """Grand mobility of spheres that do not see each other."""
    return np.kron(np.eye(len(x)), SELF)


def _resistance(M, E):
    """Force and torque rows of the inverse of a grand mobility M (11N x
    11N): R_FU (6N x 6N, on (U, W) per sphere minus ambient) and the forces
    and torques (6N) the ambient strain E induces."""
    n = len(M) // 11
    R = np.linalg.inv(M)
    fu = [11 * p + i for p in range(n) for i in range(6)]
    s = [11 * p + 6 + i for p in range(n) for i in range(5)]
    e = np.tile(_strain_coefficients(E), n)
    return R[np.ix_(fu, fu)], R[np.ix_(fu, s)] @ e


def _far_pair(xa, xb, E, far=grand_mobility):
    """Far-field two-sphere resistance, layout of _resistance."""
    return _resistance(far([xa, xb]), E)


# pairShear orders (U_a, U_b, W_a, W_b); here (U_a, W_a, U_b, W_b)
_PAIR_ORDER = [0, 1, 2, 6, 7, 8, 3, 4, 5, 9, 10, 11]


def _exact_pair(xa, xb, E):
    """Exact two-sphere resistance (fdmResistance.pairShear), same layout
    as _far_pair."""
    from .pairShear import grand_resistance
    R, rhs = grand_resistance(np.asarray(xb, float) - np.asarray(xa, float),
                              E=E)
    o = _PAIR_ORDER
    return R[np.ix_(o, o)], rhs[o]


def velocities(x, E=None, W=None, forces=None, torques=None,
               many_body=True):
    """Velocities and angular velocities (N x 3 each) of N unit spheres at
    centres x (eta = 1) in the ambient flow u = W x x + E.x, under external
    forces and torques (N x 3, default zero: free spheres).

    Stokesian dynamics (Durlofsky, Brady & Bossis 1987) with the exact
    two-sphere functions: R = M_inf^-1 + sum over pairs (R_2,exact -
    R_2,far), M_inf the force-torque-stresslet far-field grand mobility.
    Exact for one and two spheres; for three, the many-body part is that of
    the far field (reflections to O(r^-3)), the pair part exact at every
    gap.  many_body=False drops the far-field many-body part: pairwise-
    additive resistance, R = isolated spheres + sum over pairs (R_2,exact -
    isolated); the difference of the two shows how much the many-body
    interaction weighs in a configuration."""
    x = np.asarray(x, float)
    n = len(x)
    E = np.zeros((3, 3)) if E is None else np.asarray(E, float)
    W = np.zeros(3) if W is None else np.asarray(W, float)
    far = grand_mobility if many_body else _isolated_mobility
    R, b = _resistance(far(x), E)
    for a in range(n):
        for c in range(a + 1, n):
            Re, fe = _exact_pair(x[a], x[c], E)
            Rf, ff = _far_pair(x[a], x[c], E, far)
            idx = list(range(6 * a, 6 * a + 6)) + list(range(6 * c,
                                                              6 * c + 6))
            R[np.ix_(idx, idx)] += Re - Rf
            b[idx] += fe - ff
    ext = np.zeros((n, 6))
    if forces is not None:
        ext[:, :3] = forces
    if torques is not None:
        ext[:, 3:] = torques
    v = np.linalg.solve(R, b + ext.ravel()).reshape(n, 6)
    U = v[:, :3] + np.cross(W, x) + x @ E.T
    return U, v[:, 3:] + W
