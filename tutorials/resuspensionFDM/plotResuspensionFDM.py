#!/usr/bin/python3
"""Viscous resuspension with the resolved fluid (tutorials/resuspensionFDM;
thesis 2, article 3, with fdmSuspensionFoam): heavy spheres on the floor
of a channel sheared by its lid, gravity along the velocity gradient.

Per case (one Shields number Sh = eta gammaDot_w/(drho g a), a the heavy
spheres' mean radius, gammaDot_w the walls' shear rate):
  - phi(y) over time windows (eq 2.70 of thesis 1, a1 bins), the
    suspension height (phi = 0.05 on the way up) and the centroid, so the
    expansion of the bed shows;
  - over the steady part (from --start, default the second half): the
    particle velocity u_p(y) (eq 6.4) and its slope, the local shear rate;
    the momentum balance of the particles, their normal stress
    -Sigma^p_22(y) (stresslets spread over the spheres' volumes) against
    the buoyant weight above y, drho g int_y phi dy'; and
    eta_22(phi) = (weight above)/(eta gammaDot(y)), eq 6 with the local
    shear rate (the cell is not sheared uniformly here: the bed shears
    less than the clear fluid), against the closures of
    fdmPost.suspensionBalance.

    plotResuspensionFDM.py CASE... [--windows 4] [--start STRAIN]

CASE: a run's particle checkpoint (checkpoints/Sh<S>: the series and the
lid's force over all its segments, fdmPost.checkpoint) or a case
directory.

Writes resuspension.png.  Stresses in units of eta gammaDot_w.
"""

import argparse
import os

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost import suspensionBalance as sbm  # noqa: E402
from fdmPost import thinSeries  # noqa: E402
from fdmPost.rheology import channel_case, number  # noqa: E402


def shields_number(run):
    """The Shields number of the gravity block in the run's
    particleProperties (particles.h5 attributes)."""
    return number(run["particleProperties"], "shieldsNumber")


def weight_above(y, phi, edges, g):
    """drho g int_y^top phi dy' at the bin centres y (phi piecewise
    constant over the bins), with drho g = g."""
    per_bin = phi * np.diff(edges)
    above = np.cumsum(per_bin[::-1])[::-1] - 0.5 * per_bin
    return g * above


def lid_stress(case, L, start):
    """The shear stress the suspension bears: the lid's force per area
    (the lidForce function object; a checkpoint's lidForce.csv) averaged
    over the times from `start`; None without its rows."""
    if os.path.exists(f"{case}/lidForce.csv"):
        rows = thinSeries.read_force_rows(f"{case}/lidForce.csv")
    else:
        rows = thinSeries.case_force_rows(case, "lidForce")
    rows = rows[rows[:, 0] >= start]
    if not len(rows):
        return None
    # The fluid pulls the lid (moving along +x) back: F_x = -tau L_x L_z
    return -rows[:, 1].mean() / (L[0] * L[2])


def sbm_profiles(cs, L, sh_tau):
    """phi(y) of the suspension balance model at imposed shear stress
    (fdmPost.suspensionBalance.RATIO_CLOSURES, Shields number sh_tau of
    the clear fluid's stress) for the particles' volume per floor area:
    {closure: (y, phi)}, heights in a1 (the closures' unit is the mean
    radius a); a closure whose ratio cannot carry the bed (a static base)
    is left out."""
    if sh_tau is None:
        return {}
    a = cs.a.mean()
    volume = (4 / 3 * np.pi * cs.a**3).sum() / (L[0] * L[2]) / a
    out = {}
    for name, ratio in sbm.RATIO_CLOSURES.items():
        try:
            z, phi, _ = sbm.resuspension_profile(ratio, sh_tau, volume)
        except ValueError:
            continue
        out[name] = (cs.lo[1] + z * a, phi)
    return out


def analyse(case, windows, start):
    cs, L, run = channel_case(case, 0.0)
    gamma = run["shearRate"]
    sh = shields_number(run)
    # drho g of the Shields number, in units of eta gammaDot_w/a1
    g = cs.eta * gamma / (sh * cs.a.mean())
    strain = cs.t * gamma
    nb = int(round(L[1]))
    edges = np.linspace(cs.lo[1], cs.lo[1] + L[1], nb + 1)
    out = {"case": case, "Sh": sh, "edges": edges, "windows": []}
    bounds = np.linspace(0, strain[-1], windows + 1)
    for lo, hi in zip(bounds[:-1], bounds[1:]):
        steps = np.flatnonzero((strain >= lo) & (strain <= hi))
        if len(steps) == 0:
            continue
        y, phi, _ = cs.profiles(nb, steps)
        out["windows"].append((lo, hi, phi))
    start = strain[-1] / 2 if start is None else start
    steady = np.flatnonzero(strain >= start)
    y, phi, up = cs.profiles(nb, steady)
    hp, c = cs.stress_profiles(nb, steady)
    rate = np.gradient(up, y)
    w = weight_above(y, phi, edges, g)
    out.update(y=y, phi=phi, up=up / gamma, rate=rate / gamma,
               s22=-(hp + c)[:, 1, 1] / (cs.eta * gamma),
               weight=w / (cs.eta * gamma), start=start, end=strain[-1],
               height=sbm.top_height(y, phi), centroid=sbm.centroid(y, phi))
    # eq 6 with the local rate, in the bed's bulk: 2 a1 above the floor,
    # 2 a1 below the top, sheared
    tau = lid_stress(case, L, start / gamma)
    # Shields number of the stress the bed bears (article 3's definition
    # with the imposed stress): Sh tau/(eta gammaDot_w)
    out["ShTau"] = None if tau is None else sh * tau / (cs.eta * gamma)
    out["sbm"] = sbm_profiles(cs, L, out["ShTau"])
    bulk = (y > edges[0] + 2) & (y < out["height"] - 2) & (rate > 0.02)
    out["bulk"] = bulk
    out["eta22"] = np.where(bulk, w / (cs.eta * np.maximum(rate, 1e-12)),
                            np.nan)
    return out


def report(r):
    sh_tau = ("no lidForce rows" if r["ShTau"] is None else
              f"{r['ShTau']:.3f}")
    print(f"{r['case']}: Sh {r['Sh']:g} (walls' shear rate), strain"
          f" {r['end']:.2f}; Shields number of the clear fluid's shear"
          f" stress (the lid's) {sh_tau}")
    print("  window strain   height  centroid  phi at the floor bin")
    for lo, hi, phi in r["windows"]:
        y = 0.5 * (r["edges"][1:] + r["edges"][:-1])
        print(f"  {lo:5.1f}-{hi:5.1f}    {sbm.top_height(y, phi):6.2f}"
              f"  {sbm.centroid(y, phi):8.2f}  {phi[0]:.3f}")
    inside = r["phi"] > 0.02
    err = np.abs(r["s22"] - r["weight"])[inside].max() / r["weight"].max()
    print(f"  steady (strain >= {r['start']:.1f}): height {r['height']:.2f},"
          f" centroid {r['centroid']:.2f}; momentum balance: largest"
          f" |-Sigma^p_22 - weight above| over the bins with phi > 0.02,"
          f" {err:.3f} of the weight on the floor")
    for name, (ys, ps) in r["sbm"].items():
        print(f"  SBM at Sh_tau, {name}: height {sbm.top_height(ys, ps):.2f},"
              f" centroid {sbm.centroid(ys, ps):.2f}, phi on the floor"
              f" {ps[0]:.3f}")
    print("  y      phi    u_p/(gd_w a1)  gd/gd_w  -S22/(eta gd_w)"
          "  weight above  eta_22 (eq 6, local rate)")
    for k in range(len(r["y"])):
        print(f"  {r['y'][k]:5.1f}  {r['phi'][k]:.3f}  {r['up'][k]:12.3f}"
              f"  {r['rate'][k]:7.3f}  {r['s22'][k]:15.3f}"
              f"  {r['weight'][k]:12.3f}  {r['eta22'][k]:10.3f}")


def draw(results, path):
    fig, ax = plt.subplots(1, 4, figsize=(16, 4))
    for n, r in enumerate(results):
        y = r["y"]
        for k, (lo, hi, phi) in enumerate(r["windows"]):
            ax[0].plot(phi, y, "-", color=f"C{n}", alpha=0.3 + 0.7 * k
                       / max(len(r["windows"]) - 1, 1),
                       label=f"Sh {r['Sh']:g}, strain {lo:.0f}-{hi:.0f}")
        for k, (name, (ys, ps)) in enumerate(r["sbm"].items()):
            ax[0].plot(ps, ys, ["k--", "k:"][k % 2], lw=0.8,
                       label=f"SBM ({name}), Sh_tau {r['ShTau']:.2f}")
        ax[1].plot(r["up"], y, "o-", ms=3, color=f"C{n}",
                   label=f"Sh {r['Sh']:g}")
        ax[2].plot(r["s22"], y, "o", color=f"C{n}",
                   label=rf"$-\Sigma^p_{{22}}$, Sh {r['Sh']:g}")
        ax[2].plot(r["weight"], y, "-", color=f"C{n}",
                   label="weight above")
        ax[3].plot(r["phi"], r["eta22"], "o", color=f"C{n}",
                   label=f"Sh {r['Sh']:g} (eq 6, local rate)")
    phi = np.linspace(0.05, 0.57, 200)
    for name, eta in sbm.CLOSURES.items():
        ax[3].plot(phi, eta(phi, 2), "--", lw=0.8, label=name)
    ax[0].set(xlabel=r"$\phi$", ylabel=r"$y/a_1$", title="expansion")
    ax[1].set(xlabel=r"$u_p/(\dot\gamma_w a_1)$", title="particle velocity")
    ax[2].set(xlabel=r"stress$/(\eta\dot\gamma_w)$", title="momentum balance")
    ax[3].set(xlabel=r"$\phi$", ylabel=r"$\eta_{22}$", yscale="log",
              ylim=(1e-2, 1e3), title="normal viscosity")
    for a in ax:
        a.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--windows", type=int, default=4)
    ap.add_argument("--start", type=float, default=None,
                    help="strain where the steady averages start (default:"
                         " half the run)")
    ap.add_argument("--png", default="resuspension.png")
    args = ap.parse_args()
    results = [analyse(c, args.windows, args.start) for c in args.cases]
    for r in results:
        report(r)
    draw(results, args.png)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
