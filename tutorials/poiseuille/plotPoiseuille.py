#!/usr/bin/python3
"""Pressure-driven suspension post-processing (thesis 1, chapter 6):
migration of phi(y) over time windows (eqs 2.70, 6.5) against the
suspension balance model (appendix F, transient eq F.8b and steady
eqs F.10-F.11), blunting of the velocity profile, and the momentum balance
of section 6.4 (shear stress against the pressure gradient, eq F.6a, and
the uniformity of Sigma_yy); writes poiseuille.png.

    plotPoiseuille.py [case] [--windows 4] [--layer 2] [--phij 0.592]
                      [--closure SWEEPFIT]

The SBM's closures: Morris & Boulay with phi_m = --phij, or with
--closure the fit to a Couette sweep (the sweepFit.json that
tutorials/couette/thesisSweep/plotSweep.py writes: eq 4.12 and
hat Sigma^c_22 = beta (phi/phi_J)^n, fdmPost.suspensionBalance
.sweep_poiseuille) with its own phi_J.

Reads postProcessing/particles.h5 (every record; the box, mesh spacing and
viscosity from its attributes), the reconstructed U and p of the written
times and postProcessing/momentumBalance (dP0/dx from its -V0 grad P0).
Lengths in a1, time in t* = gammaDot_0 t with gammaDot_0 =
L_y |dP0/dx|/(4 eta) (eq 6.2).
"""

import argparse
import collections
import glob
import json
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


class Run:
    """A finished channel run: particle series, geometry, a1 bins (eq 6.5),
    time windows in t*, and the reconstructed fields of the last one."""

    def __init__(self, case, windows):
        self.case = case
        self.cs, self.L, self.n, self.eta, self.G = cf.read_case(case)
        self.Ly = self.L[1]
        self.gamma0 = self.Ly * abs(self.G) / (4 * self.eta)   # eq 6.2
        t = self.cs.t * self.gamma0
        if len(t) < 2 * windows:
            sys.exit(f"plotPoiseuille: {len(t)} records in particles.h5, too"
                     f" few for {windows} windows")
        self.nb = int(round(self.Ly))
        self.edges = np.linspace(0, self.Ly, self.nb + 1)
        self.yb = 0.5 * (self.edges[1:] + self.edges[:-1])
        self.yc = (np.arange(self.n[1]) + 0.5) * self.Ly / self.n[1]
        self.bounds = np.linspace(t[0], t[-1], windows + 1)
        self.windows = [np.nonzero((t >= lo) & (t <= hi))[0] for lo, hi in
                        zip(self.bounds[:-1], self.bounds[1:])]
        self.t_end = t[-1]
        times = [os.path.basename(os.path.dirname(f))
                 for f in glob.glob(f"{case}/*/U")]
        self.written = sorted(float(w) for w in times if w != "0"
                              and float(w) * self.gamma0
                              >= self.bounds[-2] - 1e-9)
        if not self.written:
            sys.exit("plotPoiseuille: no reconstructed U in the last window"
                     " (run reconstructPar -fields '(U p)')")

    def phi0(self):
        return (4 / 3 * np.pi * self.cs.a**3).sum() / self.L.prod()


# The suspension balance model's closures: a name, phi_J, the relative
# shear viscosity eta_s(phi) and hat Sigma^c_22(phi)
Closure = collections.namedtuple("Closure", "name phij eta_s sigma22")


def closure(path, phij):
    """Morris & Boulay at phi_m = phij, or the sweep fit in path."""
    if path is None:
        return Closure("Morris-Boulay", phij,
                       *sbm.morris_boulay_poiseuille(phij))
    with open(path) as f:
        fit = json.load(f)
    return Closure("Couette sweep fit", fit["phiJ"],
                   *sbm.sweep_poiseuille(fit))


def migration(run, layer, model, ax):
    """phi(y) per window against eq F.8b in the core, the SBM's domain
    (thesis 6.3.2: the wall layers, where particles order against the wall,
    are left out and the core's own mean enters): from the packing's core
    phi, zero flux at the core's edges, averaged over the same windows and
    bins.  Returns the last window's phi(y)."""
    cs, yb, Ly, nb = run.cs, run.yb, run.Ly, run.nb
    core = (yb > layer) & (yb < Ly - layer)
    centre = np.abs(yb - Ly / 2) < 1.0
    outer = core & ~centre
    _, phi_start, _ = cs.profiles(nb, [0])
    phi_core = phi_start[core].mean()
    y_edge = (Ly / 2 - layer) / Ly
    phij, sigma22 = model.phij, model.sigma22
    bounds = list(zip(run.bounds[:-1], run.bounds[1:]))
    samples = [np.linspace(lo, hi, 5)[1:] for lo, hi in bounds]
    ys, transient = sbm.poiseuille_transient(
        sigma22, phi_core, Ly, phij,
        sorted({float(s) for w in samples for s in w}), y_max=y_edge)
    print(f"Plane Poiseuille suspension: {len(cs.a)} particles, phi0"
          f" {run.phi0():.3f} (core {phi_core:.3f}, wall layers {layer:g}"
          f" a1), box {run.L.tolist()} a1, t* = {run.t_end:.2f} (gammaDot_0"
          f" = {run.gamma0:g}), migration time (9/8)(L_y/a_bar)^2 ="
          f" {9 / 8 * (Ly / 1.2)**2:.0f}")
    print("  window t*      phi centre (2 a1)   phi outer core    phi wall"
          f" layers   [SBM eq F.8b, {model.name}, phi_J {phij:g}]")
    fine = np.linspace(layer, Ly - layer, 601)
    phis, sbms = [], []
    for (lo, hi), steps, times in zip(bounds, run.windows, samples):
        _, phi, _ = cs.profiles(nb, steps)
        m = np.mean([np.interp(np.abs(fine - Ly / 2) / Ly, ys,
                               transient[float(s)]) for s in times], axis=0)
        m = np.where(core, bin_mean(m, fine, np.clip(run.edges, layer,
                                                       Ly - layer)), np.nan)
        phis.append(phi)
        sbms.append(m)
        print(f"  {lo:5.2f}-{hi:5.2f}   {phi[centre].mean():.3f}"
              f" [{m[centre].mean():.3f}]     {phi[outer].mean():.3f}"
              f" [{m[outer].mean():.3f}]    {phi[~core].mean():.3f}")
        ax.plot(phi, yb, "o-", ms=3, label=f"t* {lo:.1f}-{hi:.1f}")
    change = [(phis[-1][k].mean() - phi_start[k].mean(),
               sbms[-1][k].mean() - phi_core) for k in (centre, outer)]
    print(f"  change from the packing to the last window: centre"
          f" {change[0][0]:+.3f} (SBM {change[0][1]:+.3f}), outer core"
          f" {change[1][0]:+.3f} (SBM {change[1][1]:+.3f})")

    yst, ps, _ = sbm.poiseuille_profile(sigma22, phi_core, phij, y_max=y_edge)
    # Steady state (eqs F.10-F.11) on the same bins; the last two windows
    # tell whether the run has reached it
    steady = np.interp(np.abs(fine - Ly / 2) / Ly, yst, ps)
    steady = np.where(core, bin_mean(steady, fine, np.clip(
        run.edges, layer, Ly - layer)), np.nan)
    drift = np.abs(phis[-1] - phis[-2])[core].max() if len(phis) > 1 else 0
    rms = np.sqrt(np.mean((phis[-1] - steady)[core]**2))
    print(f"  steady SBM (eqs F.10-F.11): centre {steady[centre].mean():.3f},"
          f" outer core {steady[outer].mean():.3f}; last window against it:"
          f" centre {phis[-1][centre].mean() - steady[centre].mean():+.3f},"
          f" outer core {phis[-1][outer].mean() - steady[outer].mean():+.3f},"
          f" rms over the core bins {rms:.3f}; largest change of a core bin"
          f" between the last two windows {drift:.3f}")

    ax.plot(sbms[0], yb, "--", color="0.5", label="SBM eq F.8b, first window")
    ax.plot(sbms[-1], yb, "k--", label="SBM eq F.8b, last window")
    ax.plot(ps, Ly / 2 + yst * Ly, "k:", lw=0.8, label="SBM steady")
    ax.plot(ps, Ly / 2 - yst * Ly, "k:", lw=0.8)
    ax.axvline(phi_core, color="0.6", lw=0.6)
    ax.axhspan(0, layer, color="0.93")
    ax.axhspan(Ly - layer, Ly, color="0.93")
    ax.set(xlabel=r"$\phi$ (a$_1$ bins, eq 6.5)", ylabel=r"$y/a_1$",
           title="migration")
    ax.legend(fontsize=7)
    return phis[-1], steady


def velocity(run, U, phi, model, layer, ax):
    """Blunting (centre over mean velocity, 1.5 for the parabola) against
    eq F.8a with the measured phi(y) (mirror-averaged a1 bins) and two
    viscosity closures: Morris-Boulay and the thesis' Maron-Pierce fit (eq
    4.12, alpha = 0.803): the velocity local rheology predicts."""
    Ly, nb, yc = run.Ly, run.nb, run.yc
    newtonian = abs(run.G) / (2 * run.eta) * yc * (Ly - yc)
    _, _, up = run.cs.profiles(nb, run.windows[-1])
    y_half = np.linspace(0, 0.5, 501)
    phi_sym = 0.5 * (phi + phi[::-1])
    phi_half = phi_sym[np.minimum((Ly / 2 + y_half * Ly).astype(int), nb - 1)]
    print(f"  velocity (last window): centre/mean {U.max() / U.mean():.3f}"
          f" (parabola 1.5), mean {U.mean():.4f} (particle-free"
          f" {newtonian.mean():.4f}); eq F.8a with the measured phi(y):")
    ax.plot(U, yc, "-", label="suspension (solver U)")
    ax.plot(up, run.yb, "o", ms=4, mfc="none", label="particles (eq 6.4)")
    ax.plot(newtonian, yc, "k--", lw=0.8, label="particle-free parabola")
    closures = ((model.name, model.eta_s, ":"),
                ("Maron-Pierce eq 4.12",
                 sbm.maron_pierce_poiseuille(model.phij), "-."))
    # The SBM's own domain, the core (thesis 6.3.2): the rise of the
    # velocity from the core's edges to the centre, the edges' measured
    # velocity (the wall layers' slip and ordering) taken as given
    core = y_half <= 0.5 - layer / Ly
    u_edge = np.interp([layer, Ly - layer], yc, U).mean()
    u_centre = np.interp(Ly / 2, yc, U)
    for name, eta_s, style in closures:
        u_sbm = (sbm.poiseuille_velocity(y_half, phi_half, eta_s)
                 * run.gamma0 * Ly)
        mean_sbm = np.trapz(u_sbm, y_half) / 0.5
        rise = (sbm.poiseuille_velocity(y_half[core], phi_half[core], eta_s)
                * run.gamma0 * Ly)
        print(f"    {name}: centre/mean {u_sbm[0] / mean_sbm:.3f}, mean"
              f" {mean_sbm:.4f} (solver/model {U.mean() / mean_sbm:.3f});"
              f" core (from {layer:g} a1) rise to the centre {rise[0]:.4f}"
              f" against the solver's {u_centre - u_edge:.4f}")
        ax.plot(u_sbm, Ly / 2 + y_half * Ly, "k" + style, lw=0.8,
                label=rf"eq F.8a, measured $\phi(y)$, {name}")
        ax.plot(u_sbm, Ly / 2 - y_half * Ly, "k" + style, lw=0.8)
        ax.plot(u_edge + rise, Ly / 2 + y_half[core] * Ly, "r" + style,
                lw=1, label=f"same, core from its edges' U ({name})")
        ax.plot(u_edge + rise, Ly / 2 - y_half[core] * Ly, "r" + style,
                lw=1)
    ax.set(xlabel=r"$u_x$", title=f"velocity, t* > {run.bounds[-2]:.1f}")
    ax.legend(fontsize=6, loc="upper right", framealpha=0.6)


def x_momentum(run, gamma, hp, c, ax):
    """Sigma_xy(y) = eta dU/dy + Sigma^hp_xy + Sigma^c_xy (eqs 6.13,
    6.18-6.19) against eq F.6a, and the whole-channel balance."""
    yb, Ly, G = run.yb, run.Ly, run.G
    fluid_xy = run.eta * gamma
    sxy = fluid_xy + hp[:, 0, 1] + c[:, 0, 1]
    inner = (yb > 1) & (yb < Ly - 1)
    slope, level = cf.shear_stress_line(yb, sxy, Ly, inner)
    theory = G * (yb - Ly / 2) + level
    scale = abs(G) * Ly / 2                   # wall shear stress
    dev = np.abs(sxy - theory) / scale
    print(f"  shear stress balance (last window, {len(run.written)} fields,"
          f" bins 1 a1 from the walls): slope dSigma_xy/dy {slope:.4f}"
          f" against dP0/dx {G:g} ({(slope - G) / abs(G):+.1%}); level (wall"
          f" asymmetry) {level / scale:+.1%} of the wall stress; largest"
          f" deviation from the line {dev[inner].max():.1%} (next to the"
          f" walls {dev[~inner].max():.1%})")
    # Whole channel: the pressure-gradient force goes to the walls through
    # the fluid's wall shear and, through the particles' lambda, through
    # their sub-grid lubrication and contacts with the walls
    fluid, particles, residual = cf.global_balance(
        run.case, run.bounds[-2] / run.gamma0)
    print(f"  global x balance: fluid wall shear {fluid:.1%} and particles"
          f" {particles:.1%} of the pressure-gradient force, residual"
          f" {residual:.1e}")
    ax.plot(sxy, yb, "o-", label=r"$\Sigma_{xy}$ total")
    ax.plot(c[:, 0, 1], yb, "s", ms=3, label="contact")
    ax.plot(hp[:, 0, 1], yb, "^", ms=3, label="particle hydrodynamic")
    ax.plot(fluid_xy, yb, "v", ms=3, label=r"$\eta\,dU/dy$")
    ax.plot(theory, yb, "k--", lw=0.8,
            label=r"$dP_0/dx\,(y - L_y/2)$ + fitted level")
    ax.set(xlabel="shear stress", title="x-momentum balance (F.6a)")
    ax.legend(fontsize=7)


def y_momentum(run, hp, c, ax):
    """Sigma_yy(y) = -(1 - phi)<p>^f + Sigma^hp_yy + Sigma^c_yy (eqs
    6.13-6.14), uniform in a steady state."""
    cs = run.cs
    records = [int(np.argmin(np.abs(cs.t - w))) for w in run.written]
    pf = np.mean([cf.fluid_pressure(cf.field(run.case, "p", w, run.n),
                                    run.n, run.L, cs.x[k], cs.a)
                  for w, k in zip(run.written, records)], axis=0)
    pf = bin_mean(pf, run.yc, run.edges)
    syy = -pf + hp[:, 1, 1] + c[:, 1, 1]
    print(f"  Sigma_yy (eq 6.13) across the channel: mean {syy.mean():.3f},"
          f" spread (max - min) {np.ptp(syy):.3f}, of which contact"
          f" {np.ptp(c[:, 1, 1]):.3f}, particle hydrodynamic"
          f" {np.ptp(hp[:, 1, 1]):.3f}")
    ax.plot(syy, run.yb, "o-", label=r"$\Sigma_{yy}$ total (eq 6.13)")
    ax.plot(c[:, 1, 1], run.yb, "s", ms=3, label="contact")
    ax.plot(hp[:, 1, 1], run.yb, "^", ms=3, label="particle hydrodynamic")
    ax.plot(-pf, run.yb, "v", ms=3, label=r"$-(1-\phi)\langle p\rangle^f$")
    ax.set(xlabel="normal stress", title="y-momentum balance")
    ax.legend(fontsize=7)


def write_profiles(run, phi, U, gamma, hp, c, steady):
    """The last window's profiles on the a1 bins (eq 6.5) in
    poiseuilleProfiles.dat: phi, u_p (eq 6.4), the suspension velocity and
    shear rate, the particle hydrodynamic and contact stresses (xy, yy) and
    the steady SBM phi (eqs F.10-F.11; NaN in the wall layers)."""
    _, _, up = run.cs.profiles(run.nb, run.windows[-1])
    Ub = bin_mean(U, run.yc, run.edges)
    out = os.path.join(run.case, "poiseuilleProfiles.dat")
    np.savetxt(out, np.column_stack([
        run.yb, phi, up, Ub, gamma, hp[:, 0, 1], c[:, 0, 1], hp[:, 1, 1],
        c[:, 1, 1], steady]), fmt="%.6g", header=(
        f"last window t* {run.bounds[-2]:.2f}-{run.bounds[-1]:.2f}, a1 bins\n"
        "y phi u_p U dU/dy SigmaHp_xy SigmaC_xy SigmaHp_yy SigmaC_yy"
        " phi_SBM_steady"))
    print(f"  wrote {out}")


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
    ap.add_argument("--closure", metavar="SWEEPFIT",
                    help="the SBM closures fitted to a Couette sweep"
                         " (plotSweep.py's sweepFit.json) instead of"
                         " Morris-Boulay; its phi_J replaces --phij")
    args = ap.parse_args()
    model = closure(args.closure, args.phij)

    run = Run(args.case, args.windows)
    fig, ax = plt.subplots(1, 4, figsize=(17, 4.2))
    phi, steady = migration(run, args.layer, model, ax[0])
    U = cf.mean_layers(run.case, "U", run.written, run.n)[:, 0]
    gamma = cf.shear_rate_bins(U, run.edges, run.Ly)
    hp, c = run.cs.stress_profiles(run.nb, run.windows[-1])
    write_profiles(run, phi, U, gamma, hp, c, steady)
    x_momentum(run, gamma, hp, c, ax[2])
    y_momentum(run, hp, c, ax[3])
    velocity(run, U, phi, model, args.layer, ax[1])
    fig.tight_layout()
    out = os.path.join(args.case, "poiseuille.png")
    fig.savefig(out, dpi=110)
    print(f"  wrote {out}")


if __name__ == "__main__":
    main()
