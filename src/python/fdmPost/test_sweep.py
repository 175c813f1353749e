"""Unit tests of fdmPost.sweep: the reduced-data table written and read
back, the Maron-Pierce fit (eq 4.12) recovering exact parameters and
reporting standard errors that match the scatter of repeated noisy fits,
and the contact normal closure fit."""

import os
import tempfile
import unittest

import numpy as np

from fdmPost import sweep
from fdmPost.rheology import maron_pierce

PHI = np.array([0.30, 0.36, 0.40, 0.46, 0.49, 0.54])


def rheology(phi, eta):
    r = {q: (0.5, 0.01) for q in sweep.QUANTITIES}
    r.update(phiCore=(phi, 0.001), etaCore=(eta, 0.05 * eta),
             contact22=(-0.3 * phi, 0.02), records=100)
    return r


class ReducedData(unittest.TestCase):
    def test_round_trip(self):
        rows = [sweep.point_row(f"phi{p}", 60.0, 5.0, (10, 20, 10),
                                rheology(p, maron_pierce(p))) for p in PHI]
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "sweep.csv")
            sweep.write_points(path, rows)
            back = sweep.read_points(path)
        self.assertEqual([r["case"] for r in back], [r["case"] for r in rows])
        for a, b in zip(rows, back):
            self.assertEqual(b["records"], 100)
            for k in ("strain", "Ly", "phiCore", "etaCore", "etaCoreErr",
                      "contact22"):
                self.assertAlmostEqual(a[k] / b[k], 1, delta=1e-5, msg=k)


class CaseNames(unittest.TestCase):
    def test_phi0_of_every_runpoint_name(self):
        for name in ("phi0.42_10x20x10", "phi0.42_20x20",
                     "phi0.52_10x25x10_Delta0.25", "phi0.37_10x20x10_G4"):
            self.assertEqual(sweep.phi0_of(name), float(name[3:7]))
        self.assertEqual(sorted(sweep.TABLE_4_7)[0], 0.27)


class MaronPierceFit(unittest.TestCase):
    def test_exact_points_give_the_parameters(self):
        eta = maron_pierce(PHI, 0.9, 0.61)
        (alpha, phi_j), _ = sweep.fit_maron_pierce(PHI, eta, 0.05 * eta)
        self.assertAlmostEqual(alpha, 0.9, delta=1e-7)
        self.assertAlmostEqual(phi_j, 0.61, delta=1e-9)

    def test_standard_errors_match_the_scatter(self):
        # 5 % noise: the reported standard error of phi_J is the spread of
        # 300 fits to within 20 %, and the fits are centred on the truth
        rng = np.random.default_rng(3)
        eta = maron_pierce(PHI, 0.803, 0.59)
        err = 0.05 * eta
        fits, reported = [], []
        for _ in range(300):
            p, cov = sweep.fit_maron_pierce(
                PHI, eta + err * rng.standard_normal(len(PHI)), err)
            fits.append(p)
            reported.append(np.sqrt(np.diag(cov)))
        fits, reported = np.array(fits), np.array(reported)
        spread = fits.std(axis=0)
        self.assertAlmostEqual(np.median(reported[:, 1]) / spread[1], 1,
                               delta=0.2)
        self.assertAlmostEqual(np.median(reported[:, 0]) / spread[0], 1,
                               delta=0.2)
        self.assertLess(abs(fits[:, 1].mean() - 0.59), 3 * spread[1] / 17)

    def test_too_few_points(self):
        self.assertIsNone(sweep.fit_maron_pierce(PHI[:2], [2, 3], [1, 1]))


class ContactNormalFit(unittest.TestCase):
    def test_exact_points_give_the_parameters(self):
        x = PHI / 0.59
        s = sweep.contact_normal_closure(x, 0.7, 3.2)
        (beta, n), _ = sweep.fit_contact_normal(x, s, 0.1 * s)
        self.assertAlmostEqual(beta, 0.7, delta=1e-8)
        self.assertAlmostEqual(n, 3.2, delta=1e-7)

    def test_fit_sweep_on_exact_rows(self):
        rows = [sweep.point_row(f"phi{p}", 60.0, 5.0, (10, 20, 10),
                                rheology(p, maron_pierce(p, 0.8, 0.6)))
                for p in PHI]
        for r in rows:
            r["contact22"] = -float(sweep.contact_normal_closure(
                r["phiCore"] / 0.6, 0.5, 2.0))
        fit = sweep.fit_sweep(rows)
        self.assertAlmostEqual(fit["phiJ"], 0.6, delta=1e-8)
        self.assertAlmostEqual(fit["alpha"], 0.8, delta=1e-7)
        self.assertAlmostEqual(fit["beta"], 0.5, delta=1e-7)
        self.assertAlmostEqual(fit["n"], 2.0, delta=1e-6)
        self.assertEqual(fit["points"], len(PHI))


class UnfinishedPoint(unittest.TestCase):
    def test_a_point_without_error_bar_is_left_out(self):
        rows = [sweep.point_row(f"phi{p}", 60.0, 5.0, (10, 20, 10),
                                rheology(p, maron_pierce(p))) for p in PHI]
        short = sweep.point_row("short", 0.3, 0.1, (10, 25, 10),
                                rheology(0.55, 100.0))
        short["etaCoreErr"] = float("nan")
        fit = sweep.fit_sweep(rows + [short])
        self.assertAlmostEqual(fit["phiJ"], 0.59, delta=1e-6)

    def test_a_point_in_its_transient_is_left_out(self):
        # Strain 6, averaged from 2 with block errors: shown, not fitted
        rows = [sweep.point_row(f"phi{p}", 60.0, 5.0, (10, 20, 10),
                                rheology(p, maron_pierce(p))) for p in PHI]
        young = sweep.point_row("young", 6.0, sweep.averaging_start(6.0),
                                (10, 25, 10), rheology(0.55, 100.0))
        self.assertEqual(young["start"], 2.0)
        self.assertTrue(young["etaCoreErr"] > 0)
        fit = sweep.fit_sweep(rows + [young])
        self.assertAlmostEqual(fit["phiJ"], 0.59, delta=1e-6)
        self.assertEqual(fit["points"], len(PHI))


if __name__ == "__main__":
    unittest.main()
