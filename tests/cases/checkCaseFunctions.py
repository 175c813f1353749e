"""Unit tests of etc/caseFunctions: the restart guard removeIncompleteWrites
(a write cut short by a kill is removed, whole writes are kept),
setAdhesion (the adhesive contact law set in a copy of the Couette
tutorial's particleProperties, read back with foamDictionary), setTimeStep
(the step with records and writes kept in strain) and runSaving (a
checkpoint saved during a run and after it)."""

import os
import shutil
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


class TutorialCopy:
    """The Couette tutorial's files `paths` copied into a temporary case;
    the case functions called there, the dictionaries read back with
    foamDictionary."""

    TUTORIAL = os.path.join(os.path.dirname(FUNCTIONS), os.pardir,
                            "tutorials", "couette")

    def __init__(self, test, paths):
        tmp = tempfile.TemporaryDirectory()
        test.addCleanup(tmp.cleanup)
        self.case = tmp.name
        for path in paths:
            os.makedirs(os.path.join(self.case, os.path.dirname(path)),
                        exist_ok=True)
            shutil.copy(os.path.join(self.TUTORIAL, path),
                        os.path.join(self.case, path))
        # OpenFOAM warns on standard output when PWD is not the cwd
        self.env = dict(os.environ, PWD=self.case)

    def call(self, function, *args):
        subprocess.run(["bash", "-c", '. "$0" && ' + function + ' "$@"',
                        FUNCTIONS, *args], cwd=self.case, env=self.env,
                       check=True)

    def entry(self, path, key):
        return subprocess.run(
            ["foamDictionary", "-entry", key, "-value", path],
            cwd=self.case, env=self.env, check=True, capture_output=True,
            text=True).stdout.strip()


class SetAdhesion(unittest.TestCase):

    def test_sets_the_law_the_number_and_the_stiffness(self):
        case = TutorialCopy(self, ["constant/particleProperties"])
        case.call("setAdhesion", "2.5", "0.05")

        def entry(key):
            return case.entry("constant/particleProperties", "contact." + key)
        self.assertEqual(entry("model"), "adhesiveHertz")
        self.assertEqual(entry("adhesionNumber"), "2.5")
        self.assertEqual(entry("meanDeformation"), "0.05")
        self.assertEqual(entry("friction"), "0.5")


class SetTimeStep(unittest.TestCase):

    def test_keeps_records_and_writes_in_strain(self):
        """gammaDot deltaT 1e-3 with a record every 0.16 and a write every
        0.5 strain: 160 and 500 steps; an interval below the step: one."""
        case = TutorialCopy(self, ["system/controlDict",
                                   "constant/particleProperties"])
        case.call("setTimeStep", "1e-3", "0.16", "0.5")
        self.assertEqual(float(case.entry("system/controlDict", "deltaT")),
                         1e-3)
        self.assertEqual(case.entry("system/controlDict", "writeInterval"),
                         "500")
        self.assertEqual(case.entry("constant/particleProperties",
                                    "output.timeSeriesInterval"), "160")
        case.call("setTimeStep", "4e-3", "1e-3", "0.5")
        self.assertEqual(case.entry("system/controlDict", "writeInterval"),
                         "125")
        self.assertEqual(case.entry("constant/particleProperties",
                                    "output.timeSeriesInterval"), "1")


class RunSaving(unittest.TestCase):

    def test_saves_during_the_run_and_after_it(self):
        """A solver (a stand-in of 12 s that exits with 3) saved every 5 s:
        at least one save while it runs, one after it, its exit status."""
        tmp = tempfile.TemporaryDirectory()
        self.addCleanup(tmp.cleanup)
        script = ('. "$0"; fdmSuspensionFoam() { sleep 12; echo done; return 3; }; '
                  'runSaving 1 log.solver 5 sh -c "date +%s.%N >> saves"')
        out = subprocess.run(["bash", "-c", script, FUNCTIONS], cwd=tmp.name)
        self.assertEqual(out.returncode, 3)
        with open(os.path.join(tmp.name, "saves")) as f:
            saves = [float(t) for t in f.read().split()]
        with open(os.path.join(tmp.name, "log.solver")) as f:
            self.assertEqual(f.read(), "done\n")
        self.assertGreaterEqual(len(saves), 2)
        self.assertLessEqual(len(saves), 3)
        # The first save at about 5 s, the last after the solver stopped
        # at 12 s
        self.assertGreaterEqual(saves[-1] - saves[0], 5)


if __name__ == "__main__":
    unittest.main()
