"""The article2sensitivity runs of Allrun (sensitivity.dat: one change
each to a run of the article2radius family) for analyse.py: the table of
each beside the run it changes, and the figure of the three rolling and
twisting torque settings (thesis, article 2's code, none) against eqs 14
and 16 at mu_m 0.4."""

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost.demRheology import (article2_phi, phi_m,  # noqa: E402
                                 model_eta, model_mu, model_mu_contact)

VARIANTS = {"box24": "24 a cell (16 a)", "kt0.3": "k_t/g 0.3 (0.5)",
            "kt2": "k_t/g 2 (0.5)",
            "g1e7": "stiffness 1e7 (1e6), step / 10^1/2",
            "strain10": "strain 2-10 (2-5)",
            "noTorques": "no rolling and twisting torques",
            "codeTorques": "rolling torque of article 2's code (3/20)"}

# The torque settings of the figure: base rows (torques thesis) and the
# variants that change only the torques
TORQUES = ((None, "torques thesis (rolling 3/2)"),
           ("codeTorques", "torques article2Code (rolling 3/20)"),
           ("noTorques", "torques none"))


def sensitivity(base, variants, lines, title, roughness):
    """Each variant row beside its base row (same friction, nominal phi
    and pairs): mu and mu_c against eq 14 at the run's I_v, eta_r against
    eq 16 at its phi' (article 2's radius, roughness) with eq 13's
    phi_m."""
    if not variants:
        return
    by_run = {(r["mu_m"], r["phiNominal"], r["cutoff"]): r for r in base}
    lines += ["", "## One change at a time (%s)" % title,
              "", "phi' at article 2's radius; eq 14 at the run's I_v, eq 16 "
              "at its phi' with eq 13's phi_m at its friction.", "",
              "| mu_m | phi' | run | I_v | mu | eq 14 | mu_c | eq 14's mu_c "
              "| eta_r | eta_r / eq 16 | lambda_33 |",
              "|---|---|---|---|---|---|---|---|---|---|---|"]
    shown = []
    for r in sorted(variants, key=lambda r: (r["mu_m"], r["phiNominal"],
                                             r["variant"])):
        b = by_run.get((r["mu_m"], r["phiNominal"], r["cutoff"]))
        runs = [(VARIANTS.get(r["variant"], r["variant"]), r)]
        if b is not None and b not in shown:
            shown.append(b)
            runs.insert(0, ("as above", b))
        phim = phi_m(r["mu_m"])
        for name, x in runs:
            p = float(article2_phi(x["phi"], roughness))
            lines.append("| %g | %.4f | %s | %.4g | %.3f | %.3f | %.3f "
                         "| %.3f | %.1f ± %.1f | %.2f | %.3f |"
                         % (x["mu_m"], p, name, x["Iv"], x["mu"],
                            model_mu(x["Iv"], phim),
                            x["muContact"], model_mu_contact(x["Iv"]),
                            x["eta_r"],
                            x["eta_rErr"], x["eta_r"] / model_eta(p, phim),
                            x["lambda33"]))


def torques_figure(base, variants, roughness, iv_max, png, mu_m=0.4):
    """eta_r(phi') against eq 16 and mu(I_v) against eq 14 at mu_m for
    each torque setting, runs with I_v < iv_max, to png."""
    phim = phi_m(mu_m)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    x = np.linspace(0.40, 0.99 * phim, 200)
    axes[0].semilogy(x, model_eta(x, phim), "k--",
                     label="article 2, eq 16 (eq 13's phi_m %.3f)" % phim)
    iv = np.logspace(-3.2, -0.5, 200)
    axes[1].loglog(iv, model_mu(iv, phim), "k--", label="article 2, eq 14")
    for k, (variant, name) in enumerate(TORQUES):
        runs = ([r for r in variants if r["variant"] == variant]
                if variant else base)
        rows = sorted((r for r in runs if r["mu_m"] == mu_m
                       and r["Iv"] < iv_max), key=lambda r: r["phi"])
        if not rows:
            continue
        p = article2_phi([r["phi"] for r in rows], roughness)
        axes[0].errorbar(p, [r["eta_r"] for r in rows],
                         yerr=[r["eta_rErr"] for r in rows], fmt="o-",
                         color="C%d" % k, capsize=3, label=name)
        axes[1].loglog([r["Iv"] for r in rows], [r["mu"] for r in rows],
                       "o-", color="C%d" % k, label=name)
    axes[0].set_xlabel(r"$\phi'$ (article 2's radius)")
    axes[0].set_ylabel(r"$\eta_r$")
    axes[1].set_xlabel("$I_v$")
    axes[1].set_ylabel(r"$\mu$")
    for ax in axes:
        ax.legend(fontsize=7)
    fig.suptitle(r"Delaunay pairs, article 2's spheres, radius arms, "
                 r"$\mu_m$ = %g" % mu_m, fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    plt.close(fig)
