"""Checks of the contactOnWall case test (see contactOnWall.sh)."""

import sys

import h5py
import numpy as np

from fdmPost.checks import Checks
from fdmPost.foamCloud import check_case
from fdmResistance.pairContact import ContactLaw

# Case data: a = 1, eta = 1, h_r = 5e-3, mu = 0.5, k_n from
# 6 pi eta gammaDot a^2 = k_n (0.2 h_r)^1.5, gapFloor 1e-5
W = 6 * np.pi
hr, mu, floor, dt = 5e-3, 0.5, 1e-5, 0.05
# The contact law of eq 2.57 (tested against the C++ law on the golden
# table tests/golden/contactBarrier.dat); a wall contact has floor gap 1e-5 a
LAW = ContactLaw(roughness=hr, friction=mu, mean_deformation=0.2,
                 gap_floor=floor, lam=1)


def elastic_force(gap):
    """Eq 2.57 for a wall contact."""
    return LAW.normal(float(gap))[0]


def last(path):
    """The last record, and the velocity of the one before (a record per
    step: the Adams-Bashforth history of the last step)."""
    with h5py.File(path, "r") as f:
        out = {k: f[k][-1] for k in ("time", "position", "velocity",
                                     "angularVelocity", "contactForce",
                                     "force")}
        out["previousVelocity"] = f["velocity"][-2]
        return out


def record(path, time):
    """The record at `time` of every series."""
    with h5py.File(path, "r") as f:
        k = int(np.argmin(np.abs(f["time"][:] - time)))
        return {name: f[name][k] for name in f if name not in ("radius", "group")}


def step_summaries(log):
    """The -quiet log: its step summary lines as dicts, and whether any
    per-iteration line (linear solver, outer iteration, contacts, sub-grid)
    was left in it."""
    steps, chatty = [], False
    for line in open(log):
        if line.startswith("Step "):
            words = line.replace("Time =", "time").split()
            steps.append(dict(zip(words[2::2], words[3::2])))
        chatty |= any(s in line for s in ("Solving for", "outer iteration",
                                          "Contacts:", "particle-wall gaps"))
    return steps, chatty


def main(work):
    s = last(f"{work}/straight/postProcessing/particles.h5")
    r = last(f"{work}/restart/postProcessing/particles.h5")
    par = last(f"{work}/parallel/postProcessing/particles.h5")
    gap = s["position"][:, 1] - 1
    Fc, U = s["contactForce"], s["velocity"]
    rest, stick, slide = 0, 1, 2

    # Equilibrium overlap: where eq 2.57 gives W
    expected = LAW.overlap_under(W)

    # External forces of the three groups (constant/particleProperties)
    Fext = np.array([[0, -W, 0], [0.3 * W, -W, 0], [0.8 * W, -W, 0]])

    c = Checks()
    # The load goes through the contact; the others' flow lifts it by 0.6 %
    c.check("rest: |normal contact force / W - 1|", abs(Fc[rest, 1] / W - 1), 1e-2)
    c.check("rest: |overlap / eq 2.57 equilibrium under W - 1|",
            abs((hr - gap[rest]) / expected - 1), 1e-2)
    # The normal force is implicit: eq 2.57 at the gap the step ends with,
    # the Adams-Bashforth step dt (3/2 U - 1/2 U_previous)
    end_gap = gap + dt * (1.5 * U[:, 1] - 0.5 * s["previousVelocity"][:, 1])
    c.check("rest: |force / eq 2.57 at the end-of-step gap - 1|",
            abs(Fc[rest, 1] / elastic_force(end_gap[rest]) - 1), 1e-6)
    c.check("all: max |F^h + F^c + F_ext| / W (eq 4.17)",
            np.abs(s["force"] + Fc + Fext).max() / W, 1e-3)
    c.check("stick: |U_x| / U_x(slide)", abs(U[stick, 0]) / U[slide, 0], 1e-3)
    c.check("stick: |F_t| / (mu F_el), below 1",
            abs(Fc[stick, 0]) / (mu * elastic_force(gap[stick])), 0.99)
    # The Coulomb cap of eq 2.63 on the elastic force at the gap of the
    # last linearisation: the end-of-step gap that the velocities of the
    # second outer iteration predicted (the linearisation is then held),
    # 2.4e-4 from the step's end gap at writing
    c.check("slide: ||F_t| / (mu F_el at the end-of-step gap) - 1|",
            abs(abs(Fc[slide, 0]) / (mu * elastic_force(end_gap[slide])) - 1),
            1e-3)
    c.check("slide: 0.01 - U_x / (0.3 W/(6 pi eta a)), sliding",
            0.01 - U[slide, 0] / 0.3, 0)
    scale = np.abs(s["position"]).max()
    c.check("restart: |time reached - 2|", abs(r["time"] - 2), 1e-9)
    c.check("restart: max |dx| / box", np.abs(r["position"] - s["position"]).max() / scale, 1e-9)
    c.check("restart: max |dU| / max |U|",
            np.abs(r["velocity"] - s["velocity"]).max() / np.abs(s["velocity"]).max(), 1e-6)
    c.check("restart: max |dF_c| / W", np.abs(r["contactForce"] - Fc).max() / W, 1e-6)
    # The record at the restart time repeats the interrupted run's one: the
    # contact loads of the solved state, implicit share included
    s1 = record(f"{work}/straight/postProcessing/particles.h5", 1)
    r1 = record(f"{work}/restart/postProcessing/particles.h5", 1)
    c.check("restart: |first record time - 1|", abs(r1["time"] - 1), 1e-9)
    for key in ("force", "contactForce", "contactTorque", "contactStresslet"):
        c.check(f"restart: record at t = 1, max |d {key}| / W",
                np.abs(r1[key] - s1[key]).max() / W, 1e-9)
    # -quiet: one line per step (1 to 2 by 0.05), its contacts and smallest
    # gap (over a = 1; printed to 3 digits) those of the particles' file
    steps, chatty = step_summaries(f"{work}/restart/log.fdmSuspensionFoam")
    c.check("quiet: |number of step lines - 20|", abs(len(steps) - 20), 0)
    c.check("quiet: per-iteration lines left (0/1)", int(chatty), 0)
    c.check("quiet: |last step time - 2|", abs(float(steps[-1]["time"]) - 2), 1e-9)
    c.check("quiet: max |contacts - 3|",
            max(abs(int(st["contacts"]) - 3) for st in steps), 0)
    c.check("quiet: |smallest gap / min(y - a) - 1|",
            abs(float(steps[-1]["smallestGap"]) / gap.min() - 1), 5e-3)
    # The .foam reader shows every written time's particles (0, 1, 2)
    # with their fields, equal to the particleState
    c.check("foam reader, serial: times failing",
            check_case(f"{work}/straight/case.foam"), 0)
    c.check("foam reader, 2 ranks decomposed: times failing",
            check_case(f"{work}/parallel/case.foam", decomposed=True), 0)
    c.check("2 ranks: max |dU| / max |U|",
            np.abs(par["velocity"] - s["velocity"]).max() / np.abs(s["velocity"]).max(), 1e-5)
    c.check("2 ranks: max |dF_c| / W", np.abs(par["contactForce"] - Fc).max() / W, 1e-5)
    return c.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
