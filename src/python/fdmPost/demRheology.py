"""Simple-shear rheology of lubricatedDEMFoam runs and the model of thesis 2
(Chevremont 2020, article 2, eqs 13-16).

The time series postProcessing/lubricatedDEM/<t0>/stress.dat holds the
particle stress (compression < 0) split into normal contact (NC), shear
contact (SC), normal lubrication (NL) and shear lubrication (SL); eta_r
counts the particle stress only, as the thesis does.
"""

import glob
import os

import numpy as np

from fdmPost.particleCase import series_files, series_rows
from fdmPost.rheology import block_mean
from fdmPost.suspensionBalance import PHI_RCP, lambda33

PARTS = ("normalContact", "shearContact", "normalLubrication",
         "shearLubrication")

# Article 2 constants (eqs 14-16)
MU1, MU2, I0, INTRINSIC = 0.36, 0.7, 0.0133, 2.5


def phi_m(mu_m, p0=0.6301, dp=0.0794, mu_star=0.4032):
    """Maximum flowing fraction against contact friction (eq 13; the
    constants as arguments for fitting its form)."""
    return p0 - dp * (1 - np.exp(-np.asarray(mu_m) / mu_star))


# Article 2's roughness eps (section II.C), that of the runs read with
# its radius (validation/demFrictionSweep and demPressureShear)
ARTICLE2_ROUGHNESS = 2e-2


def article2_phi(phi, roughness):
    """The volume fraction of article 2's radius for spheres run with this
    DEM's law (article 1) at phi.  Article 2 puts the asperities inside
    the radius a: contact on the overlap (eqs 2-5), lubrication on
    h = u_n + eps a (eqs 6-9).  Article 1 puts them outside: contact at a
    surface gap eps a, lubrication on that gap.  So article 2's spheres of
    radius a are article 1's of radius a (1 - eps/2), to O(eps^2), and
    their volume fraction is phi (1 - eps/2)^-3."""
    return np.asarray(phi) * (1 - 0.5 * roughness) ** -3


def master_phi_m(phi, iv):
    """phi_m of a run at phi and I_v through the master curve
    phi/phi_m = 1/(1 + I_v^(1/2)) (eq 15)."""
    return np.asarray(phi) * (1 + np.sqrt(iv))


def fit_phi_m(phi, iv):
    """phi_m as article 2 fixed it: the value for which
    1 - phi/phi_m against I_v is one power law, fitted with its prefactor
    and exponent, phi = phi_m/(1 + c I_v^n), over runs at one friction.
    Returns (phi_m, c, n) and their standard errors.  With n fixed at 1/2
    (master_phi_m, one run) the runs far from jamming of a weakly
    frictional packing put phi_m too high when n is above 1/2."""
    from scipy.optimize import curve_fit
    phi, iv = np.asarray(phi, float), np.asarray(iv, float)
    if len(phi) < 4:
        raise ValueError("fit_phi_m needs at least 4 runs (3 parameters)")
    start = (master_phi_m(phi, iv)[np.argmin(iv)], 1.0, 0.5)
    p, cov = curve_fit(lambda i, pm, c, n: pm / (1 + c * i**n), iv, phi,
                       p0=start, maxfev=20000)
    return p, np.sqrt(np.diag(cov))


def viscous_number(phi, phim):
    """I_v from phi/phi_m = 1/(1 + I_v^(1/2)) (eq 15)."""
    return (phim / phi - 1) ** 2


def model_mu_contact(iv, mu1=MU1, mu2=MU2, i0=I0):
    """Contact part of eq 14, mu_c = mu_1 + (mu_2 - mu_1)/(1 + I_0/I_v)
    (constants as arguments for fitting)."""
    return mu1 + (mu2 - mu1) / (1 + i0 / np.asarray(iv))


def model_mu_hydrodynamic(iv, phi):
    """Hydrodynamic part of eq 14, mu_h = I_v (1 - phi)^-[eta]."""
    return iv * (1 - phi) ** -INTRINSIC


def model_mu(iv, phim):
    """mu(I_v) = mu_c + mu_h (eq 14), phi from eq 15."""
    return (model_mu_contact(iv)
            + model_mu_hydrodynamic(iv, phim / (1 + np.sqrt(iv))))


def model_eta(phi, phim):
    """eta_r(phi) (eq 16); the last term is the lubrication part."""
    x = (phim / phi - 1) ** 2
    return MU1 / x + (MU2 - MU1) / (x + I0) + (1 - phi) ** -INTRINSIC


def model_lambda33(phi, phi_rcp=PHI_RCP):
    """lambda_33 = sigma_33/sigma_22 of article 3: the linear fit (eq 7)
    and the smooth one (eq 8), independent of friction (article 3,
    section III.A)."""
    return 2.1 * (np.asarray(phi, float) - phi_rcp) + 1, lambda33(phi)


STRESSLET_PARTS = ("normalContact", "shearContact", "normalLubrication",
                   "shearLubrication")


def state_files(case):
    """(time, path) of every <case>/<time>/particleState, in time order."""
    return sorted((float(os.path.basename(os.path.dirname(p))), p)
                  for p in glob.glob(os.path.join(case, "*", "particleState")))


def dem_state(path):
    """One lubricatedDEMFoam particleState: position, velocity (relative to
    the affine flow) N x 3, radius N, mobile N (bool) and stresslet N x 6
    (xx xy xz yy yz zz), the sum of its contact and lubrication parts, and
    stressletContact, its contact parts alone."""
    from .particleCase import read_list
    with open(path) as f:
        text = f.read()
    parts = {part: read_list(text, "stresslet_" + part, 6)
             for part in STRESSLET_PARTS}
    return {"position": read_list(text, "position", 3),
            "velocity": read_list(text, "velocity", 3),
            "radius": read_list(text, "radius", 1),
            "mobile": read_list(text, "mobile", 1) > 0.5,
            "stresslet": sum(parts.values()),
            "stressletContact": sum(parts[p] for p in STRESSLET_PARTS
                                    if p.endswith("Contact"))}


def read_series(case):
    """The stress.dat rows of a case, restarts in time order, one row per
    time."""
    try:
        files = series_files(case, "lubricatedDEM", "stress")
    except FileNotFoundError as e:
        raise SystemExit(str(e))
    eta, rate = series_header(files[0])
    return series_rows(files), eta, rate


COMPONENTS = ("xx", "yy", "zz", "xy")


def stress_column(d, part, component):
    """One stress component of one part (PARTS) from the rows d of a stress
    series: after time strain phi interactions contacts stabilityNumber,
    xx yy zz xy per part."""
    return d[:, 6 + 4 * PARTS.index(part) + COMPONENTS.index(component)]


def series_header(path):
    """Viscosity and shear rate from the first line of a stress series
    (lubricatedDEMFoam's stress.dat, or a file in its layout)."""
    with open(path) as f:
        head = f.readline()
    eta = float(head.split("viscosity")[1].split(",")[0])
    rate = float(head.split("shear rate")[1])
    return eta, rate


def finished(case):
    """Whether lubricatedDEMFoam ran to its end time in case: the last
    line of its log that is not blank is 'End: ...'.  A killed or failed
    run averages over a shorter window and must not stand in for a
    finished one."""
    log = os.path.join(case, "log.lubricatedDEMFoam")
    if not os.path.isfile(log):
        return False
    with open(log) as f:
        lines = [line for line in f.read().splitlines() if line.strip()]
    return bool(lines) and lines[-1].startswith("End:")


def averages(case, start_strain, blocks=5):
    """Time averages after start_strain with block standard errors: eta_r,
    mu = sigma_xy/P, P = -sigma_yy, N1/sigma_xy, N2/sigma_xy, lambda_11,
    lambda_33, the share of
    each part in sigma_xy, phi, contacts per particle pair list."""
    d, eta, rate = read_series(case)
    return series_averages(d, eta, rate, start_strain, blocks), d, eta, rate


def series_averages(d, eta, rate, start_strain, blocks=5):
    """averages() of the rows d of a stress series; also the mean
    interaction count and, as (mean, standard error), the contact share of
    sigma_xy (contactShare) and the record-wise mu and lambda_33 (muBlocks,
    lambda33Blocks)."""
    d = d[d[:, 1] >= start_strain]
    if len(d) < blocks:
        raise SystemExit("too few records after strain %g" % start_strain)
    s = {c: sum(stress_column(d, n, c) for n in PARTS) for c in COMPONENTS}
    part_xy = {n: stress_column(d, n, "xy") for n in PARTS}
    scale = eta * abs(rate)
    out = {"phi": d[0, 2], "records": len(d),
           "strain": (d[0, 1], d[-1, 1])}
    out["eta_r"] = block_mean(s["xy"] / scale, blocks)
    out["P"] = block_mean(-s["yy"] / scale, blocks)
    xy, P = out["eta_r"][0], out["P"][0]
    out["mu"] = xy / P
    out["N1"] = block_mean((s["xx"] - s["yy"]) / scale, blocks)[0] / xy
    out["N2"] = block_mean((s["yy"] - s["zz"]) / scale, blocks)[0] / xy
    # Normal stress ratios of article 3 (section III.A): lambda_11 = s11/s22,
    # lambda_33 = s33/s22
    out["lambda11"] = block_mean(-s["xx"] / scale, blocks)[0] / P
    out["lambda33"] = block_mean(-s["zz"] / scale, blocks)[0] / P
    out["Iv"] = 1 / P
    out["share"] = {n: part_xy[n].mean() / (scale * xy) for n in PARTS}
    out["contacts"] = d[:, 4].mean()
    out["interactions"] = d[:, 3].mean()
    out["contactShare"] = block_mean(
        (part_xy["normalContact"] + part_xy["shearContact"]) / s["xy"],
        blocks)
    out["muBlocks"] = block_mean(s["xy"] / -s["yy"], blocks)
    out["lambda33Blocks"] = block_mean(s["zz"] / s["yy"], blocks)
    return out
