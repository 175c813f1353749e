"""Unit tests of fdmPost.rheology against exact geometry and stress
identities."""

import os
import tempfile
import unittest

import h5py
import numpy as np
import scipy.signal

from fdmPost.rheology import (CouetteSeries, autocorrelation_time,
                              block_mean, channel_case, core_rheology,
                              core_series,
                              mechanical_consistency, slab_volume,
                              symm6_to_tensor)


class SlabVolume(unittest.TestCase):
    def test_whole_sphere_and_cap(self):
        a = 1.3
        self.assertAlmostEqual(slab_volume(0.0, a, -5, 5), 4 / 3 * np.pi * a**3, 12)
        # Cap of height h: pi h^2 (3a - h)/3
        h = 0.4
        self.assertAlmostEqual(slab_volume(0.0, a, a - h, 9),
                               np.pi * h**2 * (3 * a - h) / 3, 12)
        # Slabs add up
        e = np.linspace(-2, 2, 7)
        self.assertAlmostEqual(sum(slab_volume(0.1, a, e[i], e[i + 1])
                                   for i in range(6)), 4 / 3 * np.pi * a**3, 12)


class GoldenTable(unittest.TestCase):
    """The channel averages as the C++ (fdm::channelAverages, behind the
    suspensionStress function object) computes them for the sample stored
    in tests/golden/channelAverages.dat (written by
    tests/unit/rheology/channelAveragesTest.C): the same values here."""

    def test_matches_the_cpp_golden_table(self):
        path = os.path.join(os.path.dirname(__file__), "..", "..", "..",
                            "tests", "golden", "channelAverages.dat")
        particles, rows = [], {}
        with open(path) as f:
            lines = [x for x in f if x.strip() and not x.startswith("#")]
        for line in lines:
            words = line.split()
            if words[0] == "particle":
                particles.append([float(w) for w in words[1:]])
            else:
                rows[words[0]] = np.array([float(w) for w in words[1:]])
        p = np.array(particles)
        self.assertEqual(p.shape, (16, 19))
        data = dict(time=np.zeros(1), position=p[None, :, 0:3],
                    velocity=p[None, :, 3:6], radius=p[:, 6],
                    stresslet=p[None, :, 7:13],
                    dipoleTrace=np.zeros((1, len(p))),
                    contactStresslet=p[None, :, 13:19])
        cs = CouetteSeries(data, lo=(0, 0, 0), span=(10, 10, 10), eta=1.0,
                           layer=2.0)
        six = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]

        def close(name, values):
            np.testing.assert_allclose(values, rows[name], rtol=1e-13,
                                       atol=1e-13, err_msg=name)

        close("corePhi", [cs.core_volume_fraction(0)])
        close("coreShearRate", [cs.core_shear_rate(0)])
        hp, c = cs.core_stresses(0)
        close("coreHydrodynamic", [hp[i, j] for i, j in six])
        close("coreContact", [c[i, j] for i, j in six])
        _, phi, up = cs.profiles(5, [0])
        close("binPhi", phi)
        close("binVelocityFlow", up)
        hp, c = cs.stress_profiles(5, [0])
        bins = [(b, i, j) for b in range(5) for i, j in six]
        close("binHydrodynamic", [hp[k] for k in bins])
        close("binContact", [c[k] for k in bins])


class Couette(unittest.TestCase):
    def make(self):
        # 4 spheres on a linear velocity profile u = 0.8 y; stresslets
        # chosen by hand; box 10 x 10 x 10 from -5, wall layer 2
        T, N = 3, 4
        y = np.array([-4.0, -1.0, 1.0, 4.0])
        x = np.zeros((T, N, 3))
        x[:, :, 1] = y
        u = np.zeros((T, N, 3))
        u[:, :, 0] = 0.8 * y
        S = np.zeros((T, N, 6))
        S[:, :, 1] = 2.0          # S_xy = 2 on every particle
        sc = np.zeros((T, N, 6))
        sc[:, :, 0] = -1.0        # contact xx
        sc[:, :, 1] = 0.5         # contact xy
        data = dict(time=np.arange(T, dtype=float), position=x, velocity=u,
                    radius=np.ones(N), stresslet=S,
                    dipoleTrace=np.full((T, N), -3.0), contactStresslet=sc)
        return CouetteSeries(data, lo=(-5, -5, -5), span=(10, 10, 10), eta=2.0,
                             layer=2.0)

    def test_core_quantities(self):
        cs = self.make()
        self.assertAlmostEqual(cs.core_shear_rate(0), 0.8, 12)
        hp, c = cs.core_stresses(0)
        V = 100 * 6
        # Two core particles: S_xy 2 each, trace -3 each
        self.assertAlmostEqual(hp[0, 1], 4 / V, 14)
        self.assertAlmostEqual(hp[1, 1], 2 * (-1.0) / V, 14)
        self.assertAlmostEqual(c[0, 0], -2 / V, 14)
        # phi_core: two unit spheres inside the core slab of 600
        self.assertAlmostEqual(cs.core_volume_fraction(0),
                               2 * 4 / 3 * np.pi / V, 12)

    def test_core_series_by_hand(self):
        cs = self.make()
        V = 100 * 6
        # Sigma_xy = eta gammaDot + (2 S_xy + 2 contact xy)/V per record
        sxy = 2.0 * 0.8 + (4 + 1) / V
        row = core_series(cs)[0]
        self.assertAlmostEqual(row[0], sxy / (2.0 * 0.8), 12)
        # xx: contact -1 per particle and the trace -3/3 of the dipole;
        # yy: the trace only; zz: the same as yy
        s_xx, s_yy = (2 * (-1.0) + 2 * (-1.0)) / V, 2 * (-1.0) / V
        self.assertAlmostEqual(row[1], (s_xx - s_yy) / sxy, 12)
        self.assertAlmostEqual(row[2], 0.0, 12)
        self.assertAlmostEqual(row[3], (1 / V) / sxy, 12)

    def test_core_rheology_by_hand(self):
        cs = self.make()
        V = 100 * 6
        sxy = 2.0 * 0.8 + (4 + 1) / V
        r = core_rheology(cs, 0.0, blocks=3)
        self.assertEqual(r["records"], 3)
        self.assertAlmostEqual(r["etaCore"][0], sxy / (2.0 * 0.8), 12)
        self.assertAlmostEqual(r["shearStress"][0], sxy, 12)
        self.assertAlmostEqual(r["contactShare"][0], (1 / V) / sxy, 12)
        # contact xx -1 on each of the two core particles, yy and zz none
        self.assertAlmostEqual(r["contact11"][0], (-2 / V) / sxy, 12)
        self.assertEqual(r["contact22"][0], 0.0)
        self.assertEqual(r["contact33"][0], 0.0)
        self.assertAlmostEqual(r["contact11"][1], 0.0, 12)

    def test_profile_integrates_to_mean_fraction(self):
        cs = self.make()
        yb, phi, up = cs.profiles(40, [0, 1])
        self.assertAlmostEqual(phi.mean(), 4 * 4 / 3 * np.pi / 1000, 12)
        # Velocity profile weighted by the indicator is the centre velocity
        # where one sphere fills the slab
        k = np.argmin(abs(yb - 1.0))
        self.assertAlmostEqual(up[k], 0.8, 12)

    def test_symm6(self):
        t = symm6_to_tensor(np.arange(6.0))
        self.assertTrue(np.array_equal(t, t.T))
        self.assertEqual(t[1, 2], 4.0)

    def test_block_mean(self):
        m, e = block_mean(np.r_[np.zeros(5), np.ones(5)], blocks=2)
        self.assertAlmostEqual(m, 0.5)
        self.assertAlmostEqual(e, 0.5)

    def test_autocorrelation_time_of_ar1(self):
        # AR(1) x_k = r x_{k-1} + noise: rho_k = r^k, so
        # tau = dx (1/2 + r/(1 - r)) = dx (1 + r)/(2 (1 - r)) exactly
        r, dx = 0.8, 0.01
        rng = np.random.default_rng(3)
        noise = rng.standard_normal(100000)
        x = scipy.signal.lfilter([1.0], [1.0, -r], noise)
        exact = dx * (1 + r) / (2 * (1 - r))
        self.assertAlmostEqual(autocorrelation_time(x, dx) / exact, 1.0,
                               delta=0.05)
        white = autocorrelation_time(noise, dx)
        self.assertAlmostEqual(white / (0.5 * dx), 1.0, delta=0.05)


class MechanicalConsistency(unittest.TestCase):
    def test_columns_from_known_imbalances(self):
        """Loads built with known relative imbalances per column: the
        wall force off by 2 % of itself, lambda parts off by 1e-7, the
        hydrodynamic force and torque off by 3e-3 and 5e-3 of contact."""
        rng = np.random.default_rng(1)
        t = np.arange(6.0)
        Fc, Tc = rng.normal(size=(2, 6, 4, 3))
        wall = rng.normal(size=(6, 3))
        with tempfile.TemporaryDirectory() as case:
            os.makedirs(f"{case}/postProcessing/momentumBalance/0")
            with h5py.File(f"{case}/postProcessing/particles.h5", "w") as f:
                f["time"] = t
                f["contactForce"], f["contactTorque"] = Fc, Tc
                Fh = -1.003 * Fc
                Fh[0] = 0   # before the start: must not count
                f["force"], f["torque"] = Fh, -1.005 * Tc
            parts = -1.02 * wall
            parts[0] = 0
            rows = np.column_stack((t, parts * (1 + 1e-7), parts, wall,
                                    np.zeros((6, 6))))
            np.savetxt(f"{case}/postProcessing/momentumBalance/0/"
                       "momentumBalance.dat", rows)
            m = mechanical_consistency(case, 1.0)
        np.testing.assert_allclose(m[0], 0.02, rtol=1e-9)
        np.testing.assert_allclose(m[1], 1e-7 / (1 + 1e-7), rtol=1e-6)
        np.testing.assert_allclose(m[2], 3e-3, rtol=1e-9)
        np.testing.assert_allclose(m[3], 5e-3, rtol=1e-9)



class CaseDescription(unittest.TestCase):
    """channel_case takes box, viscosity and shear rate from particles.h5's
    attributes, and from the dictionaries for a file without them."""

    def write_case(self, d, attrs):
        os.makedirs(f"{d}/postProcessing")
        with h5py.File(f"{d}/postProcessing/particles.h5", "w") as f:
            f["time"] = [0.0]
            f["position"] = np.full((1, 1, 3), 2.0)
            f["velocity"] = np.zeros((1, 1, 3))
            f["radius"] = [1.0]
            f["stresslet"] = np.zeros((1, 1, 6))
            f["dipoleTrace"] = np.zeros((1, 1))
            f.attrs.update(attrs)

    def test_from_attributes(self):
        with tempfile.TemporaryDirectory() as d:
            self.write_case(d, {"boxMin": [1.0, -2.0, 0.0],
                                "boxMax": [9.0, 6.0, 4.0],
                                "viscosity": 3.0, "shearRate": 0.5,
                                "meshSpacing": 0.2, "solver": "x"})
            cs, L, run = channel_case(d, 1.0)
        np.testing.assert_array_equal(L, [8, 8, 4])
        np.testing.assert_array_equal(cs.lo, [1, -2, 0])
        self.assertEqual((cs.eta, run["shearRate"], run["solver"]),
                         (3.0, 0.5, "x"))
        self.assertEqual(cs.core, (-1.0, 5.0))

    def test_lees_edwards_box_takes_its_imposed_rate(self):
        # Periodic along y and sheared: the whole box (layer 0) at the
        # imposed rate, not the particles' regression (one particle here,
        # which has none); walls (periodic x z only): the regression
        attrs = {"boxMin": [0.0, 0.0, 0.0], "boxMax": [4.0, 4.0, 4.0],
                 "viscosity": 1.0, "shearRate": 0.5, "meshSpacing": 0.2}
        with tempfile.TemporaryDirectory() as d:
            self.write_case(d, {**attrs, "periodic": [1.0, 1.0, 1.0]})
            cs, _, _ = channel_case(d, 0.0)
        self.assertEqual(cs.core, (0.0, 4.0))
        self.assertEqual(cs.core_shear_rate(0), 0.5)
        # The unit sphere at y = 2 moved across the face y = 4: whole
        cs.x[0, 0, 1] = 3.5
        self.assertAlmostEqual(cs.core_volume_fraction(0),
                               4 / 3 * np.pi / 64, 14)
        # The part across the face is its image one period down, slower by
        # gammaDot L_y = 2: the bottom bin's particle velocity
        cs.u[0, 0, 0] = 0.75
        yb, phi, up = cs.profiles(4, [0])
        self.assertAlmostEqual(phi.sum() / 4, 4 / 3 * np.pi / 64, 14)
        self.assertAlmostEqual(up[3], 0.75, 14)
        self.assertAlmostEqual(up[0], -1.25, 14)
        with tempfile.TemporaryDirectory() as d:
            self.write_case(d, {**attrs, "periodic": [1.0, 0.0, 1.0]})
            cs, _, _ = channel_case(d, 0.0)
        self.assertTrue(np.isnan(cs.core_shear_rate(0)))

    def test_from_dictionaries_without_attributes(self):
        with tempfile.TemporaryDirectory() as d:
            self.write_case(d, {})
            for sub, text in (
                    ("system/blockMeshDict", "Lx 8;\nLy 10;\nLz 4;\nnx 40;\n"),
                    ("constant/transportProperties", "nu 2;\nrho 1.5;\n"),
                    ("0/U", "bottomWall { value uniform (-1 0 0); }\n"
                            "topWall { value uniform (4 0 0); }\n")):
                os.makedirs(os.path.dirname(f"{d}/{sub}"), exist_ok=True)
                open(f"{d}/{sub}", "w").write(text)
            cs, L, run = channel_case(d, 1.0)
        np.testing.assert_array_equal(L, [8, 10, 4])
        self.assertEqual((cs.eta, run["shearRate"], run["meshSpacing"]),
                         (3.0, 0.5, 0.2))

if __name__ == "__main__":
    unittest.main()
