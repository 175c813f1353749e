"""Adhesive suspensions in Couette flow (thesis 1, chapter 5).

With the adhesion number G_0 = F_adh/(6 pi eta a1^2 gammaDot_0) imposed,
a run gives its core shear stress Sigma_12, core shear rate and core
volume fraction; from them (section 5.4)

    eta_app = Sigma_12/(eta gammaDot_0)                    (eq 5.3)
    sigma*  = 6 pi a1^2 Sigma_12/F_adh = eta_app/G_0
            = eta_core/G_core                              (eq 5.4)
    eta_core = Sigma_12/(eta gammaDot_core)                (eq 5.5)

Strong adhesion ends in one or two clusters that do not deform: the core
stops shearing (shear banding, gammaDot_core -> 0, eta_core undefined) or
a clear fluid layer opens at the walls (wall depletion).  Both are
reported instead of a viscosity.  Across runs, eta_core and phi_core are
interpolated at chosen sigma* (section 5.4.3) and eq 4.12 is fitted at
each, eta = alpha(sigma*)/(1 - phi/phi_J(sigma*))^2 (eq 5.7), giving
phi_J(sigma*).
"""

import numpy as np

from fdmPost.checkpoint import series_records
from fdmPost.rheology import channel_case, core_rheology
from fdmPost.sweep import fit_maron_pierce

# gammaDot_core/gammaDot_0 below which the core is taken as not sheared
# (the thesis' banded runs show gammaDot_core "very small or exactly 0")
BANDING_RATE = 0.05
# Mean phi of the wall layers over phi_core below which a clear layer has
# opened at the walls
DEPLETION_RATIO = 0.5


def adhesion_point(rheology, eta, gamma0, g0, phi_wall=None):
    """The quantities of eqs 5.3-5.5 from a core_rheology dict of a run
    with fluid viscosity eta, wall shear rate gamma0 and adhesion number
    g0 (0: no adhesion, sigma* infinite), and its state: 'banding' when
    gammaDot_core/gammaDot_0 < BANDING_RATE (etaCore then NaN),
    'depletion' when the wall layers' mean phi (phi_wall, if given) is
    below DEPLETION_RATIO phi_core, else 'homogeneous'."""
    s12, s12_err = rheology["shearStress"]
    rate = rheology["gammaDotCore"][0] / gamma0
    phi = rheology["phiCore"][0]
    eta_app = s12 / (eta * gamma0)
    state = "homogeneous"
    if phi_wall is not None and phi_wall < DEPLETION_RATIO * phi:
        state = "depletion"
    if rate < BANDING_RATE:
        state = "banding"
    # eq 5.4; without adhesion sigma* is infinite (its error undefined)
    sigma = (eta_app / g0, s12_err / (eta * gamma0 * g0)) if g0 > 0 \
        else (np.inf, np.nan)
    eta_core = rheology["etaCore"] if state != "banding" else (np.nan, np.nan)
    return {"etaApp": (eta_app, s12_err / (eta * gamma0)),
            "sigmaStar": sigma,
            "gammaRatio": rate, "phiCore": rheology["phiCore"],
            "etaCore": eta_core, "state": state, "adhesionNumber": g0}


def adhesion_records(records, start):
    """adhesion_point of a run's core records (fdmPost.coreRecords: a
    checkpoint's or a case's) averaged from strain `start`, the wall
    layers' phi averaged over the same records; with the strain reached
    and the wall phi added."""
    gamma0 = records.meta["shearRate"]
    r = core_rheology(records, start / gamma0)
    phi_wall = float(np.mean(records.phi_wall[records.t * gamma0 >= start]))
    p = adhesion_point(r, records.eta, gamma0,
                       records.meta.get("adhesionNumber", 0.0), phi_wall)
    p.update(strain=records.strain(), phiWall=phi_wall)
    return p


def adhesion_case(case, layer, start):
    """adhesion_records of a Couette case directory, with its phi(y)
    profile (y, phi; a1 bins) averaged from strain `start`."""
    cs, _, run = channel_case(case, layer)
    p = adhesion_records(series_records(cs, run, case), start)
    steps = np.flatnonzero(cs.t * run["shearRate"] >= start)
    p["y"], p["phi"], _ = cs.profiles(int(round(cs.span[cs.n])), steps)
    p["case"] = case
    return p


def interpolate_at_stress(series, levels):
    """Section 5.4.3: in each series (the runs of one phi_0, dicts with
    sigmaStar, phiCore, etaCore as (mean, error), banded runs left out),
    log eta_core and phi_core linearly in log sigma* at each level inside
    the series' range (no extrapolation), the relative error of eta_core
    likewise.  Returns {level: (phi, eta, eta_err)} arrays, one entry per
    series that covers the level."""
    out = {s: ([], [], []) for s in levels}
    for runs in series:
        runs = [r for r in runs if np.isfinite(r["etaCore"][0])
                and np.isfinite(r["sigmaStar"][0])]
        runs.sort(key=lambda r: r["sigmaStar"][0])
        if len(runs) < 2:
            continue
        x = np.log([r["sigmaStar"][0] for r in runs])
        log_eta = np.log([r["etaCore"][0] for r in runs])
        rel = [r["etaCore"][1] / r["etaCore"][0] for r in runs]
        phi = [r["phiCore"][0] for r in runs]
        for s in levels:
            if not x[0] <= np.log(s) <= x[-1]:
                continue
            e = np.exp(np.interp(np.log(s), x, log_eta))
            out[s][0].append(np.interp(np.log(s), x, phi))
            out[s][1].append(e)
            out[s][2].append(e * np.interp(np.log(s), x, rel))
    return {s: tuple(np.array(v) for v in out[s]) for s in levels}


def jamming_fraction(series, levels):
    """Eq 5.7 at each sigma* level from interpolate_at_stress: {level:
    (alpha, phi_J, their standard errors, points)} where at least three
    series cover the level."""
    fits = {}
    for s, (phi, eta, err) in interpolate_at_stress(series, levels).items():
        fit = fit_maron_pierce(phi, eta, err)
        if fit is None:
            continue
        (alpha, phi_j), cov = fit
        fits[s] = (alpha, phi_j, np.sqrt(cov[0, 0]), np.sqrt(cov[1, 1]),
                   len(phi))
    return fits
