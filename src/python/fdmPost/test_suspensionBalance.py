"""Unit tests of fdmPost.suspensionBalance: the closures against their
values at 3 significant figures (article 3, eqs 5-10), the resuspension profile
against the closed form of a quadratic closure and against eq 3 itself,
the eq 6 inversion, the Poiseuille zero-flux profile against its
closed form for a linear closure, and the Poiseuille migration (eq F.8b)
against that profile and its own scaling."""

import unittest

import numpy as np
from scipy import optimize

from fdmPost import suspensionBalance as sbm


def quadratic(phi, component=2, phim=2.0):
    """eta = phi^2/2: eq 3 gives the linear profile phi = phi_b - z/Sh."""
    return 0.5 * np.asarray(phi, float)**2


class Closures(unittest.TestCase):

    def test_spec_table_values(self):
        # article 3 closures (phi_m = 0.58 for eq 9; each literature form with
        # its own phi_m), three significant figures
        cases = [
            (sbm.chevremont, 2, 0.174, 9.26e-4), (sbm.chevremont, 2, 0.290, 0.154),
            (sbm.chevremont, 2, 0.464, 19.5), (sbm.chevremont, 3, 0.174, 3.78e-5),
            (sbm.chevremont, 3, 0.290, 0.0422), (sbm.chevremont, 3, 0.464, 11.9),
            (sbm.boyer, 2, 0.290, 0.966), (sbm.boyer, 2, 0.551, 263),
            (sbm.zarraga, 2, 0.290, 0.923), (sbm.zarraga, 3, 0.290, 0.421),
        ]
        for eta, comp, phi, ref in cases:
            self.assertAlmostEqual(eta(phi, comp) / ref, 1, delta=6e-3,
                                   msg=f"{eta.__name__} {comp} {phi}")
        # Morris-Boulay eta_33: the table rounds lambda_33 K_n = 0.375 to
        # 0.38, so the published constants sit 0.375/0.38 - 1 = -1.3 % below
        for phi, ref in ((0.290, 0.210), (0.551, 6.93)):
            self.assertAlmostEqual(sbm.morris_boulay(phi, 3) / ref,
                                   0.375 / 0.38, delta=6e-3, msg=f"MB {phi}")

    def test_lambda33_limits(self):
        # article 3, eqs 7-8: about 0.2 at phi = 0.25, about 1 at phi_rcp
        self.assertAlmostEqual(float(sbm.lambda33(0.25)), 0.2, delta=0.05)
        self.assertAlmostEqual(float(sbm.lambda33(0.64)), 1.0, delta=0.01)


class Resuspension(unittest.TestCase):

    def test_quadratic_closure_gives_the_linear_profile(self):
        sh, volume = 3.0, 2.0
        z, phi, phib = sbm.resuspension_profile(quadratic, sh, volume)
        self.assertAlmostEqual(phib, np.sqrt(2 * volume / sh), places=9)
        self.assertLess(np.abs(phi - (phib - z / sh)).max(), 1e-6)
        self.assertAlmostEqual(z[-1], sh * phib, places=6)

    def test_profile_conserves_volume_and_solves_eq3(self):
        for name, eta in sbm.CLOSURES.items():
            for sh in (0.5, 4.0):
                z, phi, phib = sbm.resuspension_profile(eta, sh, 8.0)
                self.assertAlmostEqual(np.trapz(phi, z) / 8.0, 1, delta=1e-4)
                self.assertAlmostEqual(sh * eta(phib, 2), 8.0, delta=1e-8)
                # eq 3 at interior samples: phi/Sh = -eta'(phi) dphi/dz
                k = slice(5, len(z) // 2)
                dphidz = np.gradient(phi, z)[k]
                deta = (eta(phi[k] + 1e-7, 2) - eta(phi[k] - 1e-7, 2)) / 2e-7
                res = phi[k] / sh + deta * dphidz
                self.assertLess(np.abs(res).max() / (phi[k] / sh).max(),
                                2e-3, msg=f"{name} Sh {sh}")

    def test_eq6_recovers_the_closure(self):
        eta = sbm.chevremont
        z, phi, _ = sbm.resuspension_profile(eta, 2.0, 8.0, n=2000)
        recovered = sbm.normal_viscosity_from_profile(z, phi, 2.0)
        bulk = phi > 0.3 * 0.58
        err = np.abs(recovered[bulk] / eta(phi[bulk], 2) - 1).max()
        self.assertLess(err, 1e-3)


class Poiseuille(unittest.TestCase):

    def test_linear_closure_gives_c_over_y(self):
        # Sigma_22 = phi: phi = C/y, clipped at phi_J inside y_J = C/phi_J;
        # the mean fixes C: phi_J y_J + C ln(y_max/y_J) = mean y_max
        phij, mean, ymax = 0.6, 0.4, 0.5
        y, phi, c = sbm.poiseuille_profile(lambda p: p, mean, phij, ymax,
                                           n=20001)
        exact = optimize.brentq(
            lambda c: c + c * np.log(ymax * phij / c) - mean * ymax,
            1e-6, phij * ymax)
        self.assertAlmostEqual(c / exact, 1, delta=1e-4)
        outside = y > c / phij
        self.assertLess(np.abs(phi[outside] - c / y[outside]).max(), 1e-9)
        self.assertTrue(np.all(phi[~outside] == phij))

    def test_boyer_friction_by_hand(self):
        # J = 0.01 at phi = 0.585/1.1: mu = 0.32 + 0.38/1.5 + 0.01
        # + 2.5 0.585 0.1, eta_s = mu/J, and J -> 1/boyer (eta_n = 1/J)
        mu, eta_s = sbm.boyer_friction(0.585 / 1.1)
        ref = 0.32 + 0.38 / 1.5 + 0.01 + 0.14625
        self.assertAlmostEqual(mu, ref, delta=1e-12)
        self.assertAlmostEqual(eta_s, 100 * ref, delta=1e-9)
        self.assertAlmostEqual(sbm.boyer(0.585 / 1.1, 2), 100, delta=1e-9)

    def test_sweep_closure_steady_profile(self):
        # the fitted power law: |y| Sigma_22(phi(y)) constant outside the
        # plug (eq F.10), the plug at phi_J, the mean phi kept (eq F.11)
        fit = {"alpha": 0.8, "phiJ": 0.6, "beta": 0.5, "n": 2.5}
        eta_s, sigma22 = sbm.sweep_poiseuille(fit)
        self.assertAlmostEqual(sigma22(0.6), 0.5, delta=1e-12)
        self.assertAlmostEqual(sigma22(0.7), 0.5, delta=1e-12)
        y, phi, _ = sbm.poiseuille_profile(sigma22, 0.45, 0.6, n=4001)
        outside = phi < 0.6 * (1 - 1e-9)
        c = y[outside] * sigma22(phi[outside])
        self.assertLess(np.ptp(c) / c.mean(), 1e-6)
        self.assertAlmostEqual(np.trapz(phi, y) / 0.5, 0.45, delta=1e-3)
        self.assertTrue(np.isinf(eta_s(0.6)))

    def test_height_and_centroid_of_a_linear_profile(self):
        # phi = 0.5 (1 - z/4): phi = 0.05 at z = 3.6, centroid 4/3
        z = np.linspace(0, 5, 51)
        phi = np.maximum(0.5 * (1 - z / 4), 0)
        self.assertAlmostEqual(sbm.top_height(z, phi), 3.6, delta=1e-12)
        self.assertAlmostEqual(sbm.centroid(z, phi), 4 / 3, delta=1e-3)

    def test_ratio_closures(self):
        # Boyer: 1/mu at J = 0.01 (phi = 0.585/1.1), 1/mu_1 at phim;
        # Morris-Boulay: lambda_2 K_n/K_s = 6 at phim
        mu = 0.32 + 0.38 / 1.5 + 0.01 + 0.14625
        self.assertAlmostEqual(sbm.boyer_ratio(0.585 / 1.1), 1 / mu, 12)
        self.assertAlmostEqual(sbm.boyer_ratio(0.585 * (1 - 1e-9)),
                               1 / 0.32, 4)
        self.assertAlmostEqual(sbm.morris_boulay_ratio(0.68 * (1 - 1e-9)),
                               0.8 * 0.75 / 0.1, 4)
        # imposed stress: the profile of eq 3 with R for eta_ii holds
        # Sh_tau R(phi_b) = V on the floor
        z, phi, phib = sbm.resuspension_profile(sbm.boyer_ratio, 3.0, 1.8)
        self.assertAlmostEqual(3.0 * sbm.boyer_ratio(phib), 1.8, 9)
        self.assertAlmostEqual(np.trapz(phi, z), 1.8, delta=1e-4)

    def test_newtonian_velocity_is_the_parabola(self):
        # eta_s = 1: u* = 2 (1/4 - y*^2), centre 0.5 (eq F.8a)
        y = np.linspace(0, 0.5, 2001)
        u = sbm.poiseuille_velocity(y, np.zeros_like(y),
                                    lambda p: np.ones_like(p))
        self.assertLess(np.abs(u - 2 * (0.25 - y**2)).max(), 1e-7)

    def test_maron_pierce_velocity_at_uniform_phi(self):
        # uniform phi: the parabola divided by eq 4.12, centre
        # 0.5 (1 - phi/phi_J)^2/alpha; no shear from phi_J on
        eta_s = sbm.maron_pierce_poiseuille(0.592)
        y = np.linspace(0, 0.5, 2001)
        u = sbm.poiseuille_velocity(y, np.full_like(y, 0.45), eta_s)
        self.assertAlmostEqual(u[0], 0.5 * (1 - 0.45 / 0.592)**2 / 0.803,
                               delta=1e-7)
        self.assertTrue(np.all(np.isinf(eta_s(np.array([0.592, 0.7])))))

    def test_plug_does_not_shear(self):
        eta_s, sigma22 = sbm.morris_boulay_poiseuille(0.592)
        y, phi, _ = sbm.poiseuille_profile(sigma22, 0.5, 0.592)
        u = sbm.poiseuille_velocity(y, phi, eta_s)
        plug = phi >= 0.592
        self.assertGreater(plug.sum(), 3)
        self.assertLess(np.ptp(u[plug]) / u[0], 1e-6)
        self.assertAlmostEqual(np.trapz(phi, y) / 0.5, 0.5, delta=1e-3)

    def test_migration_conserves_volume_and_reaches_the_steady_profile(self):
        # eq F.8b from a uniform phi0 = 0.4 ends on the zero-flux profile of
        # eqs F.10-F.11 (computed independently, |y| Sigma_22 = C); the
        # particle volume is conserved at every time
        phij = 0.592
        _, sigma22 = sbm.morris_boulay_poiseuille(phij)
        y, out = sbm.poiseuille_transient(sigma22, 0.4, 5.0, phij,
                                          [1.0, 60.0], n=30)
        for phi in out.values():
            self.assertAlmostEqual(phi.mean(), 0.4, delta=1e-12)
        early, late = out[1.0], out[60.0]
        self.assertGreater(early[0], 0.4)    # toward the centre
        self.assertLess(early[-1], 0.4)
        ys, phis, _ = sbm.poiseuille_profile(sigma22, 0.4, phij, n=2001)
        steady = np.interp(y, ys, phis)
        outside = y > 0.1                    # away from the plug's edge
        self.assertLess(np.abs(late - steady)[outside].max(), 1e-3)

    def test_migration_time_scales_with_the_channel_width_squared(self):
        # eq F.8b has the single time scale (9/8)(L_y/abar)^2 (eq F.9)
        _, sigma22 = sbm.morris_boulay_poiseuille(0.592)
        _, a = sbm.poiseuille_transient(sigma22, 0.4, 5.0, 0.592, [2.0], n=30)
        _, b = sbm.poiseuille_transient(sigma22, 0.4, 10.0, 0.592, [8.0], n=30)
        self.assertLess(np.abs(a[2.0] - b[8.0]).max(), 2e-3)


if __name__ == "__main__":
    unittest.main()
