"""Unit tests: the thesis 2 rheology model (article 2, eqs 13-16) against
its values at three and four significant figures."""

import os
import tempfile
import unittest

import numpy as np

from fdmPost.demRheology import (article2_phi, finished, fit_phi_m,
                                 master_phi_m, model_eta, model_lambda33,
                                 model_mu, phi_m, series_averages,
                                 viscous_number)


class ThesisModel(unittest.TestCase):
    def test_phi_m_of_friction(self):
        for mu, ref in ((0, 0.6301), (0.1, 0.6127), (0.4, 0.5801),
                        (0.5, 0.5737), (2, 0.5513)):
            self.assertAlmostEqual(phi_m(mu), ref, delta=1e-4)

    def test_lambda33_fits(self):
        # article 3, eqs 7 and 8, at 3 decimals
        for phi, eq7, eq8 in ((0.25, 0.181, 0.191), (0.40, 0.496, 0.486),
                              (0.50, 0.706, 0.688), (0.64, 1.000, 0.999)):
            l7, l8 = model_lambda33(phi)
            self.assertAlmostEqual(float(l7), eq7, delta=6e-4)
            self.assertAlmostEqual(float(l8), eq8, delta=6e-4)

    def test_mu_and_eta_of_iv(self):
        # I_v, mu total and eta_r at phi_m = 0.63 (article 2, eqs 13-16)
        for iv, mu, eta in ((1e-3, 0.3944, 394.4), (1e-2, 0.5898, 58.98),
                            (1e-1, 1.1698, 11.70), (1.0, 3.271, 3.27)):
            # the values are rounded to 4 significant figures
            self.assertAlmostEqual(model_mu(iv, 0.63) / mu, 1, delta=3e-4)
            phi = 0.63 / (1 + iv ** 0.5)
            self.assertAlmostEqual(viscous_number(phi, 0.63), iv,
                                   delta=1e-12 + 1e-9 * iv)
            self.assertAlmostEqual(float(master_phi_m(phi, iv)), 0.63,
                                   delta=1e-12)
            self.assertAlmostEqual(model_eta(phi, 0.63) / eta, 1, delta=2e-3)

    def test_article2_radius(self):
        # The radius r of this DEM's spheres that article 2's of radius a
        # are: the lubrication gaps agree at any centre distance d (article
        # 1: d - 2r; article 2: h = d - 2a + eps a) and contact starts at
        # 2r + eps r against 2a, to O(eps^2)
        a, eps, d = 1.0, 2e-2, 2.3
        r = a * (0.5 / float(article2_phi(0.5, eps))) ** (1 / 3)
        self.assertAlmostEqual(d - 2 * r, d - 2 * a + eps * a, delta=1e-12)
        self.assertAlmostEqual(2 * r + eps * r, 2 * a, delta=eps ** 2)
        self.assertEqual(float(article2_phi(0.5, 0)), 0.5)


    def test_phi_m_of_a_power_law(self):
        # Runs on phi = phi_m/(1 + c I_v^n) with n above 1/2, scattered by
        # 1e-3 of phi: the fit finds phi_m within its error, where one run
        # far from jamming read with n = 1/2 is 0.04 too high
        iv = np.array([0.13, 0.06, 0.035, 0.017, 0.007])
        phi = 0.63 / (1 + 0.84 * iv**0.56)
        phi *= 1 + 1e-3 * np.array([1, -1, 0.5, -0.5, 0])
        (pm, c, n), err = fit_phi_m(phi, iv)
        self.assertLess(abs(pm - 0.63), max(2 * err[0], 1e-3))
        self.assertAlmostEqual(n, 0.56, delta=0.05)
        self.assertGreater(float(master_phi_m(phi[0], iv[0])), 0.67)
        with self.assertRaises(ValueError):
            fit_phi_m(phi[:3], iv[:3])


class Finished(unittest.TestCase):
    def test_only_a_log_that_ends_with_end(self):
        with tempfile.TemporaryDirectory() as case:
            self.assertFalse(finished(case))
            log = os.path.join(case, "log.lubricatedDEMFoam")
            with open(log, "w") as f:
                f.write("Time = 4.2  strain 4.2  eta_r 64.5\n")
            self.assertFalse(finished(case))
            with open(log, "a") as f:
                f.write("End: 125000 steps, 117.7 s, 497956 particle-steps"
                        "/s\n\n")
            self.assertTrue(finished(case))


class SeriesAverages(unittest.TestCase):
    def test_steady_series(self):
        # Rows of stress.dat: time strain phi interactions contacts s, then
        # xx yy zz xy per part (NC, SC, NL, SL); viscosity 2, rate 0.5
        t = np.linspace(0, 2, 41)
        d = np.zeros((len(t), 22))
        d[:, 0] = d[:, 1] = t
        d[:, 2], d[:, 3], d[:, 4] = 0.5, 300, 40
        parts = ((-6, -5, -4, 3), (0, -1, 0, 1), (-1, -1, -1, 2),
                 (0, 0, 0, 0.5))
        for p, (xx, yy, zz, xy) in enumerate(parts):
            d[:, 6 + 4 * p:10 + 4 * p] = (xx, yy, zz, xy)
        a = series_averages(d, 2.0, 0.5, 1.0)
        self.assertEqual(a["records"], 21)
        self.assertAlmostEqual(a["eta_r"][0], 6.5)  # 6.5/(2 * 0.5)
        self.assertAlmostEqual(a["eta_r"][1], 0)
        self.assertAlmostEqual(a["mu"], 6.5 / 7)
        self.assertAlmostEqual(a["muBlocks"][0], 6.5 / 7)
        self.assertAlmostEqual(a["lambda33"], 5 / 7)
        self.assertAlmostEqual(a["lambda33Blocks"][0], 5 / 7)
        self.assertAlmostEqual(a["lambda33Blocks"][1], 0)
        self.assertAlmostEqual(a["contactShare"][0], 4 / 6.5)
        self.assertAlmostEqual(a["N1"], (-7 + 7) / 6.5)
        self.assertAlmostEqual(a["N2"], (-7 + 5) / 6.5)
        self.assertEqual(a["interactions"], 300)


if __name__ == "__main__":
    unittest.main()
