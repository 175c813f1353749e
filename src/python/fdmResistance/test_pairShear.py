"""Tests of pairShear (two free equal spheres in simple shear, unittest).

Run: PYTHONPATH=src/python python3 -m unittest fdmResistance.test_pairShear
(about 6 s; the first resistance evaluation solves the twin-multipole
recurrences, about 3 s.)

Checks and tolerances:
  far field: A, B against the Batchelor & Green (1972) series
      (pairShear.AB_far, terms to r^-12): r = 20, 10 absolute 1e-10
      (measured 2e-15 and 2e-11, the omitted O(r^-13) terms)
  near contact: (1 - A)/xi -> 4.077 (Batchelor & Green): xi = 1e-7,
      |.| < 1e-3 (measured 4.07742); B(2) = 0.4060 (Batchelor & Green,
      touching spheres): 2e-4 (measured 0.405932 from the near-contact
      forms with ln(1/xi) -> infinity)
  B&G form reproduced by the direct solve at arbitrary orientation: 1e-12
  special orientations (r along z, x, y, 45 degrees): 1e-12
  pair symmetries (U1 = -U2 about the midpoint, W1 = W2, V(-r) = -V(r)),
      X^C independence, axial spin = ambient: 1e-12
  grand resistance matrix symmetric (1e-12 relative) and positive definite
  spline A, B vs direct solve (xi = 1e-8 .. 50): relative velocity 1e-8
  fore-aft symmetry r_y(end) = r_y(start), y0 = 0.5, 1.0: 1e-6 (measured
      < 1e-9); minimum gaps y0 = 1.0: 7.076e-3, y0 = 0.01: 4.110e-5
      (Zarraga & Leighton's ~4e-5 grazing limit): 1e-3 relative
"""

import math
import unittest

import numpy as np

from . import pairShear as ps


class FarFieldAndContact(unittest.TestCase):

    def test_far_field_batchelor_green(self):
        r = np.array([10.0, 20.0])
        A, B = ps.AB_exact(r)
        Af, Bf = ps.AB_far(r)
        np.testing.assert_allclose(A, Af, rtol=0, atol=1e-10)
        np.testing.assert_allclose(B, Bf, rtol=0, atol=1e-10)
        # leading terms alone
        self.assertAlmostEqual(A[1] * 20.0**3 / 5.0, 1.0, delta=0.01)
        self.assertAlmostEqual(B[1] * 20.0**5 * 3.0 / 16.0, 1.0, delta=0.01)

    def test_near_contact(self):
        xi = 1e-7
        A, B = ps.AB_exact(np.array([2.0 + xi]))
        self.assertAlmostEqual((1.0 - A[0]) / xi, 4.077, delta=1e-3)
        self.assertAlmostEqual(ps.B_contact(), 0.4060, delta=2e-4)
        # B increases monotonically towards the contact value
        _, Bs = ps.AB_exact(np.array([2 + 1e-2, 2 + 1e-4, 2 + 1e-8]))
        self.assertTrue(np.all(np.diff(Bs) > 0) and Bs[-1] < ps.B_contact())


class Kinematics(unittest.TestCase):

    def test_bg_form_arbitrary_orientation(self):
        rng = np.random.default_rng(3)
        for _ in range(4):
            rv = rng.normal(size=3)
            rv *= (2.0 + math.exp(rng.uniform(-8, 2))) / np.linalg.norm(rv)
            A, B = ps.AB_exact(np.array([np.linalg.norm(rv)]))
            V = ps.relative_velocity(rv, exact=True)
            np.testing.assert_allclose(V, ps.bg_velocity(rv, A[0], B[0]),
                                       rtol=0, atol=1e-12)

    def test_special_orientations(self):
        r = 2.3
        A, B = ps.AB_exact(np.array([r]))
        A, B = A[0], B[0]
        V = lambda v: ps.relative_velocity(np.array(v, float), exact=True)
        # along the vorticity axis: no relative motion at all
        np.testing.assert_allclose(V([0, 0, r]), 0.0, atol=1e-12)
        # along the flow: rotation and strain cancel up to the B term
        np.testing.assert_allclose(V([r, 0, 0]), [0, -B * r / 2, 0],
                                   atol=1e-12)
        # along the gradient: they add
        np.testing.assert_allclose(V([0, r, 0]), [r * (1 - B / 2), 0, 0],
                                   atol=1e-12)
        # 45 degrees: radial velocity (1 - A) r/2, tangential -r/2
        d = np.array([1.0, 1.0, 0.0]) / math.sqrt(2.0)
        v = V(r * d)
        self.assertAlmostEqual(v @ d, (1 - A) * r / 2, delta=1e-12)
        self.assertAlmostEqual(np.linalg.norm(v - (v @ d) * d), r / 2,
                               delta=1e-12)

    def test_pair_symmetries(self):
        rv = np.array([-1.3, 1.7, 0.4])
        U1, U2, W1, W2 = ps.free_motion(rv)
        np.testing.assert_allclose(U1, -U2, atol=1e-12)
        np.testing.assert_allclose(W1, W2, atol=1e-12)
        np.testing.assert_allclose(ps.relative_velocity(-rv, exact=True),
                                   -ps.relative_velocity(rv, exact=True),
                                   atol=1e-12)
        # X^C only enters the axial spin, which equals the ambient one
        V1, V2, Z1, Z2 = ps.free_motion(rv, xc=False)
        np.testing.assert_allclose(V2 - V1, U2 - U1, atol=1e-12)
        d = rv / np.linalg.norm(rv)
        self.assertAlmostEqual(W1 @ d, ps.W_INF @ d, delta=1e-12)
        # far apart: spheres follow the ambient flow and vorticity
        U1, U2, W1, W2 = ps.free_motion(np.array([0.0, 200.0, 0.0]))
        np.testing.assert_allclose(W1, ps.W_INF, atol=1e-6)
        np.testing.assert_allclose(U2 - U1, [200.0, 0, 0], rtol=1e-6)

    def test_grand_resistance(self):
        for xi in (1e-5, 0.1, 3.0):
            rv = (2.0 + xi) * np.array([0.6, 0.0, 0.8])
            R, _ = ps.grand_resistance(rv)
            np.testing.assert_allclose(R, R.T, rtol=0,
                                       atol=1e-12 * np.abs(R).max())
            self.assertGreater(np.linalg.eigvalsh(0.5 * (R + R.T)).min(), 0)

    def test_spline(self):
        for xi in (1e-8, 3e-5, 0.02, 0.7, 5.0, 50.0):
            rv = (2.0 + xi) * np.array([math.cos(0.4), math.sin(0.4), 0.0])
            np.testing.assert_allclose(ps.relative_velocity(rv),
                                       ps.relative_velocity(rv, exact=True),
                                       rtol=0, atol=1e-8)


class Trajectories(unittest.TestCase):

    def test_fore_aft_symmetry_and_min_gap(self):
        expected = {1.0: 7.0762e-3, 0.01: 4.1104e-5}
        for y0 in (0.5, 1.0, 0.01):
            s = ps.trajectory_summary(-6.0, y0)
            if y0 >= 0.5:
                self.assertLess(abs(s["ry_end"] - y0), 1e-6)
            self.assertLess(abs(s["rz_end"]), 1e-12)
            if y0 in expected:
                self.assertAlmostEqual(s["min_gap"] / expected[y0], 1.0,
                                       delta=1e-3)
                # closest approach on the gradient axis (radial velocity
                # vanishes at x = 0)
                self.assertLess(abs(s["r_at_min"][0]), 1e-4)

    def test_trajectory_arrays(self):
        t, rx, ry, rz, gap = ps.trajectory(-6.0, 1.0)
        self.assertAlmostEqual(rx[-1], 6.0, delta=1e-10)
        self.assertTrue(np.all(np.diff(t) > 0) and np.all(gap > 0))
        self.assertTrue(np.all(np.diff(rx) > 0))
        np.testing.assert_allclose(gap, np.sqrt(rx**2 + ry**2 + rz**2) - 2,
                                   atol=1e-14)



class UnequalSpheres(unittest.TestCase):
    """a2/a1 = 1.4: the 22 and 21 blocks come from relabelling the pair."""

    LAM = 1.4

    def test_symmetric_functions_agree_with_their_transpose(self):
        # A and C are symmetric operators: the relabelled 21 functions must
        # equal the directly computed 12 ones
        S = ps.scalars(np.array([0.003, 0.3, 12.0]), lam=self.LAM)
        for f in ("XA", "YA", "XC", "YC"):
            np.testing.assert_allclose(S[f][1, 0], S[f][0, 1], rtol=1e-9)
        R, _ = ps.grand_resistance(np.array([1.1, 2.2, 0.4]), lam=self.LAM)
        np.testing.assert_allclose(R, R.T, atol=1e-9 * np.abs(R).max())
        self.assertGreater(np.linalg.eigvalsh(R).min(), 0)

    def test_far_field_is_two_isolated_spheres(self):
        S = ps.scalars(np.array([2000.0]), lam=self.LAM)
        self.assertAlmostEqual(S["XA"][1, 1, 0] / (6 * math.pi), 1.4, 5)
        self.assertAlmostEqual(S["YC"][1, 1, 0] / (8 * math.pi), 1.4**3, 5)

    def test_relabelling_gives_the_same_motion(self):
        # The same pair described from the large sphere (a1 = 1, a2 = 1/1.4,
        # lengths divided by 1.4, r reversed): velocities scale with length,
        # spins do not -- checks the parities and powers of every function
        r = np.array([1.3, 2.1, 0.5])
        U1, U2, W1, W2 = ps.free_motion(r, lam=self.LAM)
        V1, V2, Z1, Z2 = ps.free_motion(-r / self.LAM, lam=1 / self.LAM)
        np.testing.assert_allclose(U2 - U1, -(V2 - V1) * self.LAM,
                                   atol=1e-10)
        np.testing.assert_allclose(W1, Z2, atol=1e-10)
        np.testing.assert_allclose(W2, Z1, atol=1e-10)


if __name__ == "__main__":
    unittest.main()
