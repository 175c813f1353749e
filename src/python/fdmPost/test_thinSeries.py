"""Unit tests of fdmPost.thinSeries: segments joined on time give the whole
series, the thinned file keeps the series to single precision and the
run's attributes, the rows of an OpenFOAM `forces` force.dat (v1912 layout)
are parsed and joined, and checkpoint.save keeps both."""

import os
import tempfile
import unittest

import numpy as np

from fdmPost import checkpoint, thinSeries
from fdmPost.test_coreRecords import synthetic_run, write_case

FORCE_DAT = """# Force
# CofR                : (0.000000e+00 0.000000e+00 0.000000e+00)
#
# Time                   \t(total_x total_y total_z)\t(pressure_x pressure_y pressure_z)\t(viscous_x viscous_y viscous_z)
{t}                     \t(-1.00994412591654182e+02 3.69733719976051145e-01 9.42718387960256088e+00)\t(2.98566286352278408e-17 3.69733712862326314e-01 -3.31261988595263129e-17)\t(-1.00994412591654182e+02 7.11372482301418792e-09 9.42718387960256088e+00)
"""


class Joined(unittest.TestCase):
    def test_segments_give_the_whole_series(self):
        data = synthetic_run()
        a = thinSeries.until(data, 2.4)
        b = {k: (v if k == "radius" else v[20:]) for k, v in data.items()}
        whole = thinSeries.joined(a, b)
        for k in ("time",) + thinSeries.SERIES:
            np.testing.assert_array_equal(whole[k], data[k], err_msg=k)

    def test_round_trip_in_single_precision(self):
        data = synthetic_run()
        with tempfile.TemporaryDirectory() as d:
            thinSeries.write(f"{d}/p.h5", data, {"shearRate": 1.0})
            back, attrs = thinSeries.read(f"{d}/p.h5")
        self.assertEqual(attrs["shearRate"], 1.0)
        np.testing.assert_array_equal(back["time"], data["time"])
        for k in thinSeries.SERIES:
            np.testing.assert_allclose(back[k], data[k], rtol=1e-6,
                                       atol=1e-6, err_msg=k)


class ForceRows(unittest.TestCase):
    def test_force_dat_rows_in_run_order(self):
        with tempfile.TemporaryDirectory() as d:
            for t0, times in (("0", (0.01, 0.02, 0.03)), ("0.02", (0.03, 0.04))):
                os.makedirs(f"{d}/postProcessing/lid/{t0}")
                with open(f"{d}/postProcessing/lid/{t0}/force.dat", "w") as f:
                    f.write("".join(FORCE_DAT.format(t=t) if i == 0 else
                                    FORCE_DAT.format(t=t).splitlines(True)[-1]
                                    for i, t in enumerate(times)))
            rows = thinSeries.case_force_rows(d, "lid")
        np.testing.assert_allclose(rows[:, 0], [0.01, 0.02, 0.03, 0.04])
        np.testing.assert_allclose(rows[0, 1:], [-100.994412591654182,
                                                 0.369733719976051145,
                                                 9.42718387960256088])

    def test_a_segment_without_force_rows_joins(self):
        with tempfile.TemporaryDirectory() as d:
            thinSeries.write_force_rows(f"{d}/lid.csv", np.zeros((0, 4)))
            empty = thinSeries.read_force_rows(f"{d}/lid.csv")
        self.assertEqual(empty.shape, (0, 4))
        later = np.array([[0.16, -1.0, 0.0, 0.0]])
        np.testing.assert_array_equal(thinSeries.joined_rows(empty, later),
                                      later)

    def test_checkpoint_keeps_particles_and_forces(self):
        data = synthetic_run()
        with tempfile.TemporaryDirectory() as d:
            write_case(f"{d}/run", data, ["3.5"])
            os.makedirs(f"{d}/run/postProcessing/lid/0")
            with open(f"{d}/run/postProcessing/lid/0/force.dat", "w") as f:
                f.write(FORCE_DAT.format(t=3.5) + FORCE_DAT.format(t=4.0)
                        .splitlines(True)[-1])
            checkpoint.save(f"{d}/run", f"{d}/ck", particles=True,
                            forces=["lid"])
            kept, _ = thinSeries.read(f"{d}/ck/particles.h5")
            rows = thinSeries.read_force_rows(f"{d}/ck/lid.csv")
        self.assertEqual(kept["time"][-1], 3.5)
        self.assertEqual(len(kept["time"]), 36)
        np.testing.assert_allclose(rows[:, 0], [3.5])


if __name__ == "__main__":
    unittest.main()
