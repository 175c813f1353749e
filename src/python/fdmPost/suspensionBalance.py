"""Suspension balance model (SBM) predictions of steady volume-fraction
profiles, with the normal-viscosity closures of the literature.

Viscous resuspension (thesis 2, article 3, eqs 2-6): heavy particles
sheared at a uniform rate gammaDot with gravity along direction i (2: the
velocity gradient, 3: the vorticity) balance their weight with the
particle normal stress sigma_ii = -eta_f gammaDot eta_ii(phi):

    phi/Sh = -(d eta_ii/d phi) (d phi/d z)        (eq 3, z = height/a)

with Sh = eta_f gammaDot/(drho g a).  Integrating from z to the top gives
eq 6, eta_ii(phi(z)) = (1/Sh) int_z^inf phi dz', which inverts a measured
profile.  Forward, eq 3 integrates in closed form along phi:

    z(phi) = Sh int_phi^phi_b eta'(s)/s ds,   Sh eta_ii(phi_b) = V

with phi_b the fraction on the floor and V the particle volume per unit
floor area (in a): the floor carries the whole weight.  The top of the
suspension is z(0), finite for the closures below (eta ~ phi^n, n >= 2).

Closures (article 3, eqs 5-10), eta_ii = lambda_ii [r/(1 - r)]^n with
r = phi/phi_m for the literature forms, and the new expressions of article 3:
    eta_22 = r^9/(1 - r)^2 + 150 r^10                       (eq 9)
    eta_33 = lambda_33(phi) eta_22,
    lambda_33 = (phi/phi_rcp)^7.5/(1e-3 + (phi/phi_rcp)^6)   (eq 8; eq 10 as
                printed lacks the exponents)

Plane Poiseuille flow (thesis 1, appendix F): the shear stress is linear,
|sigma_xy| = G |y|, and with the normal stress ratio
Sigma_22(phi) = eta_22(phi)/eta_s(phi) the zero-flux steady state (F.10)
is |y| Sigma_22(phi(y)) = C, clipped at phi_J in the plug; C follows from
the mean volume fraction (F.11).  The migration toward it from a uniform
phi0 is eq F.8b (poiseuille_transient).
"""

import inspect

import numpy as np
from scipy import integrate, optimize

from fdmPost.rheology import maron_pierce
from fdmPost.rheology import morris_boulay as morris_boulay_shear
from fdmPost.rheology import morris_boulay_normal

PHI_RCP = 0.64


def _ratio(phi, phim):
    return np.asarray(phi, float) / phim


def zarraga(phi, component=2, phim=0.62):
    """Zarraga et al. (2000), n = 3: lambda 1.55, 1.36, 0.62."""
    lam = {1: 1.55, 2: 1.36, 3: 0.62}[component]
    r = _ratio(phi, phim)
    return lam * (r / (1 - r))**3


def boyer(phi, component=2, phim=0.585):
    """Boyer et al. (2011), n = 2: lambda_22 = 1 (sigma_22 = P_p,
    article 3 eq 5), lambda_33 = 0.6."""
    lam = {2: 1.0, 3: 0.6}[component]
    r = _ratio(phi, phim)
    return lam * (r / (1 - r))**2


def boyer_friction(phi, phim=0.585, mu1=0.32, mu2=0.7, i0=0.005):
    """Boyer et al. (2011) with their constants: the viscous number J at
    phi (phi = phim/(1 + J^(1/2))), the friction coefficient
    mu(J) = mu1 + (mu2 - mu1)/(1 + I0/J) + J + (5/2) phim J^(1/2) and the
    relative shear viscosity eta_s = mu/J; the particle pressure over the
    shear stress is 1/mu (its normal viscosity 1/J is boyer, component 2).
    Returns (mu, eta_s)."""
    j = (phim / np.asarray(phi, float) - 1) ** 2
    mu = mu1 + (mu2 - mu1) / (1 + i0 / j) + j + 2.5 * phim * np.sqrt(j)
    return mu, mu / j


def morris_boulay(phi, component=2, phim=0.68):
    """Morris & Boulay (1999), n = 2 (fdmPost.rheology.morris_boulay_normal,
    the published K_n = 0.75, lambda = 1, 0.8, 0.5; thesis 2, article 3
    tabulates lambda_33 K_n rounded to 0.38)."""
    return morris_boulay_normal(phi, component, phim)


def lambda33(phi):
    """lambda_33(phi) of article 3 (eq 8; eq 10 prints eta_33 without the
    exponents 7.5 and 6, and eta_33 = lambda_33 eta_22 is the reading that
    gives lambda_33 = 0.2 at phi = 0.25 as the article states)."""
    q = np.asarray(phi, float) / PHI_RCP
    return q**7.5 / (1e-3 + q**6)


def chevremont(phi, component=2, phim=0.58):
    """Article 3's new expressions: eta_22 (eq 9), eta_33 = lambda_33
    eta_22 (eqs 8, 10)."""
    r = _ratio(phi, phim)
    eta22 = r**9 / (1 - r)**2 + 150 * r**10
    return eta22 if component == 2 else lambda33(phi) * eta22


CLOSURES = {"Chevremont (eq 9)": chevremont, "Boyer": boyer,
            "Zarraga": zarraga, "Morris-Boulay": morris_boulay}


def boyer_ratio(phi, component=2, phim=0.585):
    """Particle normal stress over shear stress of Boyer et al. (2011),
    1/mu(J) (boyer_friction), lambda_33 = 0.6 of it: the closure of a bed
    sheared at imposed stress, finite (1/mu_1) at phim."""
    return {2: 1.0, 3: 0.6}[component] / boyer_friction(phi, phim)[0]


def morris_boulay_ratio(phi, component=2, phim=0.68):
    """eta_ii/eta_s of Morris & Boulay (1999), finite (lambda_i K_n/K_s)
    at phim."""
    return morris_boulay(phi, component, phim) \
        / morris_boulay_shear(phi, phim)[0]


# Closures of the ratio Sigma^p_ii/Sigma_12: with the shear stress tau
# imposed (a bed sheared by the fluid above it) the balance of eq 3 reads
# phi/Sh_tau = -(d R/d phi)(d phi/d z), Sh_tau = tau/(drho g a), which
# resuspension_profile solves with R in place of eta_ii and Sh_tau for Sh
RATIO_CLOSURES = {"Boyer": boyer_ratio, "Morris-Boulay": morris_boulay_ratio}


def _derivative(eta, phi, component, h=1e-7):
    return (eta(phi + h, component) - eta(phi - h, component)) / (2 * h)


def resuspension_profile(eta, sh, volume, component=2, n=400):
    """Steady profile of eq 3 for closure eta(phi, component) (one of
    CLOSURES, diverging at its default phim): Shields number sh, particle
    volume per unit floor area `volume` (in a).  Returns z (from the floor,
    increasing, to the top where phi = 0), phi(z) and phi_b."""
    phim = inspect.signature(eta).parameters["phim"].default
    target = volume / sh
    phib = optimize.brentq(lambda p: eta(p, component) - target,
                           1e-6, phim * (1 - 1e-12))
    phis = np.r_[phib * np.cos(np.linspace(0, np.pi / 2, n))[:-1], 0.0]

    def slope(p):
        return _derivative(eta, p, component) / p if p > 0 else 0.0

    z = np.array([sh * integrate.quad(slope, p, phib, limit=200)[0]
                  for p in phis])
    return z, phis, phib


def suspension_height(eta, sh, volume, component=2):
    """Top of the suspension z(phi = 0) in a (eq 3 with the volume)."""
    z, _, _ = resuspension_profile(eta, sh, volume, component)
    return z[-1]


def top_height(z, phi, phi_top=0.05):
    """Height of a suspension: the first z above the densest sample where
    phi drops below phi_top, linearly between samples (z increasing)."""
    z, phi = np.asarray(z, float), np.asarray(phi, float)
    k0 = int(np.argmax(phi))
    k = k0 + int(np.argmax(phi[k0:] < phi_top))
    f = (phi[k - 1] - phi_top) / (phi[k - 1] - phi[k])
    return z[k - 1] + f * (z[k] - z[k - 1])


def centroid(z, phi):
    """Mean height of the particle volume of a profile phi(z)."""
    return np.trapz(z * phi, z) / np.trapz(phi, z)


def normal_viscosity_from_profile(z, phi, sh):
    """Eq 6: eta_ii(z) = (1/Sh) int_z^top phi dz' by the trapezoidal rule
    on the samples (z increasing, phi -> 0 at the top)."""
    z = np.asarray(z, float)
    phi = np.asarray(phi, float)
    seg = 0.5 * (phi[1:] + phi[:-1]) * np.diff(z)
    above = np.r_[np.cumsum(seg[::-1])[::-1], 0.0]
    return above / sh


def poiseuille_profile(sigma22, phi_mean, phi_j, y_max=0.5, n=401):
    """Steady phi(y*) of the plane Poiseuille SBM (appendix F, eqs F.10-F.11):
    |y*| Sigma_22(phi) = C on 0 <= y* <= y_max (half channel, y* in units
    of the channel width), phi = phi_j where C/|y*| exceeds Sigma_22(phi_j)
    (the jammed plug), C chosen so that the mean over [0, y_max] is
    phi_mean.  sigma22(phi) must increase with phi.  Returns (y, phi, C)."""
    y = np.linspace(0, y_max, n)
    top = sigma22(phi_j)

    def profile(c):
        out = np.full_like(y, phi_j)
        for k, yk in enumerate(y):
            if yk > 0 and c / yk < top:
                out[k] = optimize.brentq(lambda p: sigma22(p) - c / yk,
                                         0.0, phi_j)
        return out

    def excess(c):
        return np.trapz(profile(c), y) / y_max - phi_mean

    lo, hi = 1e-12 * top, top * y_max
    c = optimize.brentq(excess, lo, hi)
    return y, profile(c), c


def poiseuille_transient(sigma22, phi0, width, phi_j, times, n=100,
                         abar=1.2, courant=0.4, y_max=0.5):
    """Migration from a uniform phi0 in plane Poiseuille flow (appendix F,
    eq F.8b, half channel):

        d phi/dt* = (8/9)(abar/L_y)^2 d/dy* ( f(phi) d/dy* (|y*| Sigma_22(phi)) )

    with f = (1 - phi)^5.1 (Badia et al. 2022), zero flux at the centre
    plane (symmetry) and at y* = y_max (the wall, F.7, or the edge of the
    wall layers that the thesis leaves out), and the empirical jamming rule
    of section 6.3.2: no flux into a cell at phi_j.  The sign is that of a
    positive particle pressure |y*| Sigma_22: particles move down its
    gradient, toward the centre.  Finite volumes on n cells of
    0 <= y* <= y_max (width = L_y/a1, abar in a1), explicit steps at the
    given fraction of the diffusive limit; the volume is conserved to
    round-off.  Returns (y, {t: phi(y)} for t in times)."""
    dy = y_max / n
    y = (np.arange(n) + 0.5) * dy
    k = 8.0 / 9.0 * (abar / width) ** 2
    phi = np.full(n, float(phi0))
    pending = sorted(float(t) for t in times)
    out, t = {}, 0.0
    while pending:
        f = (1 - phi) ** 5.1
        s22 = sigma22(phi)
        pressure = y * s22
        # local diffusivity k f |y| dSigma_22/dphi sets the stable step
        dp = y * (sigma22(np.minimum(phi + 1e-6, phi_j)) - s22) / 1e-6
        diffusivity = k * np.max(f * np.abs(dp)) + 1e-300
        dt = min(courant * dy**2 / diffusivity, pending[0] - t)
        flux = -k * 0.5 * (f[1:] + f[:-1]) * np.diff(pressure) / dy
        # faces between cells i, i+1: positive flux goes to i+1
        receiver = np.where(flux > 0, phi[1:], phi[:-1])
        flux[receiver >= phi_j] = 0.0
        flux = np.r_[0.0, flux, 0.0]
        phi = phi - dt * np.diff(flux) / dy
        t += dt
        if t >= pending[0] - 1e-12:
            out[pending.pop(0)] = phi.copy()
    return y, out


def poiseuille_velocity(y, phi, eta_s):
    """u*(y*) of eq F.8a, du*/dy* = -4 y*/eta_s(phi(y*)), no slip at the
    wall y* = y[-1] (y from the centre plane, in channel widths, velocity
    in gammaDot_0 L_y); zero shear rate where eta_s is infinite (plug)."""
    y = np.asarray(y, float)
    with np.errstate(divide="ignore"):
        rate = np.where(np.isfinite(eta_s(phi)), 4 * y / eta_s(phi), 0.0)
    seg = 0.5 * (rate[1:] + rate[:-1]) * np.diff(y)
    return np.r_[np.cumsum(seg[::-1])[::-1], 0.0]


def morris_boulay_poiseuille(phi_j):
    """Morris & Boulay (1999) closures with phi_m = phi_J: relative shear
    viscosity eta_s(phi) (fdmPost.rheology.morris_boulay) and the
    normal-to-shear stress ratio Sigma_22(phi) = eta_22/eta_s that
    appendix F needs (its Badia et al. 2022 fits are not in the thesis);
    phi is held just below phi_J so that the plug has a finite, huge
    eta_s."""
    def below(phi):
        return np.minimum(np.asarray(phi, float), phi_j * (1 - 1e-12))

    def eta_s(phi):
        return morris_boulay_shear(below(phi), phi_j)[0]

    def sigma22(phi):
        return morris_boulay(below(phi), 2, phi_j) / eta_s(phi)
    return eta_s, sigma22


def maron_pierce_poiseuille(phi_j, alpha=0.803):
    """The thesis' own viscosity fit (eq 4.12, alpha = 0.803, from its
    Couette runs at mu = 0.5) as the eta_s of eq F.8a, infinite from phi_J
    on (the plug, where the fit's (1 - phi/phi_J)^-2 would turn finite
    again).  Only the velocity depends on it: phi(y) of eqs F.8b and F.10
    depends on Sigma_22 alone."""
    def eta_s(phi):
        phi = np.asarray(phi, float)
        with np.errstate(divide="ignore"):
            return np.where(phi < phi_j, maron_pierce(phi, alpha, phi_j),
                            np.inf)
    return eta_s


def sweep_poiseuille(fit):
    """The closures fitted to this project's Couette sweep (fdmPost.sweep
    .fit_sweep, tutorials/couette/thesisSweep/results/sweepFit.json):
    eta_s of eq 4.12 with the fitted alpha and phi_J (infinite from phi_J
    on, as maron_pierce_poiseuille) and hat Sigma^c_22 = beta
    (phi/phi_J)^n, held at its value at phi_J in the plug."""
    from fdmPost.sweep import contact_normal_closure
    phi_j = fit["phiJ"]

    def sigma22(phi):
        phi_r = np.minimum(np.asarray(phi, float), phi_j) / phi_j
        return contact_normal_closure(phi_r, fit["beta"], fit["n"])
    return maron_pierce_poiseuille(phi_j, fit["alpha"]), sigma22
