#!/usr/bin/python3
"""Simple-shear sweeps of Allrun against thesis 2, article 2 (eqs 13-16):
per run the averages over strain 2-5 (fdmPost.demRheology.averages) are
merged into results.dat here (so the report can be redone without the
runs); then

  friction family (cut-off 2a and the Delaunay pairs, phi 0.48 and 0.52):
      phi_m = phi (1 + I_v^1/2) from the master curve, against eq 13, and
      eq 13's form fitted;
  phi family (mu_m = 0.4, cut-offs 2a, 1a and the Delaunay pairs): mu(I_v)
      split into its
      contact part mu_c, fitted with eq 14's mu_c = mu_1 + (mu_2 - mu_1)/
      (1 + I_0/I_v), and its lubrication part mu_L against eq 14's
      mu_h = I_v (1 - phi)^-5/2; eta_r against eq 16;
  article 2's spheres with radius arms, every friction: phi_m fitted as
      article 2 did (demRheology.fit_phi_m over the runs with I_v < 0.15);
  one change at a time (sensitivity.dat, variants.py), phi_m fitted so
      for a change with enough runs;
  article 3's spheres and pairs: lambda_33 against its eqs 7-8
      (normalStresses.py);

writes report.md, the phiMax*.png, muIv.png, torques.png and lambda33.png
here; runs without the End line in their log (killed, failed) are skipped.

    analyse.py [WORKDIR]

No pass/fail target: the known excess dissipation of this DEM's pair law
with the cut-off 2a (validation/README.md, DEM section) is what the
tables measure.
"""

import glob
import os
import re
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "src", "python"))

import numpy as np  # noqa: E402
from scipy.optimize import curve_fit  # noqa: E402
import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost.demRheology import (ARTICLE2_ROUGHNESS, averages,  # noqa: E402
                                 article2_phi,
                                 finished, fit_phi_m,
                                 master_phi_m, phi_m, model_eta, model_mu,
                                 model_mu_contact, model_mu_hydrodynamic,
                                 MU1, MU2, I0)
from fdmPost.report import write_markdown  # noqa: E402
from variants import VARIANTS, sensitivity, torques_figure  # noqa: E402
from normalStresses import lambda33_family  # noqa: E402

RESULTS = os.path.join(HERE, "results.dat")
SENSITIVITY = os.path.join(HERE, "sensitivity.dat")
COLUMNS = ("mu_m", "phiNominal", "cutoff", "phi", "Iv", "mu", "eta_r",
           "eta_rErr", "muContact", "muLubrication", "lambda33",
           "lambda33Err")
# The cutoff column of the Delaunay pairs (run name cutD), of the
# Delaunay pairs with article 2's spheres (cutA: one radius, 5 %
# polydispersity, roughness 2e-2), of those with shearArms radius (cutR)
# and of those with article 2's law (cutL: asperities inside); article 3's
# spheres and pairs (cutT: 5 % polydispersity, roughness 1e-3, cut-off 2a,
# radius arms)
DELAUNAY, ARTICLE2, ARTICLE2_RADIUS, ARTICLE2_LAW, ARTICLE3 = 0, -1, -2, -3, -4
PAIRS = {"D": DELAUNAY, "A": ARTICLE2, "R": ARTICLE2_RADIUS,
         "L": ARTICLE2_LAW, "T": ARTICLE3}
# The small-I_v range of article 2's power law 1 - phi/phi_m ~ I_v^n
# (10^-4 - 10^-1), with room for the run at 0.13
SMALL_IV = 0.15


def pairs_name(cutoff):
    """The pair set of a cutoff column value, for tables and legends."""
    return {DELAUNAY: "Delaunay pairs",
            ARTICLE2: "Delaunay pairs, article 2's spheres",
            ARTICLE2_RADIUS: "Delaunay pairs, article 2's spheres, "
                             "radius arms",
            ARTICLE2_LAW: "article 2's law (asperities inside), Delaunay "
                          "pairs, radius arms",
            ARTICLE3: "article 3's spheres and pairs (cut-off 2a), "
                      "radius arms"}.get(
                cutoff, "cut-off %ga" % cutoff)
CONTACT = ("normalContact", "shearContact")


def measure(work):
    """Rows (dicts) of the runs in work."""
    rows = []
    for case in glob.glob(os.path.join(work, "mu*_phi*_cut*")):
        m = re.search(r"mu([\d.]+)_phi([\d.]+)_cut([\d.]+|[DARLT])"
                      r"(?:_([a-z][\w.]*))?$", case)
        if not finished(case):
            # A killed run's shorter window must not replace a finished
            # run's row (it once did)
            print("skipped %s: not finished (no End line in its log)" % case)
            continue
        try:
            a, _, _, _ = averages(case, 2.0)
        except SystemExit as e:
            print("skipped %s: %s" % (case, e))
            continue
        contact = sum(a["share"][p] for p in CONTACT)
        row = dict(zip(COLUMNS, (
            float(m.group(1)), float(m.group(2)),
            PAIRS.get(m.group(3)) if m.group(3) in PAIRS
            else float(m.group(3)),
            a["phi"], a["Iv"], a["mu"], a["eta_r"][0], a["eta_r"][1],
            contact * a["mu"], (1 - contact) * a["mu"], a["lambda33"],
            a["lambda33Blocks"][1])))
        row["variant"] = m.group(4)
        rows.append(row)
    return rows


def merged(new, path=RESULTS, variants=False):
    """The rows of path (results.dat, or with variants sensitivity.dat,
    whose first column names the variant) with the new ones replacing
    equal keys."""
    columns = (("variant",) if variants else ()) + COLUMNS
    rows = {}
    if os.path.exists(path):
        for line in open(path):
            if not line.startswith("#"):
                v = line.split()
                # rows written before a column was added lack it
                r = dict.fromkeys(COLUMNS, float("nan"))
                r.update(zip(COLUMNS, map(float, v[1:] if variants
                                               else v)))
                r["variant"] = v[0] if variants else None
                rows[r["variant"], r["mu_m"], r["phiNominal"],
                     r["cutoff"]] = r
    for r in new:
        if (r["variant"] is not None) == variants:
            rows[r["variant"], r["mu_m"], r["phiNominal"], r["cutoff"]] = r
    out = sorted(rows.values(), key=lambda r: (
        r["variant"] or "", r["cutoff"], r["mu_m"], r["phiNominal"]))
    with open(path, "w") as f:
        f.write("# " + " ".join(columns) + "  (averages over strain 2 to"
                " the end; analyse.py)\n")
        for r in out:
            f.write(" ".join(([r["variant"]] if variants else [])
                             + ["%.6g" % r[c] for c in COLUMNS]) + "\n")
    return out


def article2_spheres(cutoff):
    """Whether the runs of a cutoff column value use article 2's spheres,
    whose volume fraction is read at article 2's radius"""
    return cutoff in (ARTICLE2, ARTICLE2_RADIUS)


def friction_family(rows, lines, cutoff, png):
    sel = [r for r in rows if r["cutoff"] == cutoff
           and r["phiNominal"] in (0.48, 0.52)]
    if not sel:
        return None
    phi_name = "phi" + ("' (article 2's radius)"
                        if article2_spheres(cutoff) else "")
    lines += ["## phi_m against the contact friction (%s)"
              % pairs_name(cutoff), "",
              "| mu_m | %s | I_v | mu | eta_r | phi_m = phi (1 + I_v^1/2) "
              "| eq 13 | difference |" % phi_name,
              "|---|---|---|---|---|---|---|---|"]
    for r in sel:
        phi = (float(article2_phi(r["phi"], ARTICLE2_ROUGHNESS))
               if article2_spheres(cutoff) else r["phi"])
        r["phim"] = float(master_phi_m(phi, r["Iv"]))
        lines.append("| %g | %.4f | %.4g | %.3f | %.1f | %.4f | %.4f | %+.4f |"
                     % (r["mu_m"], phi, r["Iv"], r["mu"], r["eta_r"],
                        r["phim"], phi_m(r["mu_m"]),
                        r["phim"] - phi_m(r["mu_m"])))
    mus = sorted({r["mu_m"] for r in sel})
    spread = [np.ptp([r["phim"] for r in sel if r["mu_m"] == m]) for m in mus]
    lines += ["", "Spread of phi_m between the two volume fractions: "
              + ", ".join("%.4f (mu_m %g)" % (s, m)
                          for s, m in zip(spread, mus)) + "."]
    mean = [np.mean([r["phim"] for r in sel if r["mu_m"] == m]) for m in mus]

    fit = None
    if len(mus) >= 3:
        fit, _ = curve_fit(phi_m, mus, mean, p0=(0.63, 0.08, 0.4))
        lines += ["", "Eq 13's form phi_m = p0 - dp (1 - exp(-mu_m/m*)) "
                  "fitted to the mean phi_m per friction: p0 = %.4f, "
                  "dp = %.4f, m* = %.3f (article 2: 0.6301, 0.0794, 0.4032)."
                  % tuple(fit)]
    fig, ax = plt.subplots(figsize=(5, 4))
    m = np.linspace(0, 1.2, 100)
    ax.plot(m, phi_m(m), "r--", label="article 2, eq 13")
    if fit is not None:
        ax.plot(m, phi_m(m, *fit), "k:", label="eq 13 form fitted")
    for phi in (0.48, 0.52):
        s = [r for r in sel if r["phiNominal"] == phi]
        ax.plot([r["mu_m"] for r in s], [r["phim"] for r in s], "o",
                label=r"DEM, $\phi$ = %.2f" % phi)
    ax.set_xlabel(r"$\mu_m$")
    ax.set_ylabel(r"$\phi_m = \phi\,(1 + I_v^{1/2})$")
    ax.legend()
    ax.set_title(pairs_name(cutoff))
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, png), dpi=120)
    return fit


def power_law_phi_m(rows, lines, cutoff, png, change=None):
    """phi_m per friction as article 2 fixed it (demRheology.fit_phi_m:
    phi' = phi_m/(1 + c I_v^n) over every run at that friction, n free),
    against eq 13; eq 13's form fitted to them.  Plot (png): phi_m(mu_m)
    and 1 - phi'/phi_m against I_v (power_law_figure), none without png.
    change: the variant the rows share, for the title."""
    fam = [r for r in rows if r["cutoff"] == cutoff and r["Iv"] < SMALL_IV]
    mus = [m for m in sorted({r["mu_m"] for r in fam})
           if sum(r["mu_m"] == m for r in fam) >= 4]
    if not mus:
        return
    lines += ["", "## phi_m fitted as article 2 did (%s%s)"
              % (pairs_name(cutoff), ", " + change if change else ""),
              "", "phi' = phi_m/(1 + c I_v^n) over the runs at one friction "
              "with I_v < %g (n free; article 2 chose phi_m so that "
              "1 - phi/phi_m against I_v is one power law at small I_v, "
              "10^-4 - 10^-1), phi' at article 2's radius; standard errors "
              "of the fit." % SMALL_IV, "",
              "| mu_m | runs | phi' | I_v | phi_m fitted | n | eq 13 "
              "| difference | phi' (1 + I_v^1/2), run nearest jamming |",
              "|---|---|---|---|---|---|---|---|---|"]
    fits = []
    for m in mus:
        sel = sorted((r for r in fam if r["mu_m"] == m), key=lambda r: r["Iv"])
        phi = article2_phi([r["phi"] for r in sel], ARTICLE2_ROUGHNESS)
        iv = np.array([r["Iv"] for r in sel])
        (pm, c, n), err = fit_phi_m(phi, iv)
        fits.append(dict(mu=m, phi=phi, iv=iv, pm=pm, c=c, n=n, err=err[0]))
        lines.append("| %g | %d | %.3f-%.3f | %.2g-%.2g | %.4f ± %.4f "
                     "| %.2f ± %.2f | %.4f | %+.4f | %.4f |"
                     % (m, len(sel), phi.min(), phi.max(), iv.min(),
                        iv.max(), pm, err[0], n, err[2], phi_m(m),
                        pm - phi_m(m), master_phi_m(phi[0], iv[0])))
    form = None
    if len(fits) >= 4:
        form, cov = curve_fit(phi_m, [f["mu"] for f in fits],
                              [f["pm"] for f in fits], p0=(0.63, 0.08, 0.4),
                              sigma=[f["err"] for f in fits],
                              absolute_sigma=True)
        lines += ["", "Eq 13's form fitted to these phi_m (weighted): "
                  "p0 = %.4f ± %.4f, dp = %.4f ± %.4f, m* = %.3f ± %.3f "
                  "(article 2: 0.6301, 0.0794, 0.4032)."
                  % (form[0], np.sqrt(cov[0, 0]), form[1],
                     np.sqrt(cov[1, 1]), form[2], np.sqrt(cov[2, 2]))]
    if png:
        power_law_figure(fits, form, pairs_name(cutoff), png)


def power_law_figure(fits, form, title, png):
    """phi_m(mu_m) of the power-law fits (with eq 13's form fitted to them
    where form is given) and 1 - phi'/phi_m against I_v per friction."""
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for k, f in enumerate(fits):
        axes[1].loglog(f["iv"], 1 - f["phi"] / f["pm"], "o", color="C%d" % k,
                       label=r"$\mu_m$ = %g" % f["mu"])
        x = np.logspace(np.log10(f["iv"].min()), np.log10(f["iv"].max()))
        cx = f["c"] * x**f["n"]
        axes[1].loglog(x, cx / (1 + cx), "-", color="C%d" % k, lw=0.8)
    mu = np.linspace(0, 1.2, 100)
    if form is not None:
        axes[0].plot(mu, phi_m(mu, *form), "k:", label="eq 13 form fitted")
    axes[0].plot(mu, phi_m(mu), "r--", label="article 2, eq 13")
    axes[0].errorbar([f["mu"] for f in fits], [f["pm"] for f in fits],
                     yerr=[f["err"] for f in fits], fmt="ko", capsize=3,
                     label="DEM, fitted power law")
    axes[0].set_xlabel(r"$\mu_m$")
    axes[0].set_ylabel(r"$\phi_m$ (article 2's radius)")
    axes[0].legend(fontsize=8)
    axes[1].set_xlabel("$I_v$")
    axes[1].set_ylabel(r"$1 - \phi'/\phi_m$")
    axes[1].legend(fontsize=8)
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, png), dpi=120)
    plt.close(fig)


def law_against_mapping(rows, lines):
    """Article 2's law (asperities inside) against this DEM's law read at
    article 2's radius, at the same phi' and friction."""
    law = [r for r in rows if r["cutoff"] == ARTICLE2_LAW]
    if not law:
        return
    mapped = [r for r in rows if r["cutoff"] == ARTICLE2_RADIUS]
    lines += ["", "## Article 2's law against the radius mapping", "",
              "Each run with asperities inside (contact on the overlap, "
              "lubrication on u_n + eps a) beside the radius-arms run whose "
              "phi' = phi (1 - eps/2)^-3 is its phi (within 1e-3: whole "
              "spheres).", "",
              "| mu_m | phi' | I_v law / mapped | mu law / mapped "
              "| mu_c law / mapped | eta_r law / mapped | eta_r / eq 16 law "
              "|", "|---|---|---|---|---|---|---|"]
    for r in sorted(law, key=lambda r: (r["mu_m"], r["phiNominal"])):
        twin = [q for q in mapped if q["mu_m"] == r["mu_m"] and abs(
            float(article2_phi(q["phi"], ARTICLE2_ROUGHNESS)) - r["phi"])
            < 1e-3]
        if not twin:
            continue
        q = twin[0]
        lines.append("| %g | %.4f | %.4g / %.4g | %.3f / %.3f | %.3f / %.3f "
                     "| %.1f ± %.1f / %.1f ± %.1f | %.2f |"
                     % (r["mu_m"], r["phi"], r["Iv"], q["Iv"], r["mu"],
                        q["mu"], r["muContact"], q["muContact"], r["eta_r"],
                        r["eta_rErr"], q["eta_r"], q["eta_rErr"],
                        r["eta_r"] / model_eta(r["phi"], phi_m(r["mu_m"]))))


def article2_radius_lines(sel, phim):
    """The rows of article 2's spheres read at article 2's radius
    (demRheology.article2_phi): eta_r against eq 16 and phi_m there."""
    out = ["", "Read at article 2's radius, phi' = phi (1 - eps/2)^-3 "
           "(eps %g):" % ARTICLE2_ROUGHNESS, "",
           "| phi' | eta_r / eq 16 at phi' | phi' (1 + I_v^1/2) |",
           "|---|---|---|"]
    for r in sel:
        p = float(article2_phi(r["phi"], ARTICLE2_ROUGHNESS))
        out.append("| %.4f | %.2f | %.4f |"
                   % (p, r["eta_r"] / model_eta(p, phim),
                      master_phi_m(p, r["Iv"])))
    return out


def phi_family(rows, lines):
    fam = [r for r in rows if r["mu_m"] == 0.4]
    cuts = sorted({r["cutoff"] for r in fam}, reverse=True)
    if not fam:
        return
    phim = phi_m(0.4)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    iv = np.logspace(-4, 0.3, 200)
    phi_iv = phim / (1 + np.sqrt(iv))
    ax = axes[0]
    ax.loglog(iv, model_mu(iv, phim), "k-", label="eq 14, $\\mu$")
    ax.loglog(iv, model_mu_contact(iv), "k--", label="eq 14, $\\mu_c$")
    ax.loglog(iv, model_mu_hydrodynamic(iv, phi_iv), "k:",
              label="eq 14, $\\mu_h$")
    for k, cut in enumerate(cuts):
        sel = sorted((r for r in fam if r["cutoff"] == cut),
                     key=lambda r: r["Iv"])
        x = np.array([r["Iv"] for r in sel])
        lines += ["", "## mu(I_v) at mu_m = 0.4, %s" % pairs_name(cut), "",
                  "| phi | I_v | mu | eq 14 at I_v | mu_c | mu_L "
                  "| I_v (1 - phi)^-5/2 | eta_r | eq 16 at phi "
                  "| phi (1 + I_v^1/2) |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        for r in sel:
            model = model_mu(r["Iv"], phim)
            lines.append(
                "| %.3f | %.4g | %.3f | %.3f | %.3f | %.3f | %.3f "
                "| %.1f ± %.1f | %.1f | %.4f |"
                % (r["phi"], r["Iv"], r["mu"], model, r["muContact"],
                   r["muLubrication"],
                   model_mu_hydrodynamic(r["Iv"], r["phi"]),
                   r["eta_r"], r["eta_rErr"], model_eta(r["phi"], phim),
                   master_phi_m(r["phi"], r["Iv"])))
        if article2_spheres(cut):
            lines += article2_radius_lines(sel, phim)
        if len(sel) >= 4:
            p, cov = curve_fit(model_mu_contact, x,
                               [r["muContact"] for r in sel],
                               p0=(MU1, MU2, I0), bounds=(0, [2, 5, 1]))
            err = np.sqrt(np.diag(cov))
            lines += ["", "Contact part fitted with eq 14's form: mu_1 = "
                      "%.3f ± %.3f, mu_2 = %.3f ± %.3f, I_0 = %.4f ± %.4f "
                      "(article 2: 0.36, 0.7, 0.0133)."
                      % (p[0], err[0], p[1], err[1], p[2], err[2])]
            ax.loglog(iv, model_mu_contact(iv, *p), "--", color="C%d" % k,
                      lw=0.8)
        ratio = [r["muLubrication"] / model_mu_hydrodynamic(r["Iv"], r["phi"])
                 for r in sel]
        lines += ["", "mu_L / (I_v (1 - phi)^-5/2): %s."
                  % ", ".join("%.2f" % v for v in ratio)]
        ax.loglog(x, [r["mu"] for r in sel], "o", color="C%d" % k,
                  label="DEM $\\mu$, %s" % pairs_name(cut))
        ax.loglog(x, [r["muContact"] for r in sel], "s", mfc="none",
                  color="C%d" % k, label="DEM $\\mu_c$, %s" % pairs_name(cut))
        ax.loglog(x, [r["muLubrication"] for r in sel], "^", mfc="none",
                  color="C%d" % k, label="DEM $\\mu_L$, %s" % pairs_name(cut))
        axes[1].semilogy([r["phi"] for r in sel], [r["eta_r"] for r in sel],
                         "o", color="C%d" % k,
                         label="DEM, %s" % pairs_name(cut))
    ax.set_xlabel("$I_v$")
    ax.set_ylabel(r"$\mu$")
    ax.legend(fontsize=7)
    phi = np.linspace(0.25, 0.56, 100)
    axes[1].semilogy(phi, model_eta(phi, phim), "k-", label="eq 16")
    axes[1].set_xlabel(r"$\phi$")
    axes[1].set_ylabel(r"$\eta_r$")
    axes[1].legend(fontsize=8)
    fig.suptitle(r"$\mu_m$ = 0.4; article 2 with $\phi_m$ = %.4f (eq 13)"
                 % phim)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "muIv.png"), dpi=120)


def main():
    new = measure(sys.argv[1]) if len(sys.argv) > 1 else []
    rows = merged(new)
    variants = merged(new, SENSITIVITY, variants=True)
    lines = ["# Simple-shear sweeps against thesis 2, article 2", "",
             "Generated by `analyse.py` (`Allrun`): tri-periodic Lees-Edwards "
             "cell of tutorials/lubricatedShear (333 bidisperse spheres "
             "1:1.4, roughness 1e-2), averages over strain 2-5; mu = "
             "sigma_xy/P, P = -sigma_yy; mu_c and mu_L its contact and "
             "lubrication parts.", ""]
    friction_family(rows, lines, 2, "phiMax.png")
    friction_family(rows, lines, DELAUNAY, "phiMaxDelaunay.png")
    friction_family(rows, lines, ARTICLE2_RADIUS, "phiMaxArticle2.png")
    power_law_phi_m(rows, lines, ARTICLE2_RADIUS, "phiMaxArticle2Fit.png")
    phi_family(rows, lines)
    base = [r for r in rows if r["cutoff"] == ARTICLE2_RADIUS]
    sensitivity(base, variants, lines, pairs_name(ARTICLE2_RADIUS),
                ARTICLE2_ROUGHNESS)
    for v in sorted({r["variant"] for r in variants}):
        power_law_phi_m([r for r in variants if r["variant"] == v], lines,
                        ARTICLE2_RADIUS, None, VARIANTS.get(v, v))
    torques_figure(base, variants, ARTICLE2_ROUGHNESS, SMALL_IV,
                   os.path.join(HERE, "torques.png"))
    law_against_mapping(rows, lines)
    lambda33_family([r for r in rows if r["cutoff"] == ARTICLE3], lines,
                    pairs_name(ARTICLE3), os.path.join(HERE, "lambda33.png"))
    write_markdown(os.path.join(HERE, "report.md"), lines)


if __name__ == "__main__":
    main()
