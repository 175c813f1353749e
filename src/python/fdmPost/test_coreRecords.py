"""Unit tests of fdmPost.coreRecords and fdmPost.checkpoint: a run cut
into segments (each restarted at the time of its checkpoint, its first
record written again) and joined gives the core averages of the unbroken
run; the table round trip; the wall layers' phi against the phi(y)
profile; the summary of a checkpoint is that of all its records; save
keeps records only up to the saved state
and never replaces a later checkpoint; restore marks the state cold and
copies the fields of time 0."""

import os
import tempfile
import unittest

import numpy as np

from fdmPost import checkpoint
from fdmPost.coreRecords import CoreRecords
from fdmPost.rheology import CouetteSeries, core_rheology

BOX = np.array([6.0, 8.0, 6.0])


def synthetic_run(records=60, particles=12, seed=3):
    """A Couette series with random positions, a linear velocity profile
    and random stresslets (the averages need no physics)."""
    rng = np.random.default_rng(seed)
    t = 0.1 * np.arange(records)
    x = rng.uniform(0, 1, (records, particles, 3)) * BOX
    u = np.zeros_like(x)
    u[..., 0] = x[..., 1] - BOX[1] / 2 + rng.normal(0, 0.1, x.shape[:2])
    return {"time": t, "position": x, "velocity": u,
            "radius": np.full(particles, 0.8),
            "stresslet": rng.normal(0, 1, (records, particles, 6)),
            "dipoleTrace": rng.normal(0, 1, (records, particles)),
            "contactStresslet": rng.normal(0, 1, (records, particles, 6))}


def series(data, keep=slice(None)):
    part = {k: (v if k == "radius" else v[keep]) for k, v in data.items()}
    return CouetteSeries(part, lo=np.zeros(3), span=BOX, eta=1.0, layer=2.0)


META = {"shearRate": 1.0, "box": BOX, "layer": 2.0}


class JoinedSegments(unittest.TestCase):
    def test_segments_give_the_unbroken_averages(self):
        data = synthetic_run()
        whole = core_rheology(series(data), 1.0)
        # Segments restarted at records 20 and 41, each writing its first
        # record again (the earlier segments reach past the restart)
        a = CoreRecords.from_series(series(data, slice(0, 25)), META)
        b = CoreRecords.from_series(series(data, slice(20, 45)), META)
        c = CoreRecords.from_series(series(data, slice(41, None)), META)
        joined = a.joined(b).joined(c)
        np.testing.assert_array_equal(joined.t, data["time"])
        parts = core_rheology(joined, 1.0)
        for key in ("etaCore", "phiCore", "N1", "N2", "contact22"):
            np.testing.assert_allclose(parts[key], whole[key], rtol=1e-12,
                                       err_msg=key)
        self.assertEqual(parts["records"], whole["records"])

    def test_table_round_trip(self):
        records = CoreRecords.from_series(series(synthetic_run()), META)
        with tempfile.TemporaryDirectory() as d:
            records.write(f"{d}/coreRecords.csv")
            back = CoreRecords.read(f"{d}/coreRecords.csv")
        self.assertEqual(back.meta["layer"], 2.0)
        np.testing.assert_allclose(back.meta["box"], BOX)
        for name in ("t", "g", "phi", "hp", "c"):
            np.testing.assert_allclose(getattr(back, name),
                                       getattr(records, name), rtol=1e-8,
                                       atol=1e-12, err_msg=name)

    def test_summary_is_over_every_record_from_start(self):
        data = synthetic_run()
        whole = core_rheology(series(data), 1.0)
        with tempfile.TemporaryDirectory() as d:
            CoreRecords.from_series(series(data), META).write(
                f"{d}/coreRecords.csv")
            text = checkpoint.summary(d, 1.0)
        self.assertIn(f"{whole['records']} records from strain 1", text)
        self.assertIn(f"eta_core {whole['etaCore'][0]:.3f} +- "
                      f"{whole['etaCore'][1]:.3f}", text)
        with tempfile.TemporaryDirectory() as d:
            CoreRecords.from_series(series(data), META).write(
                f"{d}/coreRecords.csv")
            self.assertIn("no records from strain 99",
                          checkpoint.summary(d, 99.0))

    def test_wall_phi_is_the_profile_of_the_wall_layers(self):
        # phi(y) on 1-wide bins (CouetteSeries.profiles) over the two
        # 2-wide wall layers of the 8-high cell, against the per-record
        # wall phi averaged over the records
        cs = series(synthetic_run())
        records = CoreRecords.from_series(cs, META)
        y, phi, _ = cs.profiles(8, range(len(cs.t)))
        wall = phi[(y < 2) | (y > 6)].mean()
        self.assertAlmostEqual(records.phi_wall.mean(), wall, delta=1e-12)

    def test_until_keeps_the_records_up_to_a_state(self):
        records = CoreRecords.from_series(series(synthetic_run()), META)
        self.assertEqual(records.until(2.0).t[-1], 2.0)
        self.assertEqual(len(records.until(2.0).t), 21)


def write_case(case, data, times):
    """A case directory with particles.h5 (the run attributes that
    case_description reads) and particle states at `times`."""
    import h5py
    os.makedirs(f"{case}/postProcessing")
    with h5py.File(f"{case}/postProcessing/particles.h5", "w") as f:
        for k, v in data.items():
            f[k] = v
        f.attrs.update(boxMin=np.zeros(3), boxMax=BOX, viscosity=1.0,
                       shearRate=1.0)
    os.makedirs(f"{case}/0")
    with open(f"{case}/0/U", "w") as f:
        f.write("U of time 0\n")
    for t in times:
        os.makedirs(f"{case}/{t}")
        with open(f"{case}/{t}/particleState", "w") as f:
            f.write(f"FoamFile {{ object particleState; }}\nnParticles 12;"
                    f"\n// state of time {t}\n")


class SaveAndRestore(unittest.TestCase):
    def test_save_restore_and_refusal(self):
        data = synthetic_run()
        with tempfile.TemporaryDirectory() as d:
            write_case(f"{d}/run", data, ["2", "3.5"])
            # A time written later but cut short has no particle state
            os.makedirs(f"{d}/run/4")
            # A copy that a kill cut short is not a state
            os.makedirs(f"{d}/ck")
            with open(f"{d}/ck/particleState.9.tmp", "w") as f:
                f.write("cut short")
            checkpoint.save(f"{d}/run", f"{d}/ck", layer=2.0)
            self.assertEqual(checkpoint.checkpoint_state(f"{d}/ck")[0], "3.5")
            self.assertFalse(os.path.exists(f"{d}/ck/particleState.9.tmp"))
            saved = CoreRecords.read(f"{d}/ck/coreRecords.csv")
            self.assertEqual(saved.t[-1], 3.5)

            # An older run does not replace the later checkpoint
            write_case(f"{d}/old", data, ["2"])
            with self.assertRaises(SystemExit):
                checkpoint.save(f"{d}/old", f"{d}/ck", layer=2.0)
            self.assertEqual(checkpoint.checkpoint_state(f"{d}/ck")[0], "3.5")

            os.makedirs(f"{d}/fresh/0")
            os.makedirs(f"{d}/fresh/system")
            with open(f"{d}/fresh/0/U", "w") as f:
                f.write("U of time 0\n")
            # A case that would start at time 0 is refused
            with open(f"{d}/fresh/system/controlDict", "w") as f:
                f.write("startFrom       startTime;\n")
            with self.assertRaises(SystemExit):
                checkpoint.restore(f"{d}/ck", f"{d}/fresh", 1)
            with open(f"{d}/fresh/system/controlDict", "w") as f:
                f.write("startFrom       latestTime;\n")
            self.assertEqual(checkpoint.restore(f"{d}/ck", f"{d}/fresh", 1),
                             "3.5")
            with open(f"{d}/fresh/3.5/particleState") as f:
                state = f.read()
            self.assertIn("state of time 3.5", state)
            self.assertRegex(state, r"\ncoldFluid\s+true;\n$")
            self.assertTrue(os.path.isfile(f"{d}/fresh/3.5/U"))
            # A case with written times continues from its own
            with self.assertRaises(SystemExit):
                checkpoint.restore(f"{d}/ck", f"{d}/run", 1)


if __name__ == "__main__":
    unittest.main()
