#!/usr/bin/env python3
"""Report of the two-sphere shear validation of the lubricated contact model
(run.py): table, verdict and demPairShear.png."""

import os

from fdmPost.report import write_markdown  # noqa: E402


def write(here, rows, law_rows, y_exit, eps_rough, cutoff, tol_traj,
          tol_sym):
    """rows: (shearArms, d0, eps, max relative r_y deviation, r_y at +6,
    min gap, theory's min gap, r (N x 3), theory curve (tx, ty));
    law_rows: (shearArms, spin drag factor, d0, deviation, min gap) of the
    overdamped law."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lines = [
        "# Two spheres in simple shear, lubricated contact model + Stokes "
        "drag (thesis 2, article 1, section 3.2)", "",
        "Lubrication cut-off %g a, g/(eta gammaDot a) = 1e5, Stokes number "
        "1e-3, friction 0; sphere 2 starts at r = (-6, d0, 0)." % cutoff,
        "",
        "| shearArms | roughness | d0 | max \\|r_y - r_y,th\\|/r_y,th "
        "| r_y at r_x = 6 | reference r_y at 6 | min gap (DEM) "
        "| min gap (theory) | pass |",
        "|---|---|---|---|---|---|---|---|---|"]
    ok_all = True
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    with open(os.path.join(here, "results.dat"), "w") as f:
        f.write("# shearArms roughness d0 maxRelDevRy ryEnd minGapDEM "
                "minGapTheory\n")
        for arms, d0, eps, dev, end, gmin, tgmin, r, (tx, ty) in rows:
            f.write("%s %g %g %.6e %.8f %.6e %.6e\n"
                    % (arms, eps, d0, dev, end, gmin, tgmin))
            if eps == 0:
                ref_end = d0
                ok = dev <= tol_traj and abs(end - d0) <= tol_sym * d0
            elif tgmin < eps:
                # smooth trajectory dips below the asperities: exit on the
                # theory's trajectory of minimum gap eps
                ref_end = y_exit
                ok = abs(end - y_exit) <= tol_traj * y_exit
            else:
                # never touches: the smooth trajectory, reversible
                ref_end = d0
                ok = dev <= tol_traj and abs(end - d0) <= tol_traj * d0
            ok_all = ok_all and ok
            lines.append("| %s | %g | %g | %.2f %% | %.5f | %.5f | %.3g "
                         "| %.3g | %s |"
                         % (arms, eps, d0, 100 * dev, end, ref_end, gmin,
                            tgmin, "yes" if ok else "**no**"))
            if eps != 0:
                continue
            ax = axes[0 if arms == rows[0][0] else 1]
            ax.plot(tx, ty, "k-", lw=0.8)
            ax.plot(r[::20, 0], r[::20, 1], ".", ms=2,
                    label="$d_0$ = %g" % d0)
    for ax, arms in zip(axes, (rows[0][0], rows[-1][0])):
        title = "smooth, shearArms %s" % arms
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
        "symmetry %g d0 for smooth spheres, exit offset %g %% for rough ones."
        % (100 * tol_traj, tol_sym, 100 * tol_traj), "",
        "Result: %s" % ("PASS" if ok_all else "FAIL"), "",
        "## The same law in the overdamped limit (overdampedPair.py)", "",
        "Force and torque balance at each configuration, no inertia, rigid "
        "spheres.  Spin drag factor 1: the Stokes torque of article 1 "
        "(eq 41); 2 pi: the torque of the thesis' script, "
        "-8 pi eta a^3 (2 pi omega - Omega_inf), under which the spheres "
        "turn at 1/(2 pi) of the vorticity.", "",
        "| shearArms | spin drag factor | d0 | max \\|r_y - r_y,th\\|/r_y,th "
        "| min gap | min gap (DEM, same law) |", "|---|---|---|---|---|---|"]
    dem_gap = {(arms, d0): gmin for arms, d0, eps, _, _, gmin, *_ in rows
               if eps == 0}
    for arms, factor, d0, dev, gmin in law_rows:
        lines.append("| %s | %.4g | %g | %.2f %% | %.3g | %s |"
                     % (arms, factor, d0, 100 * dev, gmin,
                        "%.3g" % dem_gap[arms, d0] if factor == 1 else "-"))
    write_markdown(os.path.join(here, "report.md"), lines)
    return ok_all
