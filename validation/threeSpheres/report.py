#!/usr/bin/env python3
"""Report of the three-sphere validation (run.py): tables against the
Stokesian-dynamics reference with exact pairs (fdmResistance.threeSphere,
unbounded fluid), report.md and threeSpheres.png here.

Targets, fixed before the runs (the published code: about 2 % on the shear
cases):
* triangle: u_x of each sphere after the box correction, the relative
  velocity u_x(1) - u_x(2,3) (no correction: it has no Stokeslet), |u_y|
  and |Omega_z| of spheres 2, 3, each within 3 % of the reference, or
  within 0.003 F/(6 pi eta a) where 3 % of the value is smaller than that;
* shear: mean deviation over the 9 numbers of a configuration (U_x, U_y,
  Omega_z of A, B, C) at most 2 % and the largest at most 5 % of the
  largest velocity (units gamma_dot a) or angular velocity of that
  configuration.

The reference is exact for two spheres; for three its many-body part is
the far field (O(r^-3) reflections), so close triplets may differ from the
exact solution by up to a few per cent (Durlofsky, Brady & Bossis 1987).
The tables also give the pairwise-additive values (exact pairs, no
many-body part): their distance from the reference is the weight of the
many-body interaction, of which the reference's own error is a part.
"""

import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmResistance import pairShear, threeSphere  # noqa: E402
from run import TRIANGLE_SIDES  # noqa: E402

TRI_REL, TRI_ABS = 0.03, 0.003
# Below this side the place of sphere 2 is less than 2 a from sphere 1's
# surface, where the field of the single-sphere run carries the solver's own
# near-field error (~0.004, as large as the box part of u_y): there sphere
# 1's box velocity is applied to all three spheres as a uniform drift
NEAR_FIELD = 3.0
SHEAR_MEAN, SHEAR_MAX = 0.02, 0.05


def load():
    """dict (kind, config, radius) -> arrays U, W of shape
    (positions, spheres, 3)."""
    rows = {}
    for line in open(os.path.join(HERE, "results.dat")):
        if line.startswith("#"):
            continue
        w = line.split()
        key = (w[0], w[1], float(w[2]))
        pos = tuple(map(float, w[3:6]))
        rows.setdefault(key, {}).setdefault(pos, {})[int(w[6])] = (
            np.array(w[10:13], float), np.array(w[13:16], float))
    out = {}
    for key, by_pos in rows.items():
        U = np.array([[by_pos[p][k][0] for k in sorted(by_pos[p])]
                      for p in sorted(by_pos)])
        W = np.array([[by_pos[p][k][1] for k in sorted(by_pos[p])]
                      for p in sorted(by_pos)])
        out[key] = (U, W)
    return out


def triangle_quantities(U, W):
    """Per position: u_x(1), u_x(2,3) mean, difference, |u_y(2,3)|,
    |Omega_z(2,3)| (arrays over positions)."""
    ux1 = U[:, 0, 0]
    ux23 = 0.5 * (U[:, 1, 0] + U[:, 2, 0])
    uy = 0.5 * (U[:, 1, 1] - U[:, 2, 1])
    wz = 0.5 * (W[:, 1, 2] - W[:, 2, 2])
    return np.array([ux1, ux23, ux1 - ux23, uy, wz])


TRI_NAMES = ("u_x(1)", "u_x(2,3)", "u_x(1) - u_x(2,3)", "u_y(2) = -u_y(3)",
             "Omega_z(2) = -Omega_z(3)")


def triangle_reference(side, many_body=True):
    x = threeSphere.cluster("triangle", side)
    U, W = threeSphere.velocities(x, forces=[[6 * np.pi, 0, 0], [0, 0, 0],
                                             [0, 0, 0]], many_body=many_body)
    return triangle_quantities(U[None], W[None])[:, 0]


def shear_reference(config, many_body=True):
    x = threeSphere.cluster(config, 2.01)
    U, W = threeSphere.velocities(x, E=pairShear.E_INF, W=pairShear.W_INF,
                                  many_body=many_body)
    return np.hstack([U[:, :2], W[:, 2:]])          # rows A, B, C


def triangle_section(data, kernel, lines):
    sides = sorted((k[1] for k in data if k[0] == "triangle"
                    and k[1] != "single"), key=float)
    lines += ["## Triangle, sphere 1 pushed (thesis 4.1.5, Tables 4.2-4.4)",
              "",
              "Units F/(6 pi eta a) (angular: F/(6 pi eta a^2)); mean over "
              "%d positions in a cell, relative standard deviation in "
              "brackets. FDM box 16 a x 16 a x 12 a (walls y = +-8 a); "
              "'corrected' removes the box velocity of a pushed single "
              "sphere (run.box_kernel). Reference: Stokesian dynamics with "
              "exact pairs, unbounded." % len(data[("triangle", sides[0],
                                                      1.0)][0]), ""]
    single = data.get(("triangle", "single", 1.0))
    if kernel is not None and single is not None:
        # sphere 1: the mean over the same cell positions as the clusters
        kernel = kernel.copy()
        k1 = single[0][:, 0].mean(axis=0) - [1.0, 0.0, 0.0]
        lines += ["Box velocity of a single pushed sphere: %+.4f at its "
                  "centre (U_single - 1, mean of %d positions; %+.4f in the "
                  "field run); at sphere 2's place for r = %s: u_x %s, "
                  "u_y %s, Omega_z %s. These correct sphere 2 and 3 for "
                  "r >= %g; closer, the single-sphere field there carries "
                  "the solver's own near-field error (about 0.004, as large "
                  "as the box part of u_y), and sphere 1's box velocity is "
                  "taken as a uniform drift of all three." % (
                      k1[0], len(single[0]), kernel[0, 0], ", ".join(sides),
                      ", ".join("%+.4f" % k for k in kernel[1:, 0]),
                      ", ".join("%+.4f" % k for k in kernel[1:, 1]),
                      ", ".join("%+.4f" % k for k in kernel[1:, 3]),
                      NEAR_FIELD), ""]
        kernel[0, :3] = k1
    else:
        kernel = None
    lines += ["| r | quantity | FDM raw | FDM corrected | reference | "
              "deviation | within target | pairwise additive |",
              "|---|---|---|---|---|---|---|---|"]
    results, ok_all = [], True
    for s in sides:
        U, W = data[("triangle", s, 1.0)]
        q = triangle_quantities(U, W)
        mean, std = q.mean(axis=1), q.std(axis=1)
        corr = mean.copy()
        if kernel is not None:
            i = TRIANGLE_SIDES.index(float(s))
            # closer than NEAR_FIELD: sphere 1's box velocity for all three
            # (a uniform drift; its K_y and rotation are zero by symmetry)
            k1 = kernel[0]
            k2 = (kernel[1 + i] if float(s) >= NEAR_FIELD
                  else np.array([k1[0], 0.0, 0.0, 0.0]))
            corr[0] -= k1[0]
            corr[1] -= k2[0]
            corr[2] -= k1[0] - k2[0]
            corr[3] -= k2[1]
            corr[4] -= k2[3]
        ref = triangle_reference(float(s))
        pairwise = triangle_reference(float(s), many_body=False)
        for j, name in enumerate(TRI_NAMES):
            dev = corr[j] - ref[j]
            tol = max(TRI_REL * abs(ref[j]), TRI_ABS)
            ok = abs(dev) <= tol
            ok_all &= ok
            lines.append("| %s | %s | %.4f (%.1f %%) | %.4f | %.4f | %+.4f "
                         "(%+.1f %%) | %s | %.4f |" % (
                             s, name, mean[j], 100 * std[j] / max(
                                 abs(mean[j]), 1e-12), corr[j], ref[j], dev,
                             100 * dev / max(abs(ref[j]), 1e-12),
                             "yes" if ok else "**no**", pairwise[j]))
        results.append((float(s), corr, std, ref))
    lines.append("")
    return results, ok_all


def shear_section(data, lines):
    lines += ["## Three free spheres in shear, gaps 0.01 a (thesis 4.1.6, "
              "Tables 4.5-4.6)", "",
              "Units gamma_dot a and gamma_dot; B at the centre of a cube of "
              "side 12 a; mean over positions in a cell (relative standard "
              "deviation in brackets). Deviation in per cent of the largest "
              "velocity (angular velocity) of the configuration.", ""]
    ok_all, results = True, {}
    for config in ("aligned", "L"):
        radii = sorted(k[2] for k in data if k[0] == "shear"
                       and k[1] == config)
        if not radii:
            continue
        ref = shear_reference(config)
        scale = np.array([np.abs(ref[:, :2]).max()] * 2
                         + [np.abs(ref[:, 2]).max()])
        pairwise = shear_reference(config, many_body=False)
        head = "| %s | reference | pairwise additive |" % config + "".join(
            " FDM a = %g | deviation |" % a for a in radii)
        lines += [head, "|---|---|---|" + "---|---|" * len(radii)]
        meas = {}
        for a in radii:
            U, W = data[("shear", config, a)]
            v = np.concatenate([U[:, :, :2] / a, W[:, :, 2:]], axis=2)
            meas[a] = (v.mean(axis=0), v.std(axis=0))
        for i, sphere in enumerate("ABC"):
            for j, name in enumerate(("U_x", "U_y", "Omega_z")):
                row = "| %s %s | %+.4f | %+.4f |" % (name, sphere,
                                                     ref[i, j],
                                                     pairwise[i, j])
                for a in radii:
                    m, s = meas[a]
                    row += " %+.4f (%.1f %%) | %+.1f %% |" % (
                        m[i, j], 100 * s[i, j] / max(abs(m[i, j]), 1e-12),
                        100 * (m[i, j] - ref[i, j]) / scale[j])
                lines.append(row)
        summary = []
        for a in radii:
            dev = np.abs(meas[a][0] - ref) / scale
            ok = dev.mean() <= SHEAR_MEAN and dev.max() <= SHEAR_MAX
            ok_all &= ok
            summary.append("a = %g: mean %.1f %%, largest %.1f %% (%s)" % (
                a, 100 * dev.mean(), 100 * dev.max(),
                "within target" if ok else "**outside target**"))
        lines += ["", "Deviation, %s: %s." % (config, "; ".join(summary)),
                  ""]
        results[config] = (ref, meas)
    return results, ok_all


def plot(tri, shear):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    if tri:
        rr = 2 + np.geomspace(0.005, 4.2, 18)   # fine near contact
        ref = np.array([triangle_reference(r) for r in rr]).T
        sides = [t[0] for t in tri]
        ax = axes[0]
        for j, c in zip((0, 1, 2), ("C0", "C1", "C2")):
            ax.plot(rr, ref[j], c, label=TRI_NAMES[j] + " reference")
            ax.errorbar(sides, [t[1][j] for t in tri],
                        [t[2][j] for t in tri], fmt="o", color=c,
                        label="FDM")
        ax.set_xlabel("r / a")
        ax.set_ylabel("velocity / (F / 6 pi eta a)")
        ax.legend(fontsize=7)
        ax = axes[1]
        for j, c in zip((3, 4), ("C3", "C4")):
            ax.plot(rr, ref[j], c, label=TRI_NAMES[j] + " reference")
            ax.errorbar(sides, [t[1][j] for t in tri],
                        [t[2][j] for t in tri], fmt="o", color=c,
                        label="FDM")
        ax.set_xlabel("r / a")
        ax.legend(fontsize=7)
        ax.set_title("triangle, sphere 1 pushed")
    ax = axes[2]
    labels = ["%s %s" % (n, s) for s in "ABC"
              for n in ("Ux", "Uy", "Wz")]
    x = np.arange(9)
    width = 0.25
    for k, config in enumerate(shear):
        ref, meas = shear[config]
        off = 10 * k
        ax.bar(x + off - width, ref.ravel(), width, color="k",
               label="reference" if k == 0 else None)
        for i, a in enumerate(sorted(meas)):
            ax.bar(x + off + i * width, meas[a][0].ravel(), width,
                   color="C%d" % i,
                   label="FDM a = %g" % a if k == 0 else None)
        ax.text(off + 3, 1.6, config)
    ax.set_xticks(list(x) + list(x + 10))
    ax.set_xticklabels(labels * 2, rotation=90, fontsize=6)
    ax.set_title("three free spheres in shear: aligned | L")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "threeSpheres.png"), dpi=120)


def main():
    data = load()
    kernel_path = os.path.join(HERE, "boxKernel.dat")
    kernel = np.loadtxt(kernel_path) if os.path.exists(kernel_path) else None
    lines = ["# Three spheres (thesis 1, sections 4.1.5-4.1.6)", ""]
    tri, ok_tri = ([], True)
    if any(k[0] == "triangle" for k in data):
        tri, ok_tri = triangle_section(data, kernel, lines)
    shear, ok_shear = shear_section(data, lines)
    ok = ok_tri and ok_shear and kernel is not None
    lines += ["Targets: triangle %g %% (or %g absolute), shear mean %g %% and "
              "largest %g %%." % (100 * TRI_REL, TRI_ABS, 100 * SHEAR_MEAN,
                                  100 * SHEAR_MAX), "",
              "Result: %s" % ("PASS" if ok else "FAIL")]
    with open(os.path.join(HERE, "report.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    plot(tri, shear)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
