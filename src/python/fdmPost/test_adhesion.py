"""Unit tests of fdmPost.adhesion: eqs 5.3-5.5 by hand, the banding and
depletion flags, and phi_J(sigma*) of eq 5.7 recovered from runs made
from a known stress-dependent Maron-Pierce law."""

import unittest

import numpy as np

from fdmPost import adhesion
from fdmPost.rheology import maron_pierce


def rheology(s12, rate, phi=0.45):
    return {"shearStress": (s12, 0.1 * s12), "gammaDotCore": (rate, 0.01),
            "phiCore": (phi, 0.001), "etaCore": (s12 / (2 * rate), 1.0)}


class Point(unittest.TestCase):
    def test_reduced_stress_by_hand(self):
        # eta 2, gammaDot_0 1, Sigma_12 12: eta_app 6, sigma* = 6/G_0;
        # eta_core = eta_app gammaDot_0/gammaDot_core = 6/0.5 = 12/(2 0.5)
        p = adhesion.adhesion_point(rheology(12.0, 0.5), 2.0, 1.0, 3.0)
        self.assertAlmostEqual(p["etaApp"][0], 6.0, 12)
        self.assertAlmostEqual(p["sigmaStar"][0], 2.0, 12)
        self.assertAlmostEqual(p["sigmaStar"][1], 0.2, 12)
        self.assertAlmostEqual(p["etaCore"][0], 12.0, 12)
        # eq 5.4's second form: eta_core/G_core, G_core = G_0 gammaDot_0/rate
        self.assertAlmostEqual(p["etaCore"][0] / (3.0 / 0.5),
                               p["sigmaStar"][0], 12)
        self.assertEqual(p["state"], "homogeneous")

    def test_no_adhesion_is_infinite_stress(self):
        p = adhesion.adhesion_point(rheology(12.0, 0.5), 2.0, 1.0, 0.0)
        self.assertTrue(np.isinf(p["sigmaStar"][0]))

    def test_flags(self):
        banded = adhesion.adhesion_point(rheology(12.0, 0.01), 2.0, 1.0, 3.0)
        self.assertEqual(banded["state"], "banding")
        self.assertTrue(np.isnan(banded["etaCore"][0]))
        self.assertAlmostEqual(banded["sigmaStar"][0], 2.0, 12)
        depleted = adhesion.adhesion_point(rheology(12.0, 0.5), 2.0, 1.0, 3.0,
                                           phi_wall=0.2)
        self.assertEqual(depleted["state"], "depletion")
        self.assertEqual(adhesion.adhesion_point(
            rheology(12.0, 0.5), 2.0, 1.0, 3.0, phi_wall=0.3)["state"],
            "homogeneous")


def phi_j(sigma):
    """A jamming fraction falling at low stress, levelling at 0.59."""
    return 0.59 - 0.08 / (1 + sigma)


class JammingFraction(unittest.TestCase):
    def make(self):
        # three series at fixed phi_core, runs at five stresses each
        stresses = [0.5, 1.0, 2.0, 4.0, 8.0]
        return [[{"sigmaStar": (s, 0.0), "phiCore": (phi, 0.001),
                  "etaCore": (maron_pierce(phi, 0.8, phi_j(s)),
                              0.05 * maron_pierce(phi, 0.8, phi_j(s)))}
                 for s in stresses] for phi in (0.38, 0.43, 0.47)]

    def test_at_the_runs_stresses_the_law_is_recovered(self):
        fits = adhesion.jamming_fraction(self.make(), [0.5, 2.0, 8.0])
        for s, (alpha, pj, _, _, n) in fits.items():
            self.assertEqual(n, 3)
            self.assertAlmostEqual(pj, phi_j(s), delta=1e-8)
            self.assertAlmostEqual(alpha, 0.8, delta=1e-6)

    def test_between_runs_and_outside(self):
        fits = adhesion.jamming_fraction(self.make(), [0.7, 3.0, 20.0])
        self.assertNotIn(20.0, fits)          # no extrapolation
        for s in (0.7, 3.0):
            self.assertAlmostEqual(fits[s][1], phi_j(s), delta=5e-3)
        self.assertLess(fits[0.7][1], fits[3.0][1])

    def test_banded_runs_are_left_out(self):
        series = self.make()
        series[0][0]["etaCore"] = (np.nan, np.nan)
        spans = adhesion.interpolate_at_stress(series, [0.5, 1.0])
        self.assertEqual(len(spans[0.5][0]), 2)
        self.assertEqual(len(spans[1.0][0]), 3)


if __name__ == "__main__":
    unittest.main()
