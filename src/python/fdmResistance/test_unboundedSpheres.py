"""Tests of unboundedSpheres (unittest).

Run: PYTHONPATH=src/python python3 -m unittest fdmResistance.test_unboundedSpheres

Checks and tolerances (coarse meshes):
  an isolated sphere under 6 pi eta a e_x moves at e_x within 0.5 % (full
      solve, level 2) and within 1 % (mirrored about z = 0 and y = 0,
      octahedral level 2); in shear, mirrored, Omega_z = -1/2 (1e-9) and
      S_xy = (10/3) pi eta a^3 within 1 %
  a pushed pair at centre distance 2.2 against the exact two-sphere
      mobility (threeSphere.velocities, exact for two spheres): U and Omega
      within 0.3 % of the largest (measured 0.10 %, 0.09 %) and within
      twice the error estimate, full solve; mirrored about z = 0, within
      0.5 %
  the same triangle solved with one mirror plane and with two gives the
      same answer (1e-9: the same mesh, half or a quarter of it unknown),
      the y-mirror images of spheres 1 and 2 included; likewise the aligned
      spheres in shear with the half turn about z added (the middle sphere
      then does not translate)
  spheres that are not symmetric about a plane are refused
"""

import unittest

import numpy as np

from . import threeSphere
from . import unboundedSpheres as us

PUSH = (6 * np.pi, 0, 0)
Z = (1, 1, -1)                  # the mirror z -> -z
Y = (1, -1, 1)
HALF_TURN_Z = (-1, -1, 1)


class Pushed(unittest.TestCase):

    def test_isolated_sphere_moves_at_stokes_velocity(self):
        for mirrors, tol in (((), 5e-3), ((Y, Z), 1e-2)):
            r = us.unbounded_spheres([(0, 0, 0)], [1.0], "rest", [PUSH],
                                     mirrors, level=2)
            self.assertAlmostEqual(r["U"][0][0], 1.0, delta=tol)
            np.testing.assert_allclose(r["U"][0][1:], 0, atol=1e-9)
            np.testing.assert_allclose(r["Omega"][0], 0, atol=1e-9)

    def test_pair_against_exact_two_sphere_mobility(self):
        x = np.array([[0.0, 0, 0], [2.2 * np.cos(0.6), 2.2 * np.sin(0.6), 0]])
        F = [PUSH, (0, 0, 0)]
        U, W = threeSphere.velocities(x, forces=F)
        for mirrors, level, tol in (((), 2, 3e-3), ((Z,), 3, 5e-3)):
            r = us.unbounded_spheres(x, [1.0, 1.0], "rest", F, mirrors,
                                     level=level, beta=1.0)
            np.testing.assert_allclose(r["U"], U, atol=tol * U[0, 0])
            np.testing.assert_allclose(r["Omega"], W,
                                       atol=tol * abs(W).max())
            if not mirrors:
                for name, exact in (("U", U), ("Omega", W)):
                    self.assertTrue(np.all(abs(r[name] - exact)
                                           <= 2 * r["error"][name] + 1e-6))

    def test_one_or_two_mirror_planes_give_the_same_triangle(self):
        x = threeSphere.cluster("triangle", 2.5)
        F = [PUSH, (0, 0, 0), (0, 0, 0)]
        one = us.mirrored_free_spheres([(c, 1.0) for c in x], us.at_rest,
                                       (Z,), level=1, beta=1.0, forces=F)
        two = us.mirrored_free_spheres([(c, 1.0) for c in x], us.at_rest,
                                       (Y, Z), level=1, beta=1.0, forces=F)
        self.assertEqual(one["elements"], 2 * two["elements"])
        for name in ("U", "Omega", "S"):
            np.testing.assert_allclose(two[name], one[name], atol=1e-9)
        self.assertGreater(two["U"][1][1], 1e-3)   # spheres 1, 2 part
        self.assertAlmostEqual(two["U"][2][1], -two["U"][1][1], delta=1e-12)

    def test_asymmetric_spheres_refused(self):
        with self.assertRaises(ValueError):
            us.mirrored_free_spheres([((0, 0.5, 0), 1.0)], us.at_rest, (Y,),
                                     level=1)


class Shear(unittest.TestCase):

    def test_free_sphere_mirrored(self):
        r = us.mirrored_free_spheres([((0, 0, 0), 1.0)], us.simple_shear,
                                     (Z,), level=2)
        np.testing.assert_allclose(r["U"][0], 0, atol=1e-9)
        np.testing.assert_allclose(r["Omega"][0], [0, 0, -0.5], atol=1e-9)
        self.assertAlmostEqual(r["S"][0][0, 1] / (10 / 3 * np.pi), 1.0,
                               delta=1e-2)

    def test_aligned_with_half_turn_as_with_mirror_only(self):
        x = [(c, 1.0) for c in threeSphere.cluster("aligned", 2.2)]
        one = us.mirrored_free_spheres(x, us.simple_shear, (Z,), level=1,
                                       beta=1.0)
        two = us.mirrored_free_spheres(x, us.simple_shear,
                                       (Z, HALF_TURN_Z), level=1, beta=1.0)
        self.assertEqual(one["elements"], 2 * two["elements"])
        for name in ("U", "Omega", "S"):
            np.testing.assert_allclose(two[name], one[name], atol=1e-9)
        np.testing.assert_allclose(two["U"][1], 0, atol=1e-12)
        self.assertGreater(abs(two["U"][0][1]), 1e-2)


if __name__ == "__main__":
    unittest.main()
