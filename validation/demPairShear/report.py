#!/usr/bin/env python3
"""Report of the two-sphere shear validation of the lubricated contact model
(run.py): table, verdict and demPairShear.png."""

import os

from fdmPost.report import write_markdown  # noqa: E402


def passes(law, d0, eps, dev, end, gmin, tgmin, y_exit, tols):
    """Verdict of one run and the reference exit offset."""
    tol_traj, tol_sym, tol_gap = tols
    if eps == 0:
        ok = dev <= tol_traj and abs(end - d0) <= tol_sym * d0
        if law == "twoSphere":
            # the complete law must also close the gap as rigid spheres do
            ok = ok and abs(gmin - tgmin) <= tol_gap * tgmin
        return ok, d0
    if tgmin < eps:
        # smooth trajectory dips below the asperities: exit on the
        # theory's trajectory of minimum gap eps
        return abs(end - y_exit) <= tol_traj * y_exit, y_exit
    # never touches: the smooth trajectory, reversible
    return dev <= tol_traj and abs(end - d0) <= tol_traj * d0, d0


def write(here, rows, law_rows, y_exit, eps_rough, cutoff, tols):
    """rows: (law, d0, eps, max relative r_y deviation, r_y at +6, min
    gap, theory's min gap, r (N x 3), theory curve (tx, ty)), law
    "thesis, ARMS" or "twoSphere"; law_rows: (shearArms, spin drag factor,
    d0, deviation, min gap) of the overdamped thesis law; tols: trajectory,
    symmetry, minimum gap (twoSphere)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lines = [
        "# Two spheres in simple shear, lubricated contact model + Stokes "
        "drag (thesis 2, article 1, section 3.2)", "",
        "Lubrication cut-off %g a, friction 0; sphere 2 starts at r = "
        "(-6, d0, 0).  Hydrodynamics thesis (article 1, eq 4 and A.3) with "
        "both shearArms, Stokes number 1e-3, g/(eta gammaDot a) = 1e5 "
        "(the thesis' values); twoSphere (the squeeze of eq 4 and the "
        "exact two-body hydrodynamics, twoSphereResistance), Stokes number "
        "1e-4, g/(eta gammaDot a) = 3e7 (at 1e5 the deflection of the bulk "
        "spring, up to 7e-5 a, exceeds the smooth pairs' minimum gaps; "
        "run.py lists what inertia and stiffness do to the exit offset)."
        % cutoff,
        "",
        "| law | roughness | d0 | max \\|r_y - r_y,th\\|/r_y,th "
        "| r_y at r_x = 6 | reference r_y at 6 | min gap (DEM) "
        "| min gap (theory) | pass |",
        "|---|---|---|---|---|---|---|---|---|"]
    ok_law = {}
    laws = list(dict.fromkeys(row[0] for row in rows))
    fig, axes = plt.subplots(1, len(laws), figsize=(5.5 * len(laws), 4.2))
    with open(os.path.join(here, "results.dat"), "w") as f:
        f.write("# law roughness d0 maxRelDevRy ryEnd minGapDEM "
                "minGapTheory\n")
        for law, d0, eps, dev, end, gmin, tgmin, r, (tx, ty) in rows:
            f.write("%s %g %g %.6e %.8f %.6e %.6e\n"
                    % (law.replace(", ", "/"), eps, d0, dev, end, gmin,
                       tgmin))
            ok, ref_end = passes(law, d0, eps, dev, end, gmin, tgmin, y_exit,
                                 tols)
            ok_law[law] = ok_law.get(law, True) and ok
            lines.append("| %s | %g | %g | %.2f %% | %.5f | %.5f | %.3g "
                         "| %.3g | %s |"
                         % (law, eps, d0, 100 * dev, end, ref_end, gmin,
                            tgmin, "yes" if ok else "**no**"))
            if eps != 0:
                continue
            ax = axes[laws.index(law)]
            ax.plot(tx, ty, "k-", lw=0.8)
            ax.plot(r[::20, 0], r[::20, 1], ".", ms=2,
                    label="$d_0$ = %g" % d0)
    for ax, law in zip(axes, laws):
        title = "smooth, %s" % law
        ax.set_xlim(-6, 6)
        ax.set_xlabel("$r_x/a$")
        ax.set_ylabel("$r_y/a$")
        ax.set_title(title + "; lines: two-sphere theory")
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "demPairShear.png"), dpi=120)

    lines += [
        "", "Reference: exact two-sphere mobility in unbounded shear "
        "(fdmResistance.pairShear; Batchelor & Green 1972, the smooth-sphere "
        "trajectories of Da Cunha & Hinch 1996).  Rough pairs whose smooth "
        "trajectory comes closer than eps leave on the theory's trajectory "
        "of minimum gap eps: offset %.5f for eps = %g." % (y_exit, eps_rough),
        "Tolerances: trajectory %g %% (thesis: within 2 %%), fore-aft "
        "symmetry %g d0 for smooth spheres, exit offset %g %% for rough ones;"
        " twoSphere also the minimum gap of smooth pairs within %g %% of "
        "the theory's (issue 37)." % (100 * tols[0], tols[1],
                                      100 * tols[0], 100 * tols[2]), ""]
    lines += ["Result, %s: %s" % (law, "PASS" if ok else "FAIL")
              for law, ok in ok_law.items()]
    lines += ["",
        "## The same law in the overdamped limit (overdampedPair.py)", "",
        "Force and torque balance at each configuration, no inertia, rigid "
        "spheres.  Spin drag factor 1: the Stokes torque of article 1 "
        "(eq 41); 2 pi: the torque of the thesis' script, "
        "-8 pi eta a^3 (2 pi omega - Omega_inf), under which the spheres "
        "turn at 1/(2 pi) of the vorticity.", "",
        "| shearArms | spin drag factor | d0 | max \\|r_y - r_y,th\\|/r_y,th "
        "| min gap | min gap (DEM, same law) |", "|---|---|---|---|---|---|"]
    dem_gap = {(law[len("thesis, "):], d0): gmin
               for law, d0, eps, _, _, gmin, *_ in rows
               if eps == 0 and law.startswith("thesis")}
    for arms, factor, d0, dev, gmin in law_rows:
        lines.append("| %s | %.4g | %g | %.2f %% | %.3g | %s |"
                     % (arms, factor, d0, 100 * dev, gmin,
                        "%.3g" % dem_gap[arms, d0] if factor == 1 else "-"))
    write_markdown(os.path.join(here, "report.md"), lines)
    return all(ok_law.values())
