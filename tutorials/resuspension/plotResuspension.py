"""Steady profiles of the viscous-resuspension tutorial against the
suspension balance model (thesis 2, article 3).

For each case (one Shields number) the particleState files from strain
--start on give the time-averaged volume fraction phi(z) of the mobile
spheres (exact sphere-slab volumes, eq 2.70 of thesis 1) and the binned
normal stress sigma_ii(z) (stresslets of the spheres centred in a bin over
its volume).  z is the height above the top of the floor spheres, in a.

Printed and written to resuspension.md, with resuspension.png:
  - the height of the suspension (phi = 0.05 on the way up) and the
    centroid of the profile, against the SBM prediction of each closure
    (fdmPost.suspensionBalance) for the same particle volume;
  - the momentum balance: -sigma_ii(z)/(eta gammaDot) from the stresslets
    against the load above z: the weight (1/Sh) int_z phi (eq 6) plus the
    drag on spheres moving up while the bed still expands;
  - eta_ii(phi) recovered from the profile (eq 6) against eq 9, Boyer and
    Zarraga, in the bulk (phi/phi_m >= 0.3, more than 5 a below the top,
    as the thesis discards the interface).

    plotResuspension.py CASE [CASE ...] [--start STRAIN]
"""

import argparse
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)),
                                "..", "..", "src", "python"))

import numpy as np  # noqa: E402

from fdmPost.rheology import number, slab_volume, vector  # noqa: E402
from fdmPost.report import write_markdown  # noqa: E402
from fdmPost import suspensionBalance as sbm  # noqa: E402
from fdmPost.demRheology import averages, dem_state, state_files  # noqa: E402

PHI_TOP = 0.05   # fdmPost.suspensionBalance.top_height


def read_case(case, start, dz):
    """Time-averaged phi(z) and the normal stress sigma_zz(z) after strain
    `start`; z is the open direction of the cell (y: gravity along the
    velocity gradient, component 2; z: along the vorticity, component 3)."""
    with open(os.path.join(case, "constant", "particleProperties")) as f:
        props = f.read()
    gamma = number(props, "shearRate")
    eta = number(props[props.index("lubricatedContact"):], "viscosity")
    drag = props[props.index("drag"):] if re.search(r"^drag\b", props, re.M) else ""
    eta_drag = number(drag, "viscosity") if drag else 0.0
    lo, hi = vector(props, "min"), vector(props, "max")
    axis = "xyz".index(re.search(r"\bopen\s+\(\s*(\w)\s*\)", props).group(1))
    span = hi - lo
    area = np.prod(span) / span[axis]
    times = state_files(case)
    if start is None:
        start = 0.5 * times[-1][0] if times else 0
    times = [(t, p) for t, p in times if t >= start - 1e-6]
    if not times:
        sys.exit(f"plotResuspension: no particleState at strain >= {start}"
                 f" in {case}")
    phi_sum, syy_sum, u_sum, n_sum, drag_sum, edges = 0, 0, 0, 0, 0, None
    for t, path in times:
        state = dem_state(path)
        x, a, s = state["position"], state["radius"], state["stresslet"]
        mobile = state["mobile"]
        floor = np.mean(x[~mobile, axis] + a[~mobile])
        if edges is None:
            top = x[mobile, axis].max() + 4
            edges = floor + np.arange(0, top - floor + dz, dz)
        y, r = x[mobile, axis], a[mobile]
        phi_sum = phi_sum + np.array(
            [slab_volume(y, r, e0, e1).sum()
             for e0, e1 in zip(edges[:-1], edges[1:])]) / (area * dz)
        k = np.digitize(y, edges) - 1
        syy = np.zeros(len(edges) - 1)
        ok = (k >= 0) & (k < len(syy))
        # symmTensor components xx xy xz yy yz zz
        np.add.at(syy, k[ok], s[mobile][ok, {1: 3, 2: 5}[axis]])
        syy_sum = syy_sum + syy / (area * dz)
        # Velocity along x relative to the affine flow (stored so), by bin
        v = state["velocity"][mobile]
        u = np.zeros(len(edges) - 1)
        np.add.at(u, k[ok], v[ok, 0])
        # Downward load of the drag on spheres moving up (a bed still
        # expanding), 6 pi eta_d a v_z per volume, in eta gammaDot/a
        dragLoad = np.zeros(len(edges) - 1)
        np.add.at(dragLoad, k[ok], 6 * np.pi * eta_drag * r[ok] * v[ok, axis])
        drag_sum = drag_sum + dragLoad / (area * dz * eta * gamma)
        u_sum = u_sum + u
        n_sum = n_sum + np.bincount(k[ok], minlength=len(u))
    z = 0.5 * (edges[1:] + edges[:-1]) - edges[0]
    volume = (4 / 3 * np.pi * np.sum(a[mobile]**3)) / area
    if re.search(r"^\s*shieldsNumber\s", props, re.M):
        sh = number(props, "shieldsNumber")
    else:
        # Acrivos number (9/2) a Sh/h_0, h_0 = V/phi_m, as lubricatedDEMFoam
        h0 = volume / number(props, "packingFraction")
        sh = number(props, "acrivosNumber") * h0 / (4.5 * a[mobile].mean())
    return dict(sh=sh, gamma=gamma, component=axis + 1, z=z, dz=dz,
                phi=phi_sum / len(times),
                syy=syy_sum / len(times), volume=volume, n=len(times),
                slip=u_sum / np.maximum(n_sum, 1),
                drag=drag_sum / len(times),
                t0=times[0][0], t1=times[-1][0])


def bulk_shear_rate(r):
    """Shear rate of the bed: gammaDot (1 + d<u'_x>/dz) by least squares
    over the bins with phi > 0.1 between 2 a above the floor and 2 a below
    the top (article 3 assumes it uniform and equal to the imposed one)."""
    z, phi = r["z"], r["phi"]
    keep = (phi > 0.1) & (z > 2) & (z < sbm.top_height(z, phi) - 2)
    if r["component"] != 2 or keep.sum() < 3:
        return r["gamma"]     # Lees-Edwards across y imposes it exactly
    slope = np.polyfit(z[keep], r["slip"][keep], 1)[0]
    return r["gamma"] * (1 + slope)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--start", type=float, default=None,
                    help="strain from which to average (default: half the"
                         " last written strain)")
    ap.add_argument("--dz", type=float, default=0.5,
                    help="bin height in a (default 0.5)")
    ap.add_argument("--shear", nargs="*", default=[], metavar="CASE",
                    help="homogeneous simple-shear runs (lubricatedDEMFoam,"
                         " tri-periodic, same contact model) whose eta_ii ="
                         " -sigma_ii/(eta gammaDot), averaged after strain 2,"
                         " are drawn over the resuspension values (article 3,"
                         " figure 8)")
    ap.add_argument("-o", "--output", default=".")
    args = ap.parse_args()

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    runs = [read_case(c, args.start, args.dz) for c in args.cases]
    phim = 0.58
    comp = runs[0]["component"]
    if any(r["component"] != comp for r in runs):
        sys.exit("plotResuspension: the cases differ in the gravity direction")
    lines = ["# Viscous resuspension along the "
             + ("velocity gradient" if comp == 2 else "vorticity")
             + f" (normal viscosity eta_{comp}{comp})",
             "",
             f"Heights in a above the floor spheres; h0 = V/phi_m with"
             f" phi_m = {phim}; model: steady SBM (eq 3) for the same"
             f" particle volume V per floor area; top where phi = {PHI_TOP}.",
             "",
             "The bed's shear rate is measured (slope of the particle"
             " velocity); the model and eq 6 use the Shields number at that"
             " rate, Sh_eff = Sh gammaDot_bed/gammaDot.",
             "",
             "| Sh | gammaDot_bed/gammaDot | Sh_eff | A | strains | V |"
             " h_top DEM | centroid DEM |"
             + "".join(f" h_top {n} | centroid {n} |" for n in sbm.CLOSURES),
             "|---" * (8 + 2 * len(sbm.CLOSURES)) + "|"]
    fig, ax = plt.subplots(1, 4, figsize=(19, 5))
    balance_err, eta_bins = [], []
    for r in runs:
        h0 = r["volume"] / phim
        rate = bulk_shear_rate(r) / r["gamma"]
        sh = r["sh"] * rate
        acrivos = 4.5 * sh / h0
        row = (f"| {r['sh']:g} | {rate:.3f} | {sh:.3f} | {acrivos:.3f}"
               f" | {r['t0']:g}-{r['t1']:g}"
               f" | {r['volume']:.2f}"
               f" | {sbm.top_height(r['z'], r['phi']):.2f}"
               f" | {sbm.centroid(r['z'], r['phi']):.2f} |")
        line, = ax[0].plot(r["phi"], r["z"], "o", ms=3,
                           label=f"DEM Sh = {r['sh']:g}")
        for (name, eta), style in zip(sbm.CLOSURES.items(),
                                      ("-", "--", ":", "-.")):
            zm, pm, _ = sbm.resuspension_profile(eta, sh, r["volume"],
                                                 r["component"])
            row += (f" {sbm.top_height(zm, pm):.2f} |"
                    f" {sbm.centroid(zm, pm):.2f} |")
            ax[0].plot(pm, zm, style, color=line.get_color(), lw=1,
                       label=f"SBM {name}" if r is runs[0] else None)
        lines.append(row)

        # Momentum balance: binned stress against the weight above
        # Weight above z over eta gammaDot (imposed): the momentum balance;
        # over eta gammaDot_bed: eta_ii (eq 6)
        weight = sbm.normal_viscosity_from_profile(r["z"], r["phi"], r["sh"])
        drag = np.r_[np.cumsum((r["drag"] * r["dz"])[::-1])[::-1][1:], 0.0]
        load = weight + drag
        # The binned virial puts each sphere's stresslet at its centre:
        # average it over 2 a (a sphere's extent) before comparing
        n = max(1, int(round(2 / r["dz"])))
        stress = np.convolve(-r["syy"], np.ones(n) / n, mode="same")
        top = sbm.top_height(r["z"], r["phi"])
        bulk = (r["z"] > 2) & (r["z"] < top - 2)
        err = np.abs(stress[bulk] - load[bulk]).max() / load[bulk].max()
        balance_err.append((r["sh"], err, load[bulk].max(),
                            np.abs(drag[bulk]).max() / load[bulk].max()))
        ax[1].plot(load, r["z"], "-", color=line.get_color(),
                   label=f"weight + drag above z, Sh = {r['sh']:g}")
        ax[1].plot(stress, r["z"], "o", ms=3, color=line.get_color(),
                   label=f"-sigma_{comp}{comp} stresslets, Sh = {r['sh']:g}")

        occupied = r["phi"] > 0.05
        ax[3].plot(r["slip"][occupied], r["z"][occupied], "o-", ms=3,
                   color=line.get_color(), label=f"Sh = {r['sh']:g}")

        keep = bulk & (r["phi"] > 0.3 * phim) & (
            r["z"] < sbm.top_height(r["z"], r["phi"]) - 5)
        # eta_ii of the profile, binned by phi/phi_m (width 0.05)
        x, y = r["phi"][keep] / phim, weight[keep] / rate
        bins = np.round(x / 0.05) * 0.05
        eta_bins.append((r["sh"], [(b, np.median(y[bins == b]), int((bins == b).sum()))
                                   for b in np.unique(bins)]))
        ax[2].semilogy(x, y, "o", ms=4,
                       color=line.get_color(),
                       label=f"DEM profile (eq 6), Sh = {r['sh']:g}")

    lines += ["", f"eta_{comp}{comp} from the profiles (eq 6 at Sh_eff, bulk),"
              " median per phi/phi_m bin of 0.05 (samples):", ""]
    for sh, rows in eta_bins:
        lines.append(f"- Sh {sh:g}: " + ", ".join(
            f"{b:.2f}: {v:.3g} ({n})" for b, v, n in rows))
    if args.shear:
        lines += ["", f"Homogeneous simple shear (eta_{comp}{comp} ="
                  f" -sigma_{comp}{comp}/(eta gammaDot), strain 2 on):", ""]
    for case in args.shear:
        a = averages(case, 2.0)[0]
        value = a["P"][0] * (1 if comp == 2 else a["lambda33"])
        ax[2].semilogy(a["phi"] / phim, value, "ks", ms=7,
                       label="homogeneous shear" if case == args.shear[0]
                       else None)
        lines.append(f"- phi {a['phi']:.3f} (phi/phi_m {a['phi'] / phim:.3f}):"
                     f" eta_{comp}{comp} {value:.3g}; article 3 (eqs 8-9)"
                     f" {float(sbm.chevremont(a['phi'], comp)):.3g}")
    phis = np.linspace(0.15, 0.98, 200) * phim
    for (name, eta), style in zip(sbm.CLOSURES.items(), ("-", "--", ":", "-.")):
        ax[2].semilogy(phis / phim, eta(phis, comp), "k" + style, lw=1,
                       label=name)
    lines += ["", "Momentum balance (bulk, 2 a from the floor and the top):"
              f" max |-sigma_{comp}{comp} (stresslets, 2 a average) - load"
              " above| / max load; the load is the weight plus the drag on"
              " spheres still moving up", ""]
    lines += [f"- Sh {sh:g}: {100 * e:.1f} % of {w:.2f} eta gammaDot (drag"
              f" {100 * d:.1f} % of the load)"
              for sh, e, w, d in balance_err]
    ax[0].set(xlabel="phi", ylabel="z/a", title="volume fraction")
    ax[1].set(xlabel="stress / (eta gammaDot)", ylabel="z/a",
              title="momentum balance")
    ax[2].set(xlabel="phi/phi_m", ylabel=f"eta_{comp}{comp}", ylim=(1e-3, 1e3),
              title="normal viscosity from the profile (eq 6)")
    ax[3].set(xlabel="<u_x> - gammaDot y  (a gammaDot)", ylabel="z/a",
              title="particle velocity against the imposed shear")
    for a in ax:
        a.legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(args.output, exist_ok=True)
    png = os.path.join(args.output, "resuspension.png")
    fig.savefig(png, dpi=120)
    lines += ["", f"Plot: {png}"]
    write_markdown(os.path.join(args.output, "resuspension.md"), lines)


if __name__ == "__main__":
    main()
