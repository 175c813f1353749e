"""timing_lines reads the solver's Timing report (reportTimings.H) as the
benchmarks use it; the sample is a line pair fdmSuspensionFoam wrote.
work_lock keeps a second benchmark run out of a work folder in use;
run_measured and copy_case."""

import os
import sys
import tempfile
import unittest

from fdmPost.caseRunner import (TIMING_COLUMNS, copy_case, run_measured,
                                timing_lines, work_lock)

LOG = """Time = 2.004
Timing [s] after 12 outer iterations in 1 step(s): total 1, per step 1, \
per outer iteration 0.0833333333333
    flow 0.669359745, indicators 0.002540905, lambda/u integrals \
0.003383779, particle solve 0.00961074, corrections 0.004655032, \
acceleration 0.075277111, output 0.128903588, other (set-up, state \
copies) 0.1062691
End
"""


class TimingLinesTest(unittest.TestCase):
    def test_columns_of_a_report(self):
        rows = timing_lines(LOG + LOG.replace("12 outer", "30 outer"))
        self.assertEqual(len(rows), 2)
        row = dict(zip(TIMING_COLUMNS, rows[0]))
        self.assertEqual(row["outer"], 12)
        self.assertEqual(row["steps"], 1)
        self.assertEqual(row["flow"], 0.669359745)
        self.assertEqual(row["acceleration"], 0.075277111)
        self.assertEqual(row["output"], 0.128903588)
        self.assertEqual(row["pairs"], 0)   # a log from before the column
        self.assertEqual(rows[1][0], 30)

    def test_pair_column(self):
        log = LOG.replace("output 0.128903588,",
                          "output 0.128903588, pairs 0.0421,")
        row = dict(zip(TIMING_COLUMNS, timing_lines(log)[0]))
        self.assertEqual(row["pairs"], 0.0421)
        self.assertEqual(row["output"], 0.128903588)

    def test_no_report(self):
        self.assertEqual(timing_lines("Time = 0\nEnd\n"), [])


class RunMeasuredTest(unittest.TestCase):
    def test_peak_memory_of_the_command(self):
        """A child that holds 200 MiB reports at least that, and one that
        holds nothing far less (the interpreter's own size)."""
        with tempfile.TemporaryDirectory() as case:
            hold = ("b = bytearray(200 * 2**20); "
                    "b[::4096] = b'x' * len(b[::4096])")
            wall, big = run_measured([sys.executable, "-c", hold], case, "log")
            _, small = run_measured([sys.executable, "-c", "pass"], case,
                                    "log")
        self.assertGreater(big, 200 * 1024)
        self.assertLess(small, 100 * 1024)
        self.assertGreater(wall, 0)


class CopyCaseTest(unittest.TestCase):
    def test_only_the_set_up_is_copied_over_a_stale_case(self):
        with tempfile.TemporaryDirectory() as work:
            source, case = (os.path.join(work, n) for n in ("a", "b"))
            for d in ("0", "constant", "system", "1", "processor0"):
                os.makedirs(os.path.join(source, d))
                open(os.path.join(source, d, "f"), "w").write(d)
            os.makedirs(os.path.join(case, "2"))
            copy_case(source, case)
            self.assertEqual(sorted(os.listdir(case)),
                             ["0", "constant", "system"])
            self.assertEqual(open(os.path.join(case, "system", "f")).read(),
                             "system")


class WorkLockTest(unittest.TestCase):
    def test_second_holder_is_refused_until_the_first_ends(self):
        with tempfile.TemporaryDirectory() as work:
            first = work_lock(work)
            with self.assertRaises(SystemExit) as stop:
                work_lock(work)
            self.assertIn("in use by another run", str(stop.exception))
            first.close()   # as when the first process ends
            work_lock(work).close()


if __name__ == "__main__":
    unittest.main()
