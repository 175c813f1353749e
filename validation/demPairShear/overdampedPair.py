#!/usr/bin/env python3
"""The pair law of lubricatedDEMFoam for two rigid smooth spheres in simple
shear with Stokes drag, in the overdamped limit (no inertia, g -> infinity):
at each configuration the 12 velocities follow from force and torque
balance, a linear system, and the relative position r = x2 - x1 is
integrated as an ODE (a = eta = gammaDot = 1, u_inf = y e_x).

It is the DEM's law without its time stepping, so it serves two purposes in
this validation: it checks that lubricatedDEMFoam integrates its law (same
minimum gaps and trajectories), and it evaluates variants cheaply -- the
tangential arms (shearArms) and the drag torque of the thesis' two-sphere
script.  That script (YADE examples/Lubrication/shearFlowTwoSpheres.py,
its spin drag) applies the torque -8 pi eta a^3 (2 pi omega - Omega_inf),
the spin multiplied by 2 pi: the spheres then turn at Omega_inf/(2 pi)
instead of with the vorticity.  spin_drag_factor = 2 pi reproduces it.
"""

import numpy as np
from scipy.integrate import solve_ivp

PI = np.pi
W_INF = np.array([0.0, 0.0, -0.5])


def shear_lubrication(u):
    """nu_t(u) of article 1 (eq 4), a = eta = 1."""
    return PI / 2 * (-2 + (2 + u) * np.log((2 + u) / u))


def loads(V, r, cutoff, arms, spin_drag_factor):
    """Forces and torques (F1, T1, F2, T2) on spheres 1 (at -r/2) and 2
    (at +r/2) moving with V = (U1, W1, U2, W2); affine in V."""
    U1, W1, U2, W2 = V[0:3], V[3:6], V[6:9], V[9:12]
    x1, x2 = -r / 2, r / 2
    F1 = -6 * PI * (U1 - np.array([x1[1], 0, 0]))
    F2 = -6 * PI * (U2 - np.array([x2[1], 0, 0]))
    T1 = -8 * PI * (spin_drag_factor * W1 - W_INF)
    T2 = -8 * PI * (spin_drag_factor * W2 - W_INF)
    dist = np.linalg.norm(r)
    n, u = r / dist, dist - 2
    if u < cutoff:
        dv = U2 - U1
        h = 1 + u / 2                       # mid-gap arms
        if arms == "radius":
            vs = 2 / (2 + u) * dv - np.cross(W2, n) - np.cross(W1, n)
        else:
            vs = dv - h * np.cross(W2, n) - h * np.cross(W1, n)
        vs -= (vs @ n) * n
        Fs = shear_lubrication(u) * vs
        Fn = 1.5 * PI * (dv @ n) / u * n
        F1 += Fn + Fs
        F2 -= Fn + Fs
        T1 += h * np.cross(n, Fs)
        T2 += h * np.cross(n, Fs)
        if u <= 1:
            w = W2 - W1
            wn = (w @ n) * n
            Tv = PI * np.log(1 / u) * ((1.5 + 0.126 * u) * (w - wn) + u * wn)
            T1 += Tv
            T2 -= Tv
    return np.concatenate([F1, T1, F2, T2])


def relative_velocity(r, cutoff=4.0, arms="contactPoint",
                      spin_drag_factor=1.0):
    """dr/dt = U2 - U1 at r from force and torque balance."""
    f0 = loads(np.zeros(12), r, cutoff, arms, spin_drag_factor)
    M = np.empty((12, 12))
    for k in range(12):
        e = np.zeros(12)
        e[k] = 1
        M[:, k] = loads(e, r, cutoff, arms, spin_drag_factor) - f0
    V = np.linalg.solve(M, -f0)
    return V[6:9] - V[0:3]


def trajectory(d0, x0=6.0, **law):
    """r(t) from (-x0, d0, 0) until r_x = +x0 (rows: points)."""
    def passed(t, r):
        return r[0] - x0
    passed.terminal = True
    passed.direction = 1
    sol = solve_ivp(lambda t, r: relative_velocity(r, **law), [0, 1e4],
                    [-x0, d0, 0.0], method="LSODA", rtol=1e-10, atol=1e-13,
                    events=passed, max_step=0.05)
    return sol.y.T
