"""The grand resistance problem of two spheres in a linear ambient flow.

The 12 x 12 resistance problem is solved directly.  With Kim & Karrila
(1991) / Jeffrey & Onishi (1984) / Jeffrey (1992) conventions (thesis 1,
appendix A):

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
geometric symmetry (thesis 1, appendix A) at lambda = 1: X^A, Y^A, X^C, Y^C,
Y^H even (22 = 11, 21 = 12), Y^B, X^G, Y^G odd (22 = -11, 21 = -12).  The
axial rotation decouples exactly (the B, H contractions are normal to d), so
X^C never affects the translational velocities (checked in the tests).
"""

import math

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
FACTOR = {"A": 6 * PI, "B": 4 * PI, "G": 4 * PI, "C": 8 * PI, "H": 8 * PI}
# parity of the function under relabelling (lambda = 1): 22 = p*11, 21 = p*12
# power of the length scale in each function's dimension (A ~ a, ...)
_LENGTH_POWER = {"A": 1, "B": 2, "G": 2, "C": 3, "H": 3}
PARITY = {"XA": 1, "YA": 1, "YB": -1, "XC": 1, "YC": 1, "XG": -1, "YG": -1,
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
    for f, p in PARITY.items():
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
        fac = FACTOR[letter]
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
