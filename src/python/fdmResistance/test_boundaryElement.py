"""Tests of boundaryElement (free spheres between plane walls, unittest).

Run: PYTHONPATH=src/python python3 -m unittest fdmResistance.test_boundaryElement
(about 5 s.)

Checks and tolerances (coarse meshes, level 2: 320 sphere elements):
  single wall, eps = 0.2, against the exact free-sphere velocities of
      validation/wallShearSphere/reference.py (Chaoui & Feuillebois 2003,
      Goldman, Cox & Brenner 1967): U_x within 1 %, Omega_z within 1.5 %
      (measured +0.59 %, +1.16 %; at level 3, beta 0.5: +0.07 %, +0.15 %,
      and +0.29 %, +0.63 % at eps = 0.05); the error estimate of
      `reference` (|fine - coarse|/3) bounds the true error of the fine mesh
  channel symmetries: sphere at the centre of plane Couette flow does not
      translate; sphere on the centre line of plane Poiseuille flow does not
      rotate or drift across; two spheres placed point-symmetrically about
      the centre of a Couette channel move with U1 = -U2, Omega1 = Omega2
      and equal stresslets (1e-8; the meshes share the symmetry)
"""

import os
import sys
import unittest

import numpy as np

from . import boundaryElement as be

def SHEAR(x):
    """Unit simple shear u = y e_x (zero on the wall y = 0)."""
    return np.stack([x[:, 1], 0 * x[:, 1], 0 * x[:, 1]], 1)


def _wall_reference():
    root = os.environ.get("FDM_PROJECT_DIR",
                          os.path.join(os.path.dirname(__file__), "..", "..",
                                       ".."))
    sys.path.insert(0, os.path.join(root, "validation", "wallShearSphere"))
    import reference
    return reference


class Unbounded(unittest.TestCase):

    def test_free_sphere_in_shear(self):
        r = be.free_spheres([((0, 0, 0), 1.0)], [], SHEAR, level=2)
        np.testing.assert_allclose(r["U"][0], 0, atol=1e-12)
        np.testing.assert_allclose(r["Omega"][0], [0, 0, -0.5], atol=1e-9)
        S = r["S"][0]
        self.assertAlmostEqual(S[0, 1] / (10 / 3 * np.pi), 1.0, delta=5e-3)
        np.testing.assert_allclose(S, S.T, atol=1e-12)
        self.assertAlmostEqual(np.trace(S), 0.0, delta=1e-12)


class SingleWall(unittest.TestCase):

    def test_free_sphere_near_wall(self):
        eps = 0.2
        ref = _wall_reference().free_sphere_velocity(eps)
        fine = be.reference([((0, 1 + eps, 0), 1.0)], [0.0], SHEAR,
                            level=2, beta=0.7)
        U, W = fine["U"][0][0], fine["Omega"][0][2]
        self.assertAlmostEqual(U / ref[0], 1.0, delta=1e-2)
        self.assertAlmostEqual(W / ref[1], 1.0, delta=1.5e-2)
        self.assertLessEqual(abs(U - ref[0]), fine["error"]["U"][0][0])
        self.assertLessEqual(abs(W - ref[1]), fine["error"]["Omega"][0][2])


class ChannelSymmetry(unittest.TestCase):

    def test_couette_centre(self):
        r = be.channel_spheres(4.0, [(0.0, 2.0, 0.0)], "couette", level=2,
                               beta=1.0)
        np.testing.assert_allclose(r["U"][0], 0, atol=1e-8)
        self.assertLess(r["Omega"][0][2], -0.4)

    def test_poiseuille_centre_line(self):
        r = be.channel_spheres(4.0, [(0.0, 2.0, 0.0)], "poiseuille",
                               level=2, beta=1.0)
        np.testing.assert_allclose(r["Omega"][0], 0, atol=1e-8)
        self.assertAlmostEqual(r["U"][0][1], 0, delta=1e-8)
        self.assertTrue(0 < r["U"][0][0] < 1)

    def test_couette_pair_point_symmetry(self):
        r = be.channel_spheres(4.0, [(-1.3, 1.7, 0.0), (1.3, 2.3, 0.0)],
                               "couette", level=1, beta=1.0)
        np.testing.assert_allclose(r["U"][0], -r["U"][1], atol=1e-8)
        np.testing.assert_allclose(r["Omega"][0], r["Omega"][1], atol=1e-8)
        np.testing.assert_allclose(r["S"][0], r["S"][1], atol=1e-8)
        self.assertGreater(abs(r["U"][0][1]), 1e-4)   # they do interact


if __name__ == "__main__":
    unittest.main()
