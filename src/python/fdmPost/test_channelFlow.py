"""Unit tests of fdmPost.channelFlow on synthetic fields (no case)."""

import unittest

import numpy as np

from fdmPost import channelFlow as cf

N = np.array([4, 10, 3])        # nx, ny, nz
L = np.array([2.0, 5.0, 1.5])


def cell_centres():
    c = [(np.arange(k) + 0.5) * l / k for k, l in zip(N, L)]
    Z, Y, X = np.meshgrid(c[2], c[1], c[0], indexing="ij")
    return X.ravel(), Y.ravel(), Z.ravel()


class ChannelFlow(unittest.TestCase):

    def test_layer_means_follow_the_blockmesh_numbering(self):
        X, Y, Z = cell_centres()
        field = np.column_stack([3 * Y + X - 1.0, Z, 0 * X])
        means = cf.layer_means(field, N)
        y = (np.arange(N[1]) + 0.5) * L[1] / N[1]
        self.assertLess(np.abs(means[:, 0] - 3 * y).max(), 1e-12)
        self.assertLess(np.abs(means[:, 1] - L[2] / 2).max(), 1e-12)

    def test_bin_shear_rate_of_a_linear_profile_is_exact(self):
        # Couette U = g y with U = 0 at y = 0: the wall value is consistent
        y = (np.arange(N[1]) + 0.5) * L[1] / N[1]
        U = 0.7 * y
        rate = cf.shear_rate_bins(U, np.linspace(0, L[1] / 2, 4), L[1])
        self.assertLess(np.abs(rate - 0.7).max(), 1e-12)

    def test_bin_shear_rate_of_the_parabola(self):
        # U = y (H - y): bins away from the walls within (Delta/H)^2
        H, n = 10.0, 50
        y = (np.arange(n) + 0.5) * H / n
        edges = np.linspace(0, H, 11)
        rate = cf.shear_rate_bins(y * (H - y), edges, H)
        mid = 0.5 * (edges[1:] + edges[:-1])
        exact = H - 2 * mid
        self.assertLess(np.abs(rate - exact)[1:-1].max(), 1e-12)
        self.assertLess(np.abs(rate - exact).max(), (H / n) ** 2)

    def test_stress_line_recovers_slope_and_level(self):
        yb = np.linspace(0.5, 9.5, 10)
        slope, level = cf.shear_stress_line(yb, 0.2 - 0.4 * (yb - 5), 10.0,
                                            yb > 1)
        self.assertAlmostEqual(slope, -0.4, places=12)
        self.assertAlmostEqual(level, 0.2, places=12)

    def test_fluid_pressure_skips_the_particles(self):
        X, Y, Z = cell_centres()
        p = np.where(Y < 2.5, 1.0, -1.0)                 # mean 0
        whole = cf.fluid_pressure(p, N, L, [], [])
        self.assertLess(np.abs(whole - np.repeat([1.0, -1.0], 5)).max(), 1e-12)
        # a sphere on the periodic x boundary covers the centres of 2 of
        # the first layer's 12 cells, one on each side (11/12 unwrapped)
        centre = (0.0, 0.25, 0.25)
        part = cf.fluid_pressure(p, N, L, [centre], [0.3])
        self.assertAlmostEqual(part[0], 10 / 12, places=12)
        self.assertLess(np.abs(part[1:] - whole[1:]).max(), 1e-12)


if __name__ == "__main__":
    unittest.main()
