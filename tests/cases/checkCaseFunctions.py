"""Unit tests of the restart guard removeIncompleteWrites (etc/caseFunctions):
a write cut short by a kill is removed, whole writes are kept."""

import os
import subprocess
import tempfile
import unittest

FUNCTIONS = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                         os.pardir, os.pardir, "etc", "caseFunctions")


def touch(path):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("x\n")


def write_time(case, time, procs, missing=()):
    """A written time: particleState in the case, U and p per processor
    (in the case itself when procs is 0), less the paths in `missing`."""
    files = [os.path.join(time, "particleState")]
    dirs = ["processor%d" % p for p in range(procs)] or ["."]
    files += [os.path.join(d, time, f) for d in dirs for f in ("U", "p")]
    for f in files:
        if f not in missing:
            touch(os.path.join(case, f))


def guard(case, procs):
    out = subprocess.run(
        ["bash", "-c", '. "$0" && removeIncompleteWrites "$1"', FUNCTIONS,
         str(max(procs, 1))], cwd=case, capture_output=True, text=True,
        check=True)
    return out.stdout


class RemoveIncompleteWrites(unittest.TestCase):

    def layout(self, procs, newest_missing=()):
        tmp = tempfile.TemporaryDirectory()
        self.addCleanup(tmp.cleanup)
        case = tmp.name
        for p in range(procs):
            os.makedirs(os.path.join(case, "processor%d" % p, "0"))
        os.makedirs(os.path.join(case, "0"), exist_ok=True)
        write_time(case, "1.5", procs)
        write_time(case, "10", procs, newest_missing)
        return case

    def test_missing_processor_field_removes_the_write(self):
        case = self.layout(2, ["processor1/10/p"])
        self.assertIn("removing incomplete write 10", guard(case, 2))
        for d in (".", "processor0", "processor1"):
            self.assertFalse(os.path.exists(os.path.join(case, d, "10")))
            self.assertTrue(os.path.exists(os.path.join(case, d, "1.5")))

    def test_missing_particle_state_removes_the_write(self):
        case = self.layout(2, ["10/particleState"])
        guard(case, 2)
        self.assertFalse(os.path.exists(os.path.join(case, "processor0",
                                                     "10")))
        self.assertTrue(os.path.exists(os.path.join(case, "1.5",
                                                    "particleState")))

    def test_whole_writes_are_kept(self):
        case = self.layout(2)
        self.assertEqual(guard(case, 2), "")
        self.assertTrue(os.path.exists(os.path.join(case, "processor1", "10",
                                                    "p")))

    def test_serial_case(self):
        case = self.layout(0, ["./10/U"])
        guard(case, 0)
        self.assertFalse(os.path.exists(os.path.join(case, "10")))
        self.assertTrue(os.path.exists(os.path.join(case, "1.5", "U")))


if __name__ == "__main__":
    unittest.main()
