#!/usr/bin/python3
"""Pressure-driven suspension post-processing (thesis 1, chapter 6):
migration of phi(y) over time windows (eqs 2.70, 6.5) against the
suspension balance model (appendix F, transient eq F.8b and steady
eqs F.10-F.11), blunting of the velocity profile, and the momentum balance
of section 6.4 (shear stress against the pressure gradient, eq F.6a, and
the uniformity of Sigma_yy); writes poiseuille.png.

    plotPoiseuille.py [case] [--windows 4] [--phij 0.592]

Reads postProcessing/particles.h5 (every record), the reconstructed U and
p of the written times, postProcessing/momentumBalance, the box and mesh
from system/blockMeshDict, dP0/dx from constant/flowProperties and
eta = rho nu from constant/transportProperties.  Lengths in a1, time in
t* = gammaDot_0 t with gammaDot_0 = L_y |dP0/dx|/(4 eta) (eq 6.2).
"""

import argparse
import glob
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost import channelFlow as cf  # noqa: E402
from fdmPost import suspensionBalance as sbm  # noqa: E402


def bin_mean(profile_y, y, edges):
    """Mean of a tabulated profile over each bin (fine trapezoid); NaN for
    empty bins."""
    out = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        s = np.linspace(lo, hi, 41)
        out.append(np.trapz(np.interp(s, y, profile_y), s) / (hi - lo)
                   if hi > lo else np.nan)
    return np.array(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("case", nargs="?", default=".")
    ap.add_argument("--windows", type=int, default=4,
                    help="time windows of the phi(y) profiles")
    ap.add_argument("--phij", type=float, default=0.592,
                    help="jamming fraction of the SBM (thesis 1: 0.592)")
    ap.add_argument("--layer", type=float, default=2.0,
                    help="wall layers left out of the SBM, in a1 (thesis:"
                         " about 2.5)")
    args = ap.parse_args()
    case = args.case

    cs, L, n, eta, G = cf.read_case(case)
    Ly = L[1]
    gamma0 = Ly * abs(G) / (4 * eta)
    t = cs.t * gamma0
    if len(t) < 2 * args.windows:
        sys.exit(f"plotPoiseuille: {len(t)} records in particles.h5, too few"
                 f" for {args.windows} windows")
    nb = int(round(Ly))                       # a1-wide bins (eq 6.5)
    edges = np.linspace(0, Ly, nb + 1)
    yb = 0.5 * (edges[1:] + edges[:-1])
    phi0 = (4 / 3 * np.pi * cs.a**3).sum() / L.prod()
    bounds = np.linspace(t[0], t[-1], args.windows + 1)
    windows = [np.nonzero((t >= lo) & (t <= hi))[0]
               for lo, hi in zip(bounds[:-1], bounds[1:])]

    # Migration in the core, the SBM's domain (thesis 6.3.2: the wall
    # layers, where particles order against the wall, are left out and the
    # core's own mean enters): eq F.8b from the packing's core phi, zero
    # flux at the core's edges, averaged over the same windows and bins
    layer = args.layer
    core = (yb > layer) & (yb < Ly - layer)
    centre = np.abs(yb - Ly / 2) < 1.0
    outer = core & ~centre
    wall = ~core
    _, phi_start, _ = cs.profiles(nb, [0])
    phi_core = phi_start[core].mean()
    y_edge = (Ly / 2 - layer) / Ly
    eta_s, sigma22 = sbm.morris_boulay_poiseuille(args.phij)
    samples = [np.linspace(lo, hi, 5)[1:] for lo, hi in
               zip(bounds[:-1], bounds[1:])]
    ys, model = sbm.poiseuille_transient(
        sigma22, phi_core, Ly, args.phij,
        sorted({float(s) for w in samples for s in w}), y_max=y_edge)
    print(f"Plane Poiseuille suspension: {len(cs.a)} particles, phi0"
          f" {phi0:.3f} (core {phi_core:.3f}, wall layers {layer:g} a1),"
          f" box {L.tolist()} a1, t* = {t[-1]:.2f} (gammaDot_0 = {gamma0:g}),"
          f" migration time (9/8)(L_y/a_bar)^2 = {9 / 8 * (Ly / 1.2)**2:.0f}")
    print("  window t*      phi centre (2 a1)   phi outer core    phi wall"
          " layers   [SBM eq F.8b, Morris-Boulay, phi_J %g]" % args.phij)
    fine = np.linspace(layer, Ly - layer, 601)
    phis, sbms = [], []
    for (lo, hi), steps, times in zip(zip(bounds[:-1], bounds[1:]), windows,
                                      samples):
        _, phi, _ = cs.profiles(nb, steps)
        m = np.mean([np.interp(np.abs(fine - Ly / 2) / Ly, ys,
                               model[float(s)]) for s in times], axis=0)
        m = np.where(core, bin_mean(m, fine, np.clip(edges, layer,
                                                       Ly - layer)), np.nan)
        phis.append(phi)
        sbms.append(m)
        print(f"  {lo:5.2f}-{hi:5.2f}   {phi[centre].mean():.3f}"
              f" [{m[centre].mean():.3f}]     {phi[outer].mean():.3f}"
              f" [{m[outer].mean():.3f}]    {phi[wall].mean():.3f}")
    change = [(phis[-1][k].mean() - phi_start[k].mean(),
               sbms[-1][k].mean() - phi_core) for k in (centre, outer)]
    print(f"  change from the packing to the last window: centre"
          f" {change[0][0]:+.3f} (SBM {change[0][1]:+.3f}), outer core"
          f" {change[1][0]:+.3f} (SBM {change[1][1]:+.3f})")

    # Velocity profile and stresses over the last window, from the written
    # (reconstructed) times inside it
    last = windows[-1]
    written = sorted(float(os.path.basename(os.path.dirname(f))) for f in
                     glob.glob(f"{case}/*/U") if os.path.basename(
                         os.path.dirname(f)) not in ("0",))
    written = [w for w in written if w * gamma0 >= bounds[-2] - 1e-9]
    if not written:
        sys.exit("plotPoiseuille: no reconstructed U in the last window"
                 " (run reconstructPar -fields '(U p)')")
    yc = (np.arange(n[1]) + 0.5) * L[1] / n[1]
    U = np.mean([cf.layer_means(cf.field(case, "U", w, n), n)[:, 0]
                 for w in written], axis=0)
    fluid_xy = eta * cf.shear_rate_bins(U, edges, Ly)
    hp, c = cs.stress_profiles(nb, last)
    sxy = fluid_xy + hp[:, 0, 1] + c[:, 0, 1]
    inner = (yb > 1) & (yb < Ly - 1)
    slope, level = cf.shear_stress_line(yb, sxy, Ly, inner)
    theory = G * (yb - Ly / 2) + level
    scale = abs(G) * Ly / 2                   # wall shear stress
    dev = np.abs(sxy - theory) / scale
    print(f"  shear stress balance (last window, {len(written)} fields, bins"
          f" 1 a1 from the walls): slope dSigma_xy/dy {slope:.4f} against"
          f" dP0/dx {G:g} ({(slope - G) / abs(G):+.1%}); level (wall"
          f" asymmetry) {level / scale:+.1%} of the wall stress; largest"
          f" deviation from the line {dev[inner].max():.1%} (next to the"
          f" walls {dev[~inner].max():.1%})")

    records = [int(np.argmin(np.abs(cs.t - w))) for w in written]
    pf = np.mean([cf.fluid_pressure(cf.field(case, "p", w, n), n, L, cs.x[k],
                                     cs.a) for w, k in zip(written, records)],
                 axis=0)
    pf_b = bin_mean(pf, yc, edges)
    syy = -pf_b + hp[:, 1, 1] + c[:, 1, 1]
    print(f"  Sigma_yy (eq 6.13) across the channel: mean {syy.mean():.3f},"
          f" spread (max - min) {np.ptp(syy):.3f}, of which contact"
          f" {np.ptp(c[:, 1, 1]):.3f}, particle hydrodynamic"
          f" {np.ptp(hp[:, 1, 1]):.3f}")

    # Whole channel: the pressure-gradient force goes to the walls through
    # the fluid's wall shear and, through the particles' lambda, through
    # their sub-grid lubrication and contacts with the walls
    fluid, particles, residual = cf.global_balance(case, bounds[-2] / gamma0)
    print(f"  global x balance: fluid wall shear {fluid:.1%} and particles"
          f" {particles:.1%} of the pressure-gradient force, residual"
          f" {residual:.1e}")

    # Blunting: centre velocity over the mean, 1.5 for the parabola
    newtonian = abs(G) / (2 * eta) * yc * (Ly - yc)
    blunt = U.max() / U.mean()
    _, _, up_last = cs.profiles(nb, last)
    # Eq F.8a with the measured phi(y) of the last window (mirror-averaged,
    # a1 bins) and the Morris-Boulay viscosity: the local-rheology velocity
    y_half = np.linspace(0, 0.5, 501)
    phi_sym = 0.5 * (phis[-1] + phis[-1][::-1])
    phi_half = phi_sym[np.minimum((Ly / 2 + y_half * Ly).astype(int), nb - 1)]
    u_sbm = sbm.poiseuille_velocity(y_half, phi_half, eta_s) * gamma0 * Ly
    print(f"  velocity (last window): centre/mean {blunt:.3f} (parabola 1.5),"
          f" mean {U.mean():.4f} (particle-free {newtonian.mean():.4f};"
          f" eq F.8a with the measured phi(y): centre/mean"
          f" {u_sbm[0] / np.trapz(u_sbm, y_half) * 0.5:.3f}, mean"
          f" {np.trapz(u_sbm, y_half) / 0.5:.4f})")

    fig, ax = plt.subplots(1, 4, figsize=(17, 4.2))
    for (lo, hi), phi in zip(zip(bounds[:-1], bounds[1:]), phis):
        ax[0].plot(phi, yb, "o-", ms=3, label=f"t* {lo:.1f}-{hi:.1f}")
    ax[0].plot(sbms[0], yb, "--", color="0.5", label="SBM eq F.8b, first window")
    ax[0].plot(sbms[-1], yb, "k--", label="SBM eq F.8b, last window")
    yst, ps, _ = sbm.poiseuille_profile(sigma22, phi_core, args.phij,
                                        y_max=y_edge)
    ax[0].plot(ps, Ly / 2 + yst * Ly, "k:", lw=0.8, label="SBM steady")
    ax[0].plot(ps, Ly / 2 - yst * Ly, "k:", lw=0.8)
    ax[0].axvline(phi_core, color="0.6", lw=0.6)
    ax[0].axhspan(0, layer, color="0.93")
    ax[0].axhspan(Ly - layer, Ly, color="0.93")
    ax[0].set(xlabel=r"$\phi$ (a$_1$ bins, eq 6.5)", ylabel=r"$y/a_1$",
              title="migration")
    ax[0].legend(fontsize=7)
    ax[1].plot(U, yc, "-", label="suspension (solver U)")
    ax[1].plot(up_last, yb, "o", ms=4, mfc="none", label="particles (eq 6.4)")
    ax[1].plot(newtonian, yc, "k--", lw=0.8, label="particle-free parabola")
    ax[1].plot(u_sbm, Ly / 2 + y_half * Ly, "k:", lw=0.8,
               label=r"eq F.8a, measured $\phi(y)$, Morris-Boulay")
    ax[1].plot(u_sbm, Ly / 2 - y_half * Ly, "k:", lw=0.8)
    ax[1].set(xlabel=r"$u_x$", title=f"velocity, t* > {bounds[-2]:.1f}")
    ax[1].legend(fontsize=7)
    ax[2].plot(sxy, yb, "o-", label=r"$\Sigma_{xy}$ total")
    ax[2].plot(c[:, 0, 1], yb, "s", ms=3, label="contact")
    ax[2].plot(hp[:, 0, 1], yb, "^", ms=3, label="particle hydrodynamic")
    ax[2].plot(fluid_xy, yb, "v", ms=3, label=r"$\eta\,dU/dy$")
    ax[2].plot(theory, yb, "k--", lw=0.8,
               label=r"$dP_0/dx\,(y - L_y/2)$ + fitted level")
    ax[2].set(xlabel="shear stress", title="x-momentum balance (F.6a)")
    ax[2].legend(fontsize=7)
    ax[3].plot(syy, yb, "o-", label=r"$\Sigma_{yy}$ total (eq 6.13)")
    ax[3].plot(c[:, 1, 1], yb, "s", ms=3, label="contact")
    ax[3].plot(hp[:, 1, 1], yb, "^", ms=3, label="particle hydrodynamic")
    ax[3].plot(-pf_b, yb, "v", ms=3, label=r"$-(1-\phi)\langle p\rangle^f$")
    ax[3].set(xlabel="normal stress", title="y-momentum balance")
    ax[3].legend(fontsize=7)
    fig.tight_layout()
    out = os.path.join(case, "poiseuille.png")
    fig.savefig(out, dpi=110)
    print(f"  wrote {out}")


if __name__ == "__main__":
    main()
