"""Unit tests: the thesis 2 rheology model against the values tabulated in
the spec (seed2 C.3, computed there from eqs 13-16)."""

import unittest

from fdmPost.demRheology import (model_eta, model_lambda33, model_mu, phi_m,
                                 viscous_number)


class ThesisModel(unittest.TestCase):
    def test_phi_m_of_friction(self):
        for mu, ref in ((0, 0.6301), (0.1, 0.6127), (0.4, 0.5801),
                        (0.5, 0.5737), (2, 0.5513)):
            self.assertAlmostEqual(phi_m(mu), ref, delta=1e-4)

    def test_lambda33_fits(self):
        # spec C.6 table of eqs 7 and 8 (3 decimals)
        for phi, eq7, eq8 in ((0.25, 0.181, 0.191), (0.40, 0.496, 0.486),
                              (0.50, 0.706, 0.688), (0.64, 1.000, 0.999)):
            l7, l8 = model_lambda33(phi)
            self.assertAlmostEqual(float(l7), eq7, delta=6e-4)
            self.assertAlmostEqual(float(l8), eq8, delta=6e-4)

    def test_mu_and_eta_of_iv(self):
        # I_v, mu total and eta_r at phi_m = 0.63 (spec table)
        for iv, mu, eta in ((1e-3, 0.3944, 394.4), (1e-2, 0.5898, 58.98),
                            (1e-1, 1.1698, 11.70), (1.0, 3.271, 3.27)):
            # the spec rounds to 4 significant figures
            self.assertAlmostEqual(model_mu(iv, 0.63) / mu, 1, delta=3e-4)
            phi = 0.63 / (1 + iv ** 0.5)
            self.assertAlmostEqual(viscous_number(phi, 0.63), iv,
                                   delta=1e-12 + 1e-9 * iv)
            self.assertAlmostEqual(model_eta(phi, 0.63) / eta, 1, delta=2e-3)


if __name__ == "__main__":
    unittest.main()
