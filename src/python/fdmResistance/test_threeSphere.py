"""Tests of threeSphere (far-field grand mobility and the Stokesian-dynamics
reference with exact pairs, unittest).

Run: PYTHONPATH=src/python python3 -m unittest fdmResistance.test_threeSphere
(about 30 s: the far-field block is derived with sympy once, about 15 s.)

Checks and tolerances:
  grand mobility symmetric (Lorentz reciprocity, 1e-15 absolute, entries
      ~0.05) and positive definite for a touching-close triplet
  far-field pair resistance against the exact two-sphere functions
      (pairShear), absolute: at r = 10, 2e-4 (R_FU, entries up to 6 pi,
      measured 8.9e-5) and 5e-5 (force from the strain, measured 4.9e-6);
      both deviations fall faster than r^-5.5 from r = 10 to 20 (measured
      r^-6.0 and r^-7.0): a wrong Rotne-Prager term would leave r^-3 or
      r^-4
  two spheres: the reference equals the exact two-sphere free motion in
      shear (1e-12)
  three spheres far apart (r = 40): the free spheres move with the
      Oseen field of the pushed one (3/4)(I + d d)/r . e_x, to O(r^-3)
      (tolerance 2 r^-3)
  frame invariance: rotating the triangle and its force rotates the
      velocities (1e-10); mirror symmetry of the triangle u_x(2) = u_x(3),
      u_y(2) = -u_y(3) (1e-12)
"""

import math
import unittest

import numpy as np

from . import pairShear as ps
from . import threeSphere as ts

PUSH = [[6 * math.pi, 0, 0], [0, 0, 0], [0, 0, 0]]


class FarField(unittest.TestCase):

    def test_mobility_symmetric_positive(self):
        x = ts.cluster("triangle", 2.01) + np.array([0.0, 0.0, 0.3]) * [
            [0], [1], [2]]
        M = ts.grand_mobility(x)
        self.assertLess(np.abs(M - M.T).max(), 1e-15)
        self.assertGreater(np.linalg.eigvalsh(M).min(), 0.0)

    def test_pair_far_field_matches_exact(self):
        errs = []
        for L in (10.0, 20.0):
            d = np.array([0.6, 0.0, 0.8]) * L
            Re, fe = ts._exact_pair(-d / 2, d / 2, ps.E_INF)
            Rf, ff = ts._far_pair(-d / 2, d / 2, ps.E_INF)
            errs.append((np.abs(Re - Rf).max(), np.abs(fe - ff).max()))
        self.assertLess(errs[0][0], 2e-4)       # entries up to 6 pi
        self.assertLess(errs[0][1], 5e-5)
        for k in range(2):
            self.assertGreater(math.log2(errs[0][k] / errs[1][k]), 5.5)


class Reference(unittest.TestCase):

    def test_two_spheres_exact(self):
        r = np.array([2.05, 0.6, -0.3])
        U, W = ts.velocities([-r / 2, r / 2], E=ps.E_INF, W=ps.W_INF)
        U1, U2, W1, W2 = ps.free_motion(r)
        np.testing.assert_allclose(U, [U1, U2], rtol=0, atol=1e-12)
        np.testing.assert_allclose(W, [W1, W2], rtol=0, atol=1e-12)

    def test_far_triangle_oseen(self):
        s = 40.0
        x = ts.cluster("triangle", s)
        U, _ = ts.velocities(x, forces=PUSH)
        self.assertLess(abs(U[0, 0] - 1.0), 2 / s**3)
        for k in (1, 2):
            d = (x[k] - x[0]) / s
            oseen = 0.75 / s * (np.eye(3) + np.outer(d, d)) @ [1, 0, 0]
            np.testing.assert_allclose(U[k], oseen, rtol=0, atol=2 / s**3)

    def test_rotation_and_mirror(self):
        x = ts.cluster("triangle", 2.1)
        U, W = ts.velocities(x, forces=PUSH)
        self.assertLess(abs(U[1, 0] - U[2, 0]), 1e-12)
        self.assertLess(abs(U[1, 1] + U[2, 1]), 1e-12)
        c, s = math.cos(0.7), math.sin(0.7)
        Q = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]) @ np.array(
            [[1, 0, 0], [0, c, -s], [0, s, c]])
        Ur, Wr = ts.velocities(x @ Q.T, forces=np.array(PUSH) @ Q.T)
        np.testing.assert_allclose(Ur, U @ Q.T, rtol=0, atol=1e-10)
        np.testing.assert_allclose(Wr, W @ Q.T, rtol=0, atol=1e-10)


if __name__ == "__main__":
    unittest.main()
