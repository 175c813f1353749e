"""The Couette sweep of thesis 1 (section 4.2.2, Table 4.7): the reduced
data of each point, the Maron-Pierce fit of eq 4.12 with its
uncertainty, and the contact normal stress closure hat Sigma^c_22(phi/phi_J)
that the suspension balance model of appendix F needs (eq F.8b), fitted
to the same points.

Reduced data: one row per point, the core rheology of
fdmPost.rheology.core_rheology (mean and standard error of each
quantity), the strain reached, the records averaged and the box, in a CSV
file that plotSweep.py writes and rebuilds its plot from.
"""

import csv

import numpy as np
from scipy import optimize

from fdmPost.rheology import maron_pierce

QUANTITIES = ("phiCore", "gammaDotCore", "etaCore", "contactShare", "N1",
              "N2", "contact11", "contact22", "contact33")
HEADER = (["case", "strain", "start", "records", "Lx", "Ly", "Lz"]
          + [f"{q}{s}" for q in QUANTITIES for s in ("", "Err")])


# Thesis 1, Table 4.7: phi0 -> (phi_core, gammaDot_core/gammaDot_0) in the
# thesis' boxes (L_x = L_y = 20 a1, 25 a1 above phi0 0.45; L_z = 20 a1)
TABLE_4_7 = {0.27: (0.303, 0.923), 0.32: (0.359, 0.885), 0.37: (0.405, 0.873),
             0.42: (0.458, 0.773), 0.47: (0.493, 0.745), 0.52: (0.543, 0.563),
             0.54: (0.570, 0.391)}


def phi0_of(case):
    """The nominal fraction phi0 of a runPoint case name (phi0.42_10x20x10,
    phi0.42_20x20, phi0.42_10x20x10_G4: 0.42)."""
    return float(case[len("phi"):].split("_")[0])


def wall_layer(ly):
    """The wall layer runPoint leaves out of the core: the thesis' 5 a1
    from a wall separation of 20 a1 on, a quarter of it below."""
    return 5.0 if ly >= 20 else ly / 4


# The strain the averages of a finished point start at (the transient of
# the thesis' runs); a run shorter than three times that averages from a
# third of it and is still in its transient
STEADY_START = 5.0


def averaging_start(strain):
    """Where runPoint's averages start for a run that reached strain."""
    return STEADY_START if strain >= 3 * STEADY_START else strain / 3


def in_transient(row):
    """Whether a point's run is shorter than three times STEADY_START."""
    return row["strain"] < 3 * STEADY_START


def point_row(case, strain, start, box, rheology):
    """One row of the reduced data: a case name, the strain reached, the
    strain the averages start at, the box edges and a core_rheology dict."""
    row = {"case": case, "strain": strain, "start": start,
           "records": rheology["records"],
           "Lx": box[0], "Ly": box[1], "Lz": box[2]}
    for q in QUANTITIES:
        row[q], row[q + "Err"] = rheology[q]
    return row


def write_points(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, HEADER)
        w.writeheader()
        for row in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v)
                        for k, v in row.items()})


def read_points(path):
    """The rows of write_points, numbers as floats (records as int)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        for k in HEADER[1:]:
            row[k] = float(row[k])
        row["records"] = int(row["records"])
    return rows


def fit_maron_pierce(phi, eta, err):
    """Weighted least squares of eq 4.12, eta = alpha/(1 - phi/phi_J)^2,
    to points with standard errors err.  Started from the straight line
    eta^(-1/2) = alpha^(-1/2) (1 - phi/phi_J); returns (alpha, phi_J) and
    their covariance (errors taken as absolute), or None with fewer than
    three points."""
    phi, eta, err = (np.asarray(v, float) for v in (phi, eta, err))
    if len(phi) < 3:
        return None
    # eta^(-1/2) has the error err/(2 eta^(3/2))
    b1, b0 = np.polyfit(phi, eta ** -0.5, 1, w=2 * eta ** 1.5 / err)
    start = (b0 ** -2, -b0 / b1)
    p, cov = optimize.curve_fit(maron_pierce, phi, eta, p0=start, sigma=err,
                                absolute_sigma=True)
    return p, cov


def contact_normal_closure(phi_r, beta, n):
    """hat Sigma^c_22 = beta (phi/phi_J)^n, the magnitude of the contact
    normal stress over the shear stress (eq F.4), finite and increasing
    up to jamming as the steady state of eq F.10 needs."""
    return beta * np.asarray(phi_r, float) ** n


def fit_contact_normal(phi_r, s22, err):
    """Weighted least squares of contact_normal_closure to the measured
    magnitudes |hat Sigma^c_22| at phi/phi_J = phi_r; returns (beta, n)
    and their covariance, or None with fewer than three points."""
    phi_r, s22, err = (np.asarray(v, float) for v in (phi_r, s22, err))
    if len(phi_r) < 3:
        return None
    # Straight line in logarithms for the start
    n, logb = np.polyfit(np.log(phi_r), np.log(s22), 1)
    p, cov = optimize.curve_fit(contact_normal_closure, phi_r, s22,
                                p0=(np.exp(logb), n), sigma=err,
                                absolute_sigma=True)
    return p, cov


def fit_sweep(rows):
    """Both fits of a sweep (rows of read_points): a dict of alpha, phiJ,
    beta, n with their standard errors and covariances, None where there
    are fewer than three points.  The closure is fitted against
    phi_core/phi_J of the fitted phi_J.  A point without an error bar (a
    run too short for block errors) or one still in its transient (a run
    shorter than three times STEADY_START) is left out."""
    rows = [r for r in rows
            if np.isfinite(r["etaCoreErr"]) and r["etaCoreErr"] > 0
            and not in_transient(r)]
    phi = np.array([r["phiCore"] for r in rows])
    mp = fit_maron_pierce(phi, [r["etaCore"] for r in rows],
                          [r["etaCoreErr"] for r in rows])
    if mp is None:
        return None
    (alpha, phi_j), cov = mp
    # Compressive contact normal stress only (a dilute point may have none)
    s22 = np.array([-r["contact22"] for r in rows])
    err = np.array([r["contact22Err"] for r in rows])
    keep = s22 > 0
    cn = fit_contact_normal(phi[keep] / phi_j, s22[keep], err[keep])
    (beta, n), cov_n = cn if cn is not None else \
        ((np.nan, np.nan), np.full((2, 2), np.nan))
    return {"alpha": alpha, "alphaErr": np.sqrt(cov[0, 0]),
            "phiJ": phi_j, "phiJErr": np.sqrt(cov[1, 1]),
            "maronPierceCovariance": cov.tolist(),
            "beta": beta, "betaErr": np.sqrt(cov_n[0, 0]),
            "n": n, "nErr": np.sqrt(cov_n[1, 1]),
            "contactNormalCovariance": cov_n.tolist(),
            "points": len(rows)}
