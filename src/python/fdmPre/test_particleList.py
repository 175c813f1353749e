import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from fdmPre.particleList import read_particle_list  # noqa: E402

PROJECT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                       "..", "..")


class ReadParticleList(unittest.TestCase):
    def write(self, text):
        f = tempfile.NamedTemporaryFile("w", delete=False, suffix="List")
        f.write(text)
        f.close()
        self.addCleanup(os.remove, f.name)
        return f.name

    def test_entries(self):
        path = self.write("// comment (x y z)\n2\n(\n(a (1 2 3) 1)\n"
                          "(b (4.5 -5e-1 6) 1.4)\n)\n")
        groups, x, r = read_particle_list(path)
        self.assertEqual(groups, ["a", "b"])
        np.testing.assert_array_equal(x, [[1, 2, 3], [4.5, -0.5, 6]])
        np.testing.assert_array_equal(r, [1, 1.4])

    def test_count_mismatch_names_file(self):
        path = self.write("3\n(\n(a (1 2 3) 1)\n)\n")
        with self.assertRaisesRegex(ValueError, os.path.basename(path)):
            read_particle_list(path)

    def test_reads_what_fdmPackParticles_writes(self):
        tool = os.path.join(PROJECT, "applications", "utilities",
                            "fdmPackParticles", "fdmPackParticles")
        out = os.path.join(tempfile.mkdtemp(), "particleList")
        subprocess.run([sys.executable, tool, "--box", "8", "8", "8",
                        "--walls", "", "--phi", "0.3", "--seed", "2",
                        "-o", out], check=True, stdout=subprocess.DEVNULL)
        groups, x, r = read_particle_list(out)
        self.assertEqual(set(groups), {"suspended"})
        self.assertAlmostEqual(4 / 3 * np.pi * np.sum(r ** 3) / 512, 0.3,
                               delta=0.01)
        self.assertTrue(np.all((x >= 0) & (x <= 8)))


if __name__ == "__main__":
    unittest.main()
