"""series_files and series_rows: the time-series files of restarted runs
are read in run order, a rerun from the same time included, one row per
time (the later run's)."""

import os
import tempfile
import unittest

import numpy as np

from fdmPost.particleCase import series_files, series_rows


def write(path, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    np.savetxt(path, rows, header="time value")


class SeriesTest(unittest.TestCase):
    def test_restarts_in_run_order(self):
        with tempfile.TemporaryDirectory() as case:
            d = os.path.join(case, "postProcessing", "balance")
            # first run 0..3 (killed), rerun from 0 to 2, restart 2..4
            write(os.path.join(d, "0", "balance.dat"),
                  [[0, 10], [1, 11], [2, 12], [3, 99]])
            write(os.path.join(d, "0", "balance_1.dat"),
                  [[0, 10], [1, 11], [2, 12]])
            write(os.path.join(d, "2", "balance.dat"),
                  [[2, 12], [3, 13], [4, 14]])
            write(os.path.join(d, "0", "other.dat"), [[0, -1]])
            files = series_files(case, "balance", "balance")
            self.assertEqual([os.path.relpath(f, d) for f in files],
                             ["0/balance.dat", "0/balance_1.dat",
                              "2/balance.dat"])
            rows = series_rows(files)
            np.testing.assert_array_equal(rows[:, 0], [0, 1, 2, 3, 4])
            # time 3: the restart's row, not the killed run's
            np.testing.assert_array_equal(rows[:, 1], [10, 11, 12, 13, 14])

    def test_header_only_files_are_skipped(self):
        with tempfile.TemporaryDirectory() as case:
            d = os.path.join(case, "postProcessing", "balance")
            # a run to 2, then two restarts at the end time (no steps)
            write(os.path.join(d, "0", "balance.dat"), [[0, 10], [2, 12]])
            write(os.path.join(d, "2", "balance.dat"), np.empty((0, 2)))
            write(os.path.join(d, "2", "balance_1.dat"), np.empty((0, 2)))
            rows = series_rows(series_files(case, "balance", "balance"))
            np.testing.assert_array_equal(rows, [[0, 10], [2, 12]])

    def test_missing_series_is_an_error(self):
        with tempfile.TemporaryDirectory() as case:
            with self.assertRaises(FileNotFoundError):
                series_files(case, "balance", "balance")


if __name__ == "__main__":
    unittest.main()
