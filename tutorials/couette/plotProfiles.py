#!/usr/bin/env python3
"""Couette tutorial post-processing: velocity profile u_x(y) against the
analytic linear profile, relative viscosity from the wall shear stress, and
a PNG plot (profiles.png).  Reads the latest reconstructed time.

Particle-free for now: the relative viscosity must be 1 (pure fluid).
"""

import os
import re
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from fdmPost.foamFields import read_internal_field


def latest_time(case):
    times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d) and d != "0"]
    return max(times, key=float)


def wall_velocity(case, patch):
    text = open(f"{case}/0/U").read()
    block = text[text.index(patch):]
    return float(re.search(r"uniform\s*\(\s*(\S+)", block).group(1))


def main(case="."):
    t = latest_time(case)
    U = read_internal_field(f"{case}/{t}/U")
    C = read_internal_field(f"{case}/{t}/C")
    nu = float(re.search(r"^nu\s+([^;\s]+)", open(f"{case}/constant/transportProperties").read(), re.M).group(1))
    y = C[:, 1]
    H = y.max() + y.min()                  # walls at 0 and H, centres Delta/2 inside
    delta = 2 * y.min()
    uBottom, uTop = wall_velocity(case, "bottomWall"), wall_velocity(case, "topWall")
    shearRate = (uTop - uBottom) / H

    yBins = np.unique(np.round(y, 12))
    uMean = np.array([U[np.isclose(y, yb), 0].mean() for yb in yBins])
    exact = uBottom + shearRate * yBins
    err = np.abs(uMean - exact).max() / np.abs(exact).max()

    # Wall shear stress from the wall-adjacent cells (two-point gradient)
    tauBottom = nu * (uMean[0] - uBottom) / (delta / 2)
    tauTop = nu * (uTop - uMean[-1]) / (delta / 2)
    etaRel = 0.5 * (tauBottom + tauTop) / (nu * shearRate)

    print(f"Couette tutorial, time {t}: shear rate {shearRate:g} 1/s")
    print(f"  velocity profile: relative L-inf error vs analytic {err:.3e}")
    print(f"  relative viscosity (wall shear stress / (eta gamma_dot)) {etaRel:.6f}")

    fig, ax = plt.subplots(figsize=(4.5, 4))
    ax.plot(exact, yBins, "k-", label="analytic")
    ax.plot(uMean, yBins, "o", ms=3, mfc="none", label="fdmSuspensionFoam")
    ax.set_xlabel(r"$u_x$")
    ax.set_ylabel(r"$y$")
    ax.set_title(f"plane Couette, rel. error {err:.1e}")
    ax.legend()
    fig.tight_layout()
    fig.savefig(f"{case}/profiles.png", dpi=120)
    print(f"  wrote {case}/profiles.png")


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
