"""Tests of fdmResistance.pairContact: the contact law, the eight-function
description of the pair's mobility, and the rough-pair trajectories
(fore-aft symmetry without contact; with contact, one exit streamline
whatever the initial offset, Da Cunha & Hinch 1996)."""

import math
import pathlib
import unittest

import numpy as np

from . import pairContact as pc

LAM = 1.4


class ContactLawTest(unittest.TestCase):

    def test_stiffness_rule_and_coulomb_cap(self):
        law = pc.ContactLaw(roughness=5e-3, friction=0.5,
                            mean_deformation=0.2, lam=LAM)
        self.assertEqual(law.normal(5e-3 + 1e-9)[0], 0.0)
        # 6 pi eta gammaDot a1^2 at the mean deformation (barrier ~ 1 there)
        f_el, delta = law.normal(5e-3 * 0.8)
        self.assertAlmostEqual(f_el / (6 * math.pi), 1.0, 3)
        n = np.array([0.0, 1.0, 0.0])
        Y = law.truncate(np.array([1.0, 0.2, 0.0]), n, delta)
        self.assertAlmostEqual(Y @ n, 0.0, 15)
        Ft = law.tangential(f_el, delta, Y)
        self.assertAlmostEqual(np.linalg.norm(Ft), 0.5 * f_el, 10)
        small = law.truncate(np.array([1e-5, 0.0, 0.0]), n, delta)
        self.assertAlmostEqual(np.linalg.norm(law.tangential(f_el, delta,
                                                             small)),
                               (2 / 7) * f_el / delta * 1e-5, 10)


    def test_overlap_under_a_load_inverts_the_law(self):
        law = pc.ContactLaw(roughness=5e-3, mean_deformation=0.2, lam=1)
        for force in (1e-3, 0.1, 1.0, 6 * math.pi, 1e4):
            delta = law.overlap_under(force)
            self.assertAlmostEqual(law.normal(5e-3 - delta)[0] / force,
                                   1.0, 9)
        # The deformation rule: 6 pi eta gammaDot a1^2 at 0.2 h_r
        self.assertAlmostEqual(law.overlap_under(6 * math.pi) / 1e-3, 1.0, 3)

    def test_barrier_matches_the_cpp_golden_table(self):
        # Eq 2.57 as the C++ law evaluates it (tests/unit/contact/
        # contactLawTest.C writes the table): F_el/k_n to 1e-13
        table = np.loadtxt(pathlib.Path(__file__).resolve().parents[3]
                           / "tests" / "golden" / "contactBarrier.dat")
        self.assertEqual(len(table), 48)
        for hr, floor, gap, f in table:
            law = pc.ContactLaw(roughness=hr, gap_floor=floor, lam=1)
            self.assertAlmostEqual(law.normal(gap)[0] / law.kn, f,
                                   delta=1e-13 * f)


class PairTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.exact = pc.ExactPair(LAM)
        gaps = np.exp(np.linspace(math.log(1e-3), math.log(8.0), 40))
        vals = [pc.pair_functions(cls.exact.motion, g, LAM) for g in gaps]
        cls.functions = pc.FunctionPair(
            gaps, {f: [v[f] for v in vals] for f in pc.FUNCTIONS}, LAM)

    def test_eight_functions_give_the_full_motion(self):
        for gap, angle in ((0.004, 2.2), (0.3, 0.4)):
            d = np.array([math.cos(angle), math.sin(angle), 0.0])
            r = (2.4 + gap) * d
            F1 = np.array([0.3, -1.2, 0.0])
            Ft = F1 - (F1 @ d) * d
            l1, l2 = (2.4 + gap) / 2.4, LAM * (2.4 + gap) / 2.4
            loads = (F1, l1 * np.cross(d, Ft), l2 * np.cross(d, Ft))
            for a, b in zip(self.exact.motion(r, *loads),
                            self.functions.motion(r, *loads)):
                np.testing.assert_allclose(a, b, atol=1e-3 * gap + 1e-6)

    def test_smooth_pair_is_fore_aft_symmetric(self):
        law = pc.ContactLaw(roughness=1e-9, lam=LAM)
        tr = pc.trajectory(-6.0, 1.0, self.functions, law)
        self.assertAlmostEqual(tr["r"][-1, 1], 1.0, 3)

    def test_rough_pairs_leave_on_one_streamline(self):
        ends = [pc.trajectory(-6.0, y0, self.functions)["r"][-1, 1]
                for y0 in (0.25, 1.0)]
        self.assertGreater(ends[0], 1.0)
        self.assertAlmostEqual(ends[0], ends[1], 3)


if __name__ == "__main__":
    unittest.main()
