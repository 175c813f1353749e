"""Unit tests of fdmPost.particleFiles (no case, no VTK)."""

import json
import os
import tempfile
import unittest

import numpy as np

from fdmPost import particleFiles


class ContactSums(unittest.TestCase):
    def test_pairs_and_walls(self):
        # Pair 0-1 with F on 0, wall contact of 2 (j = -1): 1 gets -F,
        # the wall nothing
        lines = {"i": np.array([0, 2]), "j": np.array([1, -1]),
                 "force": np.array([[-4.0, 1, 0], [0, 5, 0]])}
        total = particleFiles.contact_sums(lines, 3)
        np.testing.assert_array_equal(
            total, [[-4, 1, 0], [4, -1, 0], [0, 5, 0]])

    def test_no_contacts(self):
        self.assertEqual(np.abs(particleFiles.contact_sums({}, 2)).max(), 0)


class ReadSeries(unittest.TestCase):
    def test_times_to_paths(self):
        with tempfile.TemporaryDirectory() as case:
            os.mkdir(os.path.join(case, "VTK"))
            with open(os.path.join(case, "VTK", "particles.vtp.series"),
                      "w") as f:
                json.dump({"file-series-version": "1.0", "files": [
                    {"name": "particles_0.vtp", "time": 0},
                    {"name": "particles_0.5.vtp", "time": 0.5}]}, f)
            series = particleFiles.read_series(case, "particles")
            self.assertEqual(sorted(series), [0.0, 0.5])
            self.assertEqual(series[0.5],
                             os.path.join(case, "VTK", "particles_0.5.vtp"))


if __name__ == "__main__":
    unittest.main()
