"""Pressure-driven channel of fdmSuspensionFoam (thesis 1, chapter 6):
case geometry, plane averages of the solver's fields, and the momentum
balances of section 6.4.

Channel from blockMesh: walls normal to y at 0 and L_y, periodic x (flow)
and z, cells numbered i + nx (j + ny k).
"""

import numpy as np

from fdmPost.foamFields import read_internal_field
from fdmPost.particleCase import momentum_balance
from fdmPost.rheology import channel_case


def read_case(case):
    """(particle series, box L, cells n, eta, dP0/dx) of a channel case:
    fdmPost.rheology.channel_case, the cells from the box and the mesh
    spacing, and dP0/dx (kinematic) from the run's momentum balance, whose
    pressure column is -V0 grad P0 (postProcessing/momentumBalance)."""
    cs, L, run = channel_case(case, 0.0)
    n = np.rint(L / run["meshSpacing"]).astype(int)
    G = -momentum_balance(case)["pressure"][-1, 0] / np.prod(L)
    return cs, L, n, cs.eta, G


def layer_means(values, n):
    """Plane (x-z) average per cell layer in y of a cell field."""
    shape = (n[2], n[1], n[0]) + values.shape[1:]
    return values.reshape(shape).mean(axis=(0, 2))


def field(case, name, time, n):
    return read_internal_field(f"{case}/{time:g}/{name}", nCells=n.prod())


def mean_layers(case, name, times, n):
    """Layer means of a field, averaged over the written times."""
    return np.mean([layer_means(field(case, name, t, n), n) for t in times],
                   axis=0)


def fluid_pressure(p, n, L, centres, radii):
    """(1 - phi) <p>^f per cell layer (eq 6.14): p relative to its domain
    mean (thesis 6.4.1), averaged over the cells whose centre lies outside
    every sphere (periodic in x and z)."""
    d = L / n
    c = [(np.arange(k) + 0.5) * dk for k, dk in zip(n, d)]
    Z, Y, X = np.meshgrid(c[2], c[1], c[0], indexing="ij")
    inside = np.zeros(X.shape, bool)
    for x, a in zip(centres, radii):
        dx = [np.abs(C - xc) for C, xc in zip((X, Y, Z), x)]
        dx[0] = np.minimum(dx[0], L[0] - dx[0])
        dx[2] = np.minimum(dx[2], L[2] - dx[2])
        inside |= dx[0]**2 + dx[1]**2 + dx[2]**2 < a * a
    p = p.reshape(X.shape) - p.mean()
    return np.where(inside, 0.0, p).mean(axis=(0, 2))


def shear_rate_bins(U, edges, L_y):
    """Bin means of dU/dy from the layer means U at the cell centres: the
    difference of U at the bin edges over the bin width (U = 0 on the
    walls)."""
    yc = (np.arange(len(U)) + 0.5) * L_y / len(U)
    Ue = np.interp(edges, np.r_[0, yc, L_y], np.r_[0, U, 0])
    return np.diff(Ue) / np.diff(edges)


def shear_stress_line(yb, sxy, L_y, inner):
    """Least-squares line Sigma_xy = level + slope (y - L_y/2) over the
    bins `inner`.  Eq F.6a fixes the slope, dP0/dx; the level is the
    asymmetry of the two walls' stresses, zero only on long averages (the
    zero crossing fluctuates, thesis 6.4.2)."""
    slope, level = np.polyfit(yb[inner] - L_y / 2, sxy[inner], 1)
    return slope, level


def global_balance(case, start_time):
    """Whole-channel x momentum after start_time: the shares of the
    pressure-gradient force carried by the fluid's wall shear and by the
    particles (their lambda, passed to the walls through sub-grid
    lubrication and wall contacts), and the residual |wall + lambda +
    drive|/|drive| (thesis eqs 4.14-4.16)."""
    mb = momentum_balance(case)
    late = mb["time"] >= start_time
    wall, lam, drive = (mb[k][late, 0].mean() for k in
                        ("wall", "lambdaV", "pressure"))
    return -wall / drive, -lam / drive, abs(wall + lam + drive) / abs(drive)
