"""The article3 family of Allrun for analyse.py: lambda_33 = sigma_33/
sigma_22 with article 3's spheres and pairs against its fits (eqs 7 and
8), which it states independent of friction (article 3, section III.A),
and the normal viscosities eta_22 = sigma_22/(eta gammaDot) = 1/I_v and
eta_33 = lambda_33 eta_22 against its eq 9 and eqs 8-9 at phi/phi_m (eq 13's
phi_m at the run's friction, as article 3 takes phi_m from article 2)."""

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost.demRheology import model_lambda33, phi_m  # noqa: E402
from fdmPost.suspensionBalance import chevremont  # noqa: E402

# The target of issue 37: lambda_33 within 5 % of eqs 7-8
TOLERANCE = 0.05


def lambda33_family(rows, lines, title, png):
    """Table (mu_m, phi, lambda_33 with its block standard error, eqs 7 and
    8, the deviation from each) and plot of lambda_33(phi) against both."""
    if not rows:
        return
    rows = sorted(rows, key=lambda r: (r["mu_m"], r["phi"]))
    lines += ["", "## lambda_33 against article 3's eqs 7-8 (%s)" % title, "",
              "Record-wise sigma_33/sigma_22 averaged over strain 2 to the "
              "end, with its block standard error; target within %d %% of "
              "eqs 7-8." % round(100 * TOLERANCE), "",
              "| mu_m | phi | I_v | lambda_33 | eq 7 | eq 8 | vs eq 7 "
              "| vs eq 8 | phi/phi_m | eta_22 = 1/I_v | eq 9 | eta_33 "
              "| eqs 8-9 |", "|---|---|---|---|---|---|---|---|---|---|---|"
              "---|---|"]
    for r in rows:
        l7, l8 = model_lambda33(r["phi"])
        lam, err = r["lambda33"], r["lambda33Err"]
        phim = float(phi_m(r["mu_m"]))
        lines.append("| %g | %.3f | %.3g | %.3f ± %.3f | %.3f | %.3f "
                     "| %+.1f %% | %+.1f %% | %.3f | %.3g | %.3g | %.3g "
                     "| %.3g |"
                     % (r["mu_m"], r["phi"], r["Iv"], lam, err, l7, l8,
                        100 * (lam / l7 - 1), 100 * (lam / l8 - 1),
                        r["phi"] / phim, 1 / r["Iv"],
                        chevremont(r["phi"], 2, phim), lam / r["Iv"],
                        chevremont(r["phi"], 3, phim)))
    fig, ax = plt.subplots(figsize=(5.5, 4))
    x = np.linspace(0.3, 0.62, 100)
    l7, l8 = model_lambda33(x)
    ax.plot(x, l7, "k--", label="article 3, eq 7")
    ax.plot(x, l8, "k-", label="article 3, eq 8")
    ax.fill_between(x, (1 - TOLERANCE) * l8, (1 + TOLERANCE) * l8,
                    color="0.85", label="eq 8 ± %d %%"
                    % round(100 * TOLERANCE))
    for k, mu in enumerate(sorted({r["mu_m"] for r in rows})):
        sel = [r for r in rows if r["mu_m"] == mu]
        ax.errorbar([r["phi"] for r in sel], [r["lambda33"] for r in sel],
                    yerr=[r["lambda33Err"] for r in sel], fmt="o",
                    color="C%d" % k, capsize=3, label=r"$\mu_m$ = %g" % mu)
    ax.set_xlabel(r"$\phi$")
    ax.set_ylabel(r"$\lambda_{33} = \sigma_{33}/\sigma_{22}$")
    ax.set_title(title, fontsize=8)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    plt.close(fig)
