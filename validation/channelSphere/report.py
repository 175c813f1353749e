#!/usr/bin/env python3
"""Report of the channel sphere validation (run.py): for every (family,
H, d, sphere) the mean and scatter over the in-plane positions of the
normalised velocities and stresslet with the frameInvariant sub-grid
model, and the FDM alone at one position, against the free spheres in
the channel of fdmResistance.boundaryElement.channel_spheres (cached in
reference.dat with its discretisation error); writes report.md and
channelSphere.png.

    ./report.py [--recompute]      (run.py calls it after the solves)

Targets (set before the runs, as in wallShearSphere): |error| of the
position mean with the sub-grid model at most 3 % for the velocities
(U_x, U_y, Omega_z) and 5 % for the stresslet S_xy, for every case.
Where the normalised reference is near zero (|reference| < 0.1: U_x and
U_y of the shear family and U_y of the Poiseuille family, zero by
symmetry; U_y and the angular velocity of the pair's centre-line sphere)
the target is an absolute |error| of at most 0.01 in the normalised unit
instead.  Where a reference cannot be computed the table shows "n/a"
and the result is FAIL.

Normalisation (a = 1, eta = nu rho of the template, shear rate 1 or
U_c = 1): shear -Omega_z/shear (0.5 unbounded), S_xy/((10/3) pi eta a^3
shear) (1 unbounded), U_x/(shear a), U_y/(shear a); Poiseuille U_x/U_c,
Omega_z a/U_c (sign kept), S_xy/(4 U_c eta a^3/H) (Ghalya et al. 2020),
U_y/U_c; pair (each sphere) U_x/U_c, U_y/U_c, 2 a Omega_z/U_c (as
Bhattacharya et al. 2006), S_xy/(4 U_c eta a^3/H)."""

import argparse
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("FDM_PROJECT_DIR",
                                               os.path.join(HERE, "..", "..")),
                                "src", "python"))
from fdmPost.report import write_markdown  # noqa: E402
from run import PAIR_Y2, U_C, centres  # noqa: E402  (one geometry)

REL_TOL = {"velocity": 0.03, "stresslet": 0.05}
NEAR_ZERO = 0.1
ABS_TOL = 0.01
REFERENCE_FILE = os.path.join(HERE, "reference.dat")

# (label, kind) of the four normalised quantities of each family, in the
# order of normalise()
QUANTITIES = {
    "shear": [("-Omega_z/shear", "velocity"),
              ("S_xy/((10/3) pi eta a^3 shear)", "stresslet"),
              ("U_x/(shear a)", "velocity"),
              ("U_y/(shear a)", "velocity")],
    "poiseuille": [("U_x/U_c", "velocity"),
                   ("Omega_z a/U_c", "velocity"),
                   ("S_xy/(4 U_c eta a^3/H)", "stresslet"),
                   ("U_y/U_c", "velocity")],
    "pair": [("U_x/U_c", "velocity"),
             ("U_y/U_c", "velocity"),
             ("2a Omega_z/U_c", "velocity"),
             ("S_xy/(4 U_c eta a^3/H)", "stresslet")]}
FAMILIES = ("shear", "poiseuille", "pair")


def template_eta():
    """Dynamic viscosity nu rho of the template's transportProperties."""
    text = open(os.path.join(HERE, "template", "constant",
                             "transportProperties")).read()
    value = {k: float(re.search(r"^\s*%s\s+([^;\s]+)\s*;" % k, text,
                                re.M).group(1)) for k in ("nu", "rho")}
    return value["nu"] * value["rho"]


def normalise(family, H, ux, uy, omz, sxy, eta):
    """The four normalised quantities (QUANTITIES order) from the raw
    U_x, U_y, Omega_z, S_xy."""
    if family == "shear":
        return np.array([-omz, sxy / (10.0 / 3.0 * np.pi * eta), ux, uy])
    if family == "pair":
        return np.array([ux / U_C, uy / U_C, 2 * omz / U_C,
                         sxy / (4 * U_C * eta / H)])
    return np.array([ux / U_C, omz / U_C, sxy / (4 * U_C * eta / H),
                     uy / U_C])


def key(family, H, d, sphere):
    return (family, round(float(H), 9), round(float(d), 9), int(sphere))


def load():
    """{(family, H, d, sphere): {model: array (positions, 4) of raw U_x,
    U_y, Omega_z, S_xy}} and the solves' box, cell counts and wall
    times."""
    out = {}
    cost = []
    for line in open(os.path.join(HERE, "results.dat")):
        if line.startswith("#"):
            continue
        r = line.split()
        out.setdefault(key(*r[:4]), {}).setdefault(
            r[6], []).append([float(v) for v in r[7:11]])
        if r[3] == "1":
            cost.append((float(r[11]), int(r[12]), float(r[13])))
    return ({k: {m: np.array(v) for m, v in ms.items()}
             for k, ms in out.items()}, cost)


def read_reference_cache():
    """{key: 30 numbers U(3), Omega(3), S(9, row major), then their
    estimated errors in the same order} of reference.dat."""
    cache = {}
    if os.path.isfile(REFERENCE_FILE):
        for line in open(REFERENCE_FILE):
            if line.startswith("#") or not line.strip():
                continue
            r = line.split()
            cache[key(*r[:4])] = np.array([float(v) for v in r[4:34]])
    return cache


def write_reference_cache(cache):
    with open(REFERENCE_FILE, "w") as f:
        f.write("# free spheres a = 1, eta = 1 in the channel 0 < y < H "
                "from fdmResistance.boundaryElement.channel_spheres "
                "(centre at y = d; pair: (-d H/2, H/2, 0) and (d H/2, %g, "
                "0)); "
                "shear: u = (y - H/2, 0, 0), poiseuille and pair: "
                "u = (4 y (H - y)/H^2, 0, 0)\n# family H d sphere U_x U_y "
                "U_z Omega_x Omega_y Omega_z S_xx S_xy S_xz S_yx S_yy S_yz "
                "S_zx S_zy S_zz, then the estimated error of each\n"
                % PAIR_Y2)
        for k in sorted(cache):
            f.write("%s %.17g %.17g %d %s\n" % (k + (" ".join(
                "%.6g" % v for v in cache[k]),)))


def boundary_element(family, H, d):
    """Reference of one configuration: {sphere: 30 numbers}."""
    from fdmResistance.boundaryElement import channel_spheres
    # the solver's geometry (the walls are unbounded along x and z, so the
    # origin does not matter: moving it changes the result by 1e-13)
    x = centres(family, H, d, 0.0, (0.0, 0.0))
    r = channel_spheres(H, x, "couette" if family == "shear"
                        else "poiseuille")
    return {i + 1: np.concatenate(
        [np.ravel(r[q][i]) for q in ("U", "Omega", "S")]
        + [np.ravel(r["error"][q][i]) for q in ("U", "Omega", "S")])
        for i in range(len(x))}


def references(keys, recompute):
    """Reference (30 numbers, or None) for every key, from reference.dat,
    computing the missing ones (all with recompute); and notes on what
    could not be computed."""
    cache = read_reference_cache()
    todo = sorted({k[:3] for k in keys if recompute or k not in cache})
    notes = []
    for config in todo:
        print("reference %s H %g d %g ..." % config, flush=True)
        try:
            for sphere, values in boundary_element(*config).items():
                cache[config + (sphere,)] = values
        except Exception as e:      # a broken reference must not hide
            notes.append("reference %s H %g d %g failed (%s: %s)."  # the
                         % (config + (type(e).__name__, e)))      # table
    if todo:
        write_reference_cache(cache)
    return {k: cache.get(k) for k in keys}, notes


def ref_normalised(k, r):
    """Normalised reference quantities and their estimated errors (nan
    without a reference): r is U(3), Omega(3), S(9, row major), so
    S_xy = r[7], then the errors in the same order."""
    if r is None:
        return np.full(4, np.nan), np.full(4, np.nan)
    return (normalise(k[0], k[1], r[0], r[1], r[5], r[7], 1.0),
            np.abs(normalise(k[0], k[1], *r[[15, 16, 20, 22]], 1.0)))


def judge(kind, ref, value):
    """(error text, passes or None): relative error, or absolute where the
    reference is near zero."""
    if not np.isfinite(ref):
        return "n/a", None
    if abs(ref) < NEAR_ZERO:
        return "%+.4f abs" % (value - ref), abs(value - ref) <= ABS_TOL
    err = value / ref - 1
    return "%+.2f %%" % (100 * err), abs(err) <= REL_TOL[kind]


def fmt(v, digits=4):
    return "n/a" if not np.isfinite(v) else "%.*f" % (digits, v)


def main(argv=()):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--recompute", action="store_true",
                        help="recompute reference.dat")
    args = parser.parse_args(list(argv))
    eta = template_eta()
    data, cost = load()
    # by family, then by 2a/H, d and sphere
    keys = sorted(data, key=lambda k: (FAMILIES.index(k[0]), -k[1], k[2],
                                       k[3]))
    refs, notes = references(keys, args.recompute)

    rows = {}    # key: (ref, sg mean, sg std, fdm, ref error)
    lines = ["# Free spheres in a channel: Couette, Poiseuille and the "
             "Bhattacharya pair (thesis 1, 4.1.2b, c, 4.1.4)", "",
             "Generated by `report.py` from `results.dat` (`run.py`).",
             "Sphere a = 1, Delta = a/5, walls y = 0 and y = H, cyclic in "
             "x and z with period L = %s a; position mean (std) over the "
             "in-plane positions with the frameInvariant sub-grid model, "
             "one position without it (FDM alone)."
             % ", ".join("%g" % L for L in sorted({c[0] for c in cost}))
             if cost else "", "",
             "d/a: height of the centre; for the pair, the streamwise "
             "separation rho_12/H of sphere 2 (centre 1.33 a above the "
             "bottom wall) downstream of sphere 1 (centre line), H = 4 a.",
             "", "| family | 2a/H | d/a | sphere | quantity | reference "
             "(error) | FDM + SG mean (std) | error | FDM alone | error |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    worst = {}   # (family, quantity index, absolute): largest |error|
    failures = []
    undecided = 0
    for k in keys:
        fam, H, d, sphere = k
        sg_raw = data[k].get("frameInvariant", np.full((1, 4), np.nan))
        sg_all = np.array([normalise(fam, H, *v, eta) for v in sg_raw])
        sg, sg_std = sg_all.mean(axis=0), sg_all.std(axis=0)
        fdm = (np.array([normalise(fam, H, *v, eta)
                         for v in data[k]["none"]]).mean(axis=0)
               if "none" in data[k] else np.full(4, np.nan))
        ref, ref_err = ref_normalised(k, refs[k])
        rows[k] = (ref, sg, sg_std, fdm, ref_err)
        for j, (name, kind) in enumerate(QUANTITIES[fam]):
            e_sg, ok = judge(kind, ref[j], sg[j])
            e_fdm, _ = judge(kind, ref[j], fdm[j])
            lines.append("| %s | %.3f | %g | %d | %s | %s (%s) | %s (%s) | "
                         "%s | %s | %s |"
                         % (fam, 2 / H, d, sphere, name, fmt(ref[j]),
                            fmt(ref_err[j]), fmt(sg[j]), fmt(sg_std[j]),
                            e_sg, fmt(fdm[j]), e_fdm))
            if ok is None:
                undecided += 1
                continue
            absolute = abs(ref[j]) < NEAR_ZERO
            size = (abs(sg[j] - ref[j]) if absolute
                    else abs(sg[j] / ref[j] - 1))
            w = worst.setdefault((fam, j, absolute), 0.0)
            worst[(fam, j, absolute)] = max(w, size)
            if not ok:
                failures.append("%s H %g d %g sphere %d %s"
                                % (fam, H, d, sphere, name))

    lines += [""]
    for fam in FAMILIES:
        parts = []
        for j, (name, kind) in enumerate(QUANTITIES[fam]):
            if (fam, j, False) in worst:
                parts.append("%s %.2f %%" % (name,
                                             100 * worst[(fam, j, False)]))
            if (fam, j, True) in worst:
                parts.append("%s %.4f (absolute)" % (name,
                                                     worst[(fam, j, True)]))
        if parts:
            lines.append("Largest |error| with the sub-grid model, %s: %s."
                         % (fam, ", ".join(parts)))
    lines += ["Targets: 3 % (velocities), 5 % (stresslet) of the position "
              "mean with the sub-grid model; absolute 0.01 (normalised) "
              "where |reference| < 0.1."]
    if failures:
        lines += ["", "Outside the target: " + "; ".join(failures) + "."]
    if cost:
        walls = np.array([c[2] for c in cost])
        lines += ["", "Cost: %d solves, %d to %d cells, %.0f to %.0f s each "
                  "(mean %.0f s; 2 solves at a time on 2 cores)."
                  % (len(cost), min(c[1] for c in cost),
                     max(c[1] for c in cost), walls.min(), walls.max(),
                     walls.mean())]
    lines += ["", "Reference: `fdmResistance.boundaryElement.channel_spheres` "
              "(free spheres between two walls, unbounded in x and z; "
              "boundary integrals, the error in brackets is its estimated "
              "discretisation error), cached in `reference.dat` "
              "(`./report.py --recompute` recomputes it).", "",
              "Notes. The solver's box is periodic in x and z with period L; "
              "at the centre of the Couette channel the disturbance of the "
              "force-free sphere decays exponentially along the channel: at "
              "H = 4 a box of L = 24 instead of 16 changed Omega_z and S_xy "
              "by less than 3e-7 (relative; one position). In Poiseuille "
              "flow at an imposed pressure gradient the periodic array of "
              "spheres lowers the flow rate by a fraction ~ 1/L^2: at H = 5, "
              "d = 1.5 a box of L = 24 raised U_x, Omega_z and S_xy alike "
              "by 0.17 %, so that L = 16 is about 0.3 % low in all three "
              "(1/L^2 extrapolation). The wall sub-grid functions act "
              "only below the gaps 0.3 a (X) and 0.15 a (Y): the shear family "
              "(gaps (H - 2a)/2 >= 0.4 a) and the Poiseuille cases with "
              "d/a >= 1.3 and H - d - a >= 0.3 a are solved by the FDM alone "
              "in both columns, which then differ only by the position."]
    if notes:
        lines += [""] + ["Note: " + n for n in notes]
    ok = not failures and undecided == 0 and bool(keys)
    result = "PASS" if ok else "FAIL"
    if undecided:
        result += " (%d quantities without a reference)" % undecided
    lines += ["", "Result: %s" % result]
    write_markdown(os.path.join(HERE, "report.md"), lines)
    plot(rows)


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    families = [f for f in FAMILIES if any(k[0] == f for k in rows)]
    if not families:
        return
    fig, axes = plt.subplots(len(families), 3,
                             figsize=(13, 4 * len(families)), squeeze=False)
    for ax_row, fam in zip(axes, families):
        keys = sorted(k for k in rows if k[0] == fam)
        if fam == "shear":
            x = np.array([2 / k[1] for k in keys])
            series = [(x, keys, "C0", "")]
            panels = [(0, 0.5), (1, 1.0), (2, None)]
            xlabel = "2a/H"
        elif fam == "pair":
            series = []
            for sphere in (1, 2):
                ks = [k for k in keys if k[3] == sphere]
                series.append((np.array([k[2] for k in ks]), ks,
                               "C%d" % (sphere - 1), " sphere %d" % sphere))
            panels = [(0, None), (1, None), (2, None)]
            xlabel = "rho_12/H"
        else:
            series = []
            for i, H in enumerate(sorted({k[1] for k in keys}, reverse=True)):
                ks = [k for k in keys if k[1] == H]
                series.append((np.array([k[2] for k in ks]), ks, "C%d" % i,
                               " 2a/H = %.3g" % (2 / H)))
            panels = [(0, None), (1, None), (2, None)]
            xlabel = "d/a"
        for ax, (j, unbounded) in zip(ax_row, panels):
            for x, ks, colour, label in series:
                ref = np.array([rows[k][0][j] for k in ks])
                sg = np.array([rows[k][1][j] for k in ks])
                std = np.array([rows[k][2][j] for k in ks])
                fdm = np.array([rows[k][3][j] for k in ks])
                order = np.argsort(x)
                if np.isfinite(ref).any():
                    ax.plot(x[order], ref[order], "-x", color=colour,
                            label="reference" + label)
                ax.errorbar(x, sg, yerr=std, fmt="o", color=colour,
                            label="FDM + sub-grid" + label)
                ax.plot(x, fdm, "s", color=colour, mfc="none",
                        label="FDM alone" + label)
                if fam == "shear" and j == 2:
                    # the U_y check in the same panel
                    uy = np.array([rows[k][1][3] for k in ks])
                    ax.errorbar(x, uy, yerr=[rows[k][2][3] for k in ks],
                                fmt="^", color="C1", label="U_y FDM + SG")
                if fam == "poiseuille" and j == 0:
                    H = ks[0][1]
                    d = np.linspace(min(1.0, x.min()), max(H / 2, x.max()),
                                    100)
                    ax.plot(d, 4 * U_C * d * (H - d) / H ** 2, ":",
                            color=colour, label="fluid u(d)" + label)
            if unbounded is not None:
                ax.axhline(unbounded, color="0.6", ls=":",
                           label="unbounded")
            ax.set_xlabel(xlabel)
            title = QUANTITIES[fam][j][0]
            if fam == "shear" and j == 2:
                title = "U_x, U_y/(shear a) (0 by symmetry)"
            ax.set_title("%s: %s" % (fam, title))
        ax_row[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "channelSphere.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1:])
