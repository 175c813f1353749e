#!/usr/bin/env python3
"""Benchmark (issue 30, item 1, frozen configurations): cost against error
of one time step of a sheared Couette suspension, for each solver setting,
against a reference solve of the same step at tolerances far below any
setting tested.

A snapshot is a written time T of a Couette run (runPoint or the
tutorial): its fields, particleState (positions, velocities and the
Adams-Bashforth history) and constant/ and system/.  Every setting restarts
from T for one step of the run's deltaT, so all settings move the particles
to the same positions (explicit in the velocities of T) and solve the same
configuration at T + deltaT from the same initial guess, as within a run.
Per setting and snapshot:

  cost   core-seconds of the step's solve (serial: flow, forcing, particle
         solve and acceleration from the solver's Timing lines; start-up,
         reading and output excluded) and its outer iterations;
  error  of the particle translational and angular velocities against the
         reference (rms and max over the particles, in gammaDot a1, a1 the
         smallest radius) and of the particle stress (sum of the stresslets
         over the cell volume, thesis eq 2.73): Sigma_xy, N1 = Sigma_xx -
         Sigma_yy and N2 = Sigma_yy - Sigma_zz of the hydrodynamic part
         (stresslet, sub-grid lubrication included) and of the contact part
         (contactStresslet), each relative to the reference's |Sigma_xy|;
         and the step's own momentum balance, wall force against the
         particles' lambda (Table 4.8, eq 4.14), next to the reference's.

Settings (NAME, NAME+PART+... for several, or NAME@LAMBDATOL for another
lambda residual per step):

  default    the tutorial's settings before issue 30: Anderson, lambda
             residual 1e-3, no layer-mean correction, two pressure
             corrections, U and p to relTol 0.1 and 0.05
             (validation/benchmarks/solverSettings.py names them all)
  thesis     the thesis scheme: no acceleration, the same lambda residual
  thesis10   the thesis scheme with its fixed 10 outer loops per step
  layerMean  the default with the layer-mean coarse correction (SIMPLEC
             layerMeanCorrection on, layerMeanViscosityRatio 16)
  layerMeanAlphaF  layerMean with the lambda step alpha_lambda = F Delta^2/nu
             (coupling alphaLambdaFactor; thesis eq 2.41: F = 1)
  nCorr1     (a part) one pressure correction per outer iteration
  loose      (a part) U and p to relTol 0.3 and 0.2 per outer iteration
  gamgU      the default with GAMG for U (relTol 0.1)
  relax0.97  the default with U relaxed by 0.97 instead of 0.9
  reference  Anderson to lambda residual 1e-9, linear solvers to 1e-12
             absolute (relTol 0), at most 3000 outer iterations
  Delta0.25  (a part) the snapshot meshed again at Delta = a1/4, its
             fields mapped, the sub-grid tables of a1/4; its errors
             against the a1/5 reference include the change of resolution
             (Delta0.1667: a1/6)
  betweenRecords1e-2  (a part) the steps that write nothing stop at the
             lambda residual 1e-2 (coupling lambdaToleranceBetweenRecords)

A betweenRecords setting with --steps N writes only its last step, so
that the N - 1 steps before it stop at the looser residual as between
records in a run; its reference solves that step from the state of a
replay (the same N - 1 loose steps, the last written).  The reference
always solves the measured configuration (positions checked to 1e-9).

With --steps N every setting runs N steps from the snapshot and the last
is measured, against a reference solve of that step from the setting's own
state (N = 1: the snapshot's step, one reference for all).  A scheme that
converges some error mode better starts the measured step from a state it
made itself, as within its own run.

What it showed (phi 0.42, 10 x 20 x 10 a1, strain 1, --steps 6): the
default's velocity error is mostly a common drift of the particles along
the periodic directions (2 % gammaDot a1 in z), the profile across the
gap that under-relaxed SIMPLEC converges hundreds of times slower than
the cell scale; GAMG for U or relaxation 0.97 leave it, the layer-mean
correction removes it (8 times smaller rms error at the same lambda
residual).  Extrapolating U, p and lambda linearly in time from the last
two steps (tried, then removed) made the first lambda residual of a step
worse (1.8e-2 against 1.5e-2: lambda moves with the particles, not in
place) and saved no outer iteration.  Carrying U, p and lambda with the
particles instead (each support cell shifted by its particle's rigid
displacement, first order in the gradients; tried, then removed) moved
lambda by 1.5 % per step but left the first lambda residual of a step
unchanged (1.17e-2 against 1.16e-2, tutorial cell 8^3 a1, phi 0.3, 50
steps at 4e-3; 1e-4 at 4e-5): the change of a step is the flow's
response to the new configuration, not the particles' translation.
Keeping the Anderson differences
from one step to the next (tried, then removed) took 13-21 outer
iterations per step against 12-15: the map changes between steps more
than its secant model carries over.  Inexact inner solves with one
pressure correction (layerMean+loose+nCorr1) halve the cost of a step at
errors close to the default's (N1 excepted), but over 2 strains the
wall-normal momentum balance is 9 times worse (couetteTimeStep): the
wall pressure is not in these errors.

The lambda residual of eq 2.54 is the change of lambda over an iteration,
(rigid - u)/alpha_lambda: at the same residual a smaller alpha_lambda
leaves a smaller velocity mismatch, and F = 0.5 at residual 3e-3 (8-9 outer
iterations per step) is as close to its own reference as F = 1 at 1e-3
(12-15).  But the converged solution depends on F: where supports
overlap, the velocity correction of eq 2.53 does not vanish at the fixed
point, and the pseudo-mass terms of eq 2.43 that it leaves scale with
1/alpha_lambda.  The references at F = 0.5 and F = 1 (strain 1, lambda
residual 1e-9) differ by 1.2e-3 gammaDot a1 rms (3.0e-3 max) in the
particle velocities and by 5.6e-4, 2.3e-4, 5.4e-4 of Sigma_xy in the
hydrodynamic Sigma_xy, N1, N2: a change of the discrete model as large as
the errors compared here, so F stays 1.

What limits the outer iteration (tried on the sheared-sphere case test,
one sphere, Delta = a/5, and on this snapshot at strain 1, then removed):
not the flow solve (three SIMPLEC sweeps per lambda correction: the same
outer iterations, 43-45 to 1e-6 with Anderson, a plain tail rate of 0.985
per iteration either way), not the cell-scale part of the mismatch (its
non-affine part corrected 2 or 4 times faster: 41 and 59 against 43), not
lambda left behind by the moving particles (carried with each particle's
rigid displacement: first residual 1.46e-2 against 1.50e-2).  The slow
tail is a gradient field: the change of lambda between late iterations is
99.7 % curl-free for one sphere (radial, balanced by the pressure, so
that velocities, forces, torques and the deviatoric stresslet barely
move), 59 % at iteration 8 and 95 % at iteration 30 here.  The first
residual of a step is the configuration's change (particle velocities
change by 1-3 % of gammaDot a1 rms per 2e-3 step) and grows with the step
(median 1.6e-2, 3.0e-2, 9.9e-2 at 2e-3, 4e-3, 8e-3).

The rigid-body constraint made implicit in the momentum matrix (tried,
then removed): K (U - U_prev) on the particles' cells, K = f nu/Delta^2,
its force moved into lambda after each sweep so that it vanishes at the
fixed point.  For the pushed sphere (one sphere, Anderson) the particle
velocity error after 10, 20, 40 outer iterations was 0.42, 0.19, 3.5e-3
at f = 0 and 0.42, 0.20, 4.0e-3 at f = 10: no faster.  And it moved the
converged solution by 1.2e-4, 8.0e-4, 2.6e-3 gammaDot a at f = 1, 10,
100: the Rhie-Chow face flux carries rAtU, which K changes inside the
particles.  On this snapshot (strain 1, one step) f = 10 stopped at the
lambda residual in 18 outer iterations against 78, but 1.7e-2 gammaDot a1
rms from the reference at any residual.  A drag estimate 6 pi nu a (times
c) on the diagonal of the particle system, balanced by its value at the
last iterate, was slower at c = 0.5, 2 and -0.3 and diverged at c = -1.

The U under-relaxation (settings part relaxU<a>; tried, left at 0.9).  In
SIMPLEC it is a pseudo-time step of about a/(1 - a) cell diffusion times
per outer iteration, and for an isolated particle that is what limits its
rigid motion: a sphere pushed through the sheared channel (the
sheared-sphere case test, Delta = a/5) reaches 0.84 of its velocity after
140 plain outer iterations at 0.9 and 0.99 of it after 60 at 0.99; with
Anderson it is within 1e-3 of its velocity after 60 iterations at 0.9 and
20 at 0.99, the converged values 2e-4 apart.  On this snapshot (strain
1, one step) it does not pay: 12, 15, 20 outer iterations to the lambda
residual 1e-3 at 0.98, 0.99, 0.995 against 12 at 0.9, and at 0.99 the
errors against its own reference are the default's (1.2e-3 against
1.1e-3 gammaDot a1 rms; GAMG for U: 22 iterations, 1.0e-3).  The steady
reference at 0.99 takes 664 outer iterations (1045 core-s) against 150
(191).  And the converged solution moves with it, by 3.6e-3 gammaDot a1
rms (7.9e-3 max) in the particle velocities and 2.2e-3 of Sigma_xy in the
hydrodynamic Sigma_xy, and by 3.2e-3 with consistent overlaps (below),
so it is not the overlaps alone.  It is the Rhie-Chow pressure term of
the face flux, whose coefficient at SIMPLEC's fixed point is the relaxed
1/a_C, alpha_U/a_C: with SIMPLEC RhieChowFactor 0.9 (part RC0.9: the
coefficient 0.9/a_C at any relaxation, RhieChowCorrection.H) the
reference at 0.99 is 8.7e-4 gammaDot a1 rms from the one at 0.9 with the
thesis overlaps and 2.1e-9 with consistent overlaps (784 outer
iterations against 151), so that with both the converged solution
depends on no solver setting.  The rest with the thesis overlaps is their
velocity correction, which does not vanish at the fixed point and which
the relaxed sweep must undo.  It is no lever either: the layer-mean step
at 0.99 with RC0.9 takes 16 outer iterations (1.5e-3 gammaDot a1 rms from
the 0.9 reference) against 12, and the coefficient 1/a_C (RC1, relaxation
0.9) moves the solution by 3.2e-3.  Nor is an implicit rigid-body
penalty now that it cannot move the fixed point (K (U - U_prev) on the
support cells, K = F nu/Delta^2, its force moved into lambda after each
sweep; RC0.9, thesis overlaps; tried, then removed): 11, 13 outer
iterations at F = 1, 10 (1.34e-3, 1.89e-3 gammaDot a1 rms) against 12
(1.27e-3), diverged at 100; left in U (not moved) at F = 10 it stopped in
17 iterations 1.2e-2 from the reference.  Nor a larger lambda step
(consistent overlaps, alphaLambdaFactor 2): 12 outer iterations at the
lambda residual 1e-3 (1.9e-3 gammaDot a1 rms) and 18 at 5e-4 (1.05e-3)
against 12 (1.16e-3) at factor 1.  The velocity error of the default
step is at the particle scale: of its energy in the fluid, 50 % is in
the means over blocks of a1 (5^3 cells), 32 % over 2 a1, 11 % over 5 a1
and 8 % in the layer means; the particles' errors are relative motions
(1.12e-3 of 1.16e-3 gammaDot a1 rms with the common translation
removed), so a coarse correction above the particle scale cannot remove
much of it.  The Anderson depth (part depth<m>): 14, 12, 12, 12 outer
iterations at m = 4, 8, 16, 24, the same errors.

The mesh spacing (part Delta0.25, Delta = a1/4 with the sub-grid tables
calibrated there; strain 1): the a1/4 reference is 3.0e-2 gammaDot a1
rms (6.5e-2 max) from the a1/5 one in the particle velocities, 3.2e-2
gammaDot in Omega, 3.0e-3, 2.1e-3, 2.2e-3 of Sigma_xy in the hydrodynamic
Sigma_xy, N1, N2 (the contact parts 1.4e-4 to 3.3e-4): the resolution
moves the solution 25 times more than the default step's solver error.
The a1/4 reference costs 91 core-s and 129 outer iterations against 175
and 147.  With --steps 6, each against its own mesh's reference: the
a1/5 default 4.31 core-s, 12 outer iterations, U 1.2e-3 rms (relative
motion 1.1e-3), Omega 7.3e-4, hydrodynamic Sigma_xy, N1, N2 1.4e-4,
7.1e-5, 1.1e-4; a1/4 at the same lambda residual 2.05 core-s, 11
iterations, 1.7e-3 (1.3e-3), 7.2e-4, 1.3e-4, 6.8e-6, 1.6e-4; a1/4 at
6.4e-4 (the residual scales with alpha_lambda = Delta^2/nu) 2.46 core-s,
14 iterations, 1.6e-3 (8.0e-4), 4.7e-4, 7.8e-5, 3.8e-5, 5.2e-5: every
error but the common translation at or below the a1/5 default's, at
1.75 times less cost.

Consistent overlaps (part consistent: particleProperties coupling
overlaps consistent).  In the thesis form the fixed point keeps, in each
particle's equation, (1/alpha_lambda) int J_u (U + Omega x r - u) over the
cells it shares with a neighbour, where u is the J_lambda-mean of both
rigid motions: measured at the reference of strain 1, 0.13 rms and 0.58
max (6 pi nu a1 gammaDot a1 = 18.8, contact forces 104 rms).  These forces
do not sum to zero, so the wall force misses the particles' lambda by
5.1e-4, 2.8e-3, 8.0e-4 (x, y, z) at lambda residual 1e-9.  In the
consistent form (couplingStencils.H) the references at alpha_lambda
factors 1 and 0.5 agree to 1.8e-9 gammaDot a1 rms (1.2e-3 in the thesis
form), the wall balance is 3e-10, 1e-10, 2e-10, and the solution moves
from the thesis form's by 8.0e-4 gammaDot a1 rms (2.2e-3 max), 8.4e-4
gammaDot in Omega, 1.6e-4, 2.4e-5, 1.4e-4 of Sigma_xy in the
hydrodynamic Sigma_xy, N1, N2.  Cost unchanged: reference 147 outer
iterations against 150, the layer-mean default step 12 against 12, with
the errors of the thesis form against its own reference (1.2e-3 against
1.1e-3 gammaDot a1 rms).  A smaller lambda step does not pay there
either: factor 0.5 needs 27 outer iterations to the lambda residual 1e-3
(2.2e-3 gammaDot a1 rms, mostly the common drift) and 9 to 3e-3 (2.2e-3).

Steps between records (strain 1, --steps 6, the 6th recorded after 5
loose steps at 3-4 outer iterations each): at the record's residual 1e-3
the recorded step takes 15 outer iterations against the default's 12, its
velocities are as close to the reference (1.5e-3 against 1.2e-3 gammaDot
a1 rms) but N1 and N2 are not (hydrodynamic Sigma_xy, N1, N2 1.6e-4,
2.6e-4, 2.9e-4 against 1.4e-4, 7.1e-5, 1.1e-4 of Sigma_xy): the pressure
of the loose steps is left behind.  At the record's residual 5e-4 (21
outer iterations) every error is below the default's: U 5.0e-4, relative
4.7e-4, Omega 2.7e-4, hydrodynamic 3.0e-5, 6.4e-5, 5.6e-5, contact
1.1e-6, 1.9e-6, 4.7e-6 (wall balance y 2.6e-3 against 1.7e-3, the
reference's own 1.7e-3).  Loose steps at 3e-3: the record takes 12
iterations with errors near the default's (N1, N2 1.2e-4, 1.4e-4).

    run.py --snapshot CASE:T[,T...] [--snapshot ...] [--steps N]
           [--settings default,thesis,thesis10,default@1e-4]
           [--reference reference+Delta0.1667]

Writes report.md here (cases in build/benchmarks/frozenCouette).
"""

import argparse
import os
import re
import shutil
import sys
from datetime import date

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.environ["FDM_PROJECT_DIR"]
sys.path.insert(0, os.path.join(PROJECT, "src", "python"))
from fdmPost.caseRunner import (foam_get, foam_set, run_logged,  # noqa
                                snapshot_case, timing_lines, work_lock)
from fdmPost.particleCase import momentum_balance, read_list  # noqa
from fdmPost.rheology import number  # noqa: E402
sys.path.insert(0, os.path.dirname(HERE))
from solverSettings import (apply_mesh, apply_setting,  # noqa: E402
                            case_suffix, check_setting,
                            solve_as_between_records)

# Settings that stop the steps between records at a looser residual
BETWEEN_RECORDS = "betweenRecords"
STATE_KEYS = (("position", 3), ("radius", 1), ("velocity", 3),
              ("angularVelocity", 3),
              ("stresslet", 6), ("contactStresslet", 6))


def setting_case(snapshot, time, setting, work, steps=1, replay=False):
    """A copy of the snapshot with the setting's edits that runs `steps`
    steps from T; returns the case and its end time.  replay: every step
    solved as between records of a betweenRecords setting (residual, inner
    solvers), the last written too, so that the case reaches the state of
    the setting's run one step before its measured one."""
    check_setting(setting)
    case = os.path.join(work, "%s_%s%s%s" % (
        os.path.basename(snapshot), case_suffix(setting),
        "_%dsteps" % steps if steps > 1 else "", "_replay" if replay else ""))
    dt = float(foam_get(snapshot, "deltaT", "system/controlDict"))
    end = "%.12g" % (float(time) + steps * dt)
    if finished(case) and os.path.isfile(os.path.join(case, end,
                                                      "particleState")):
        return case, end
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(snapshot, case)
    foam_set(case, "startFrom", "latestTime", "system/controlDict")
    foam_set(case, "endTime", end, "system/controlDict")
    foam_set(case, "writeControl", "timeStep", "system/controlDict")
    foam_set(case, "writeInterval", 1, "system/controlDict")
    foam_set(case, "functions", "{}", "system/controlDict")
    apply_mesh(case, setting, time)
    apply_setting(case, setting)
    if BETWEEN_RECORDS in setting:
        # Only the measured step is written (and recorded): the steps
        # before it stop at the looser residual, as between records in a run
        # (runTime: counted from this run's start; timeStep counts the
        # time index of the whole run)
        foam_set(case, "writeControl", "runTime", "system/controlDict")
        foam_set(case, "writeInterval", "%.12g" % (steps * dt),
                 "system/controlDict")
        foam_set(case, "output.timeSeriesInterval", 10 ** 6,
                 "constant/particleProperties")
    if replay:
        pp = "constant/particleProperties"
        foam_set(case, "coupling.lambdaTolerance",
                 foam_get(case, "coupling.lambdaToleranceBetweenRecords", pp),
                 pp)
        solve_as_between_records(case)
    return case, end


def reference_from(case, time, work):
    """The reference solve of the step after `time` of a setting's case
    (the snapshot itself when time is its own start)."""
    source = os.path.join(work, "start_%s_%s" % (os.path.basename(case),
                                                 time))
    if not os.path.isdir(source):
        os.makedirs(source)
        for d in ("constant", "system", time):
            shutil.copytree(os.path.join(case, d), os.path.join(source, d))
    return setting_case(source, time, "reference", work)


def check_same_positions(run, ref):
    """A reference must solve the measured configuration."""
    moved = np.abs(run["state"]["position"] - ref["state"]["position"]).max()
    if moved > 1e-9:
        raise SystemExit("the reference's positions differ from the measured"
                         " step's by up to %.1e" % moved)


def read_state(case, time):
    text = open(os.path.join(case, time, "particleState")).read()
    state = {}
    for key, width in STATE_KEYS:
        try:
            state[key] = np.asarray(read_list(text, key, width))
        except KeyError:
            pass
    return state


def finished(case):
    """The step was solved (a rerun of the benchmark reuses it)."""
    log = os.path.join(case, "log.fdmSuspensionFoam")
    return os.path.isfile(log) and bool(timing_lines(open(log).read()))


def solve(case, end):
    if not finished(case):
        run_logged(["fdmSuspensionFoam"], case, "log.fdmSuspensionFoam")
    text = open(os.path.join(case, "log.fdmSuspensionFoam")).read()
    timing = timing_lines(text)
    if not timing:
        raise RuntimeError("no Timing line in %s" % case)
    # The last step's solve work (flow, forcing, particle solve,
    # acceleration, pairs), without start-up and output; serial, so
    # seconds are core-seconds
    last = np.array(timing[-1]) - (np.array(timing[-2]) if len(timing) > 1
                                   else 0)
    outer = int(last[0])
    seconds = sum(last[3:9]) + last[10]
    residual = re.findall(r"lambda residual (\S+),", text)
    return {"coreSeconds": seconds, "outer": outer,
            "residual": float(residual[-1]) if residual else float("nan"),
            "state": read_state(case, end),
            "wallBalance": wall_balance(case, end)}


def wall_balance(case, end):
    """Momentum balance of the step (Table 4.8, eq 4.14): |F^w +
    F^FDM,parts| per component over |F^w|, the wall force against the
    particles' lambda; the wall pressure enters it, the particle errors
    above do not see it."""
    mb = momentum_balance(case)
    k = np.argmin(np.abs(mb["time"] - float(end)))
    wall, parts = mb["wall"][k], mb["lambdaParts"][k]
    return np.abs(wall + parts) / np.linalg.norm(wall)


def stress_parts(state, volume):
    """Sigma_xy, N1, N2 of the hydrodynamic and contact stresslet sums."""
    out = {}
    for part, key in (("hydro", "stresslet"), ("contact", "contactStresslet")):
        if key not in state:
            continue
        # symmTensor rows: xx xy xz yy yz zz
        s = np.asarray(state[key]).reshape(-1, 6).sum(axis=0) / volume
        out[part] = np.array([s[1], s[0] - s[3], s[3] - s[5]])
    return out


def errors(run, ref, shear_rate, volume):
    a1 = ref["state"]["radius"].min()
    scale_u, scale_w = shear_rate * a1, shear_rate
    row = {}
    for key, scale in (("velocity", scale_u), ("angularVelocity", scale_w)):
        d = np.linalg.norm(np.asarray(run["state"][key]).reshape(-1, 3)
                           - np.asarray(ref["state"][key]).reshape(-1, 3),
                           axis=1) / scale
        row[key] = (np.sqrt(np.mean(d ** 2)), d.max())
    # The same without the mean over the particles: a common translation
    # (the slow mode of the outer iteration along the periodic flow
    # direction) moves no particle relative to another
    d = (np.asarray(run["state"]["velocity"]).reshape(-1, 3)
         - np.asarray(ref["state"]["velocity"]).reshape(-1, 3))
    d = np.linalg.norm(d - d.mean(axis=0), axis=1) / scale_u
    row["relativeVelocity"] = (np.sqrt(np.mean(d ** 2)), d.max())
    s_run = stress_parts(run["state"], volume)
    s_ref = stress_parts(ref["state"], volume)
    sxy = abs(s_ref["hydro"][0] + s_ref.get("contact", np.zeros(3))[0])
    for part in s_ref:
        row[part] = np.abs(s_run[part] - s_ref[part]) / sxy
    return row


def cell_volume_and_rate(case):
    """Volume from the blockMeshDict box, shear rate from the wall speeds."""
    text = open(os.path.join(case, "system", "blockMeshDict")).read()
    box = [number(text, k) for k in ("Lx", "Ly", "Lz")]
    top = foam_get(case, "boundaryField.topWall.value", "0/U"
                   if os.path.isfile(os.path.join(case, "0", "U")) else
                   "%s/U" % sorted(d for d in os.listdir(case)
                                   if re.fullmatch(r"[0-9.e+-]+", d))[0])
    real = r"[-+0-9.eE]+"
    u_top = float(re.search(r"\(\s*(%s)\s+%s\s+%s\s*\)"
                            % (real, real, real), top).group(1))
    return box[0] * box[1] * box[2], 2 * abs(u_top) / box[1]


def main():
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--snapshot", action="append", required=True,
                    help="CASE:T[,T...] (written times of a Couette run)")
    ap.add_argument("--settings", default="default,thesis,thesis10")
    ap.add_argument("--steps", type=int, default=1,
                    help="steps per setting from the snapshot; the last is "
                    "measured against a reference solve of the same step "
                    "(more than one lets a setting's own state settle)")
    ap.add_argument("--reference", default="reference",
                    help="the setting every one-step run is measured "
                    "against (reference+Delta0.1667: the converged step on "
                    "the finer mesh, so that the errors include the "
                    "resolution's)")
    args = ap.parse_args()
    work = os.path.join(PROJECT, "build", "benchmarks", "frozenCouette")
    lock = work_lock(work)  # noqa: F841 (held until the process ends)

    rows = []
    for spec in args.snapshot:
        source, _, times = spec.rpartition(":")
        for time in times.split(","):
            snap = snapshot_case(os.path.abspath(source), time, work)
            volume, rate = cell_volume_and_rate(snap)
            first = None
            if args.steps == 1:
                case, end = setting_case(snap, time, args.reference, work)
                first = solve(case, end)
                print("%s: %s %d outer iterations, %.1f core-s, "
                      "lambda residual %.1e" % (
                          os.path.basename(snap), args.reference,
                          first["outer"],
                          first["coreSeconds"], first["residual"]),
                      flush=True)
            for setting in args.settings.split(","):
                case, end = setting_case(snap, time, setting, work,
                                         args.steps)
                run = solve(case, end)
                ref = first
                if ref is None:
                    # The measured step is the last: its reference starts
                    # from the setting's own state one step before
                    dt = float(foam_get(snap, "deltaT", "system/controlDict"))
                    before = "%.12g" % (float(end) - dt)
                    start = case
                    if BETWEEN_RECORDS in setting:
                        start, _ = setting_case(snap, time, setting, work,
                                                args.steps - 1, replay=True)
                        solve(start, before)
                    ref = solve(*reference_from(start, before, work))
                    check_same_positions(run, ref)
                row = errors(run, ref, rate, volume)
                row.update(wallBalance=run["wallBalance"],
                           wallBalanceReference=ref["wallBalance"])
                row.update(snapshot=os.path.basename(snap), setting=setting,
                           coreSeconds=run["coreSeconds"], outer=run["outer"],
                           residual=run["residual"], steps=args.steps)
                rows.append(row)
                print("  %-16s %6.1f core-s %4d outer, |dU| rms %.1e max "
                      "%.1e" % (setting, run["coreSeconds"], run["outer"],
                                *row["velocity"]), flush=True)
    write_report(rows, args.reference)


def write_report(rows, reference):
    lines = [
        "# Frozen-configuration benchmark: one step of a sheared Couette "
        "suspension",
        "",
        "Errors against the reference solve of the same step (see run.py; "
        "setting %s for one step): " % reference +
        "velocities in gammaDot a1 (also with the mean over the particles "
        "removed), angular velocities in gammaDot, stress parts relative to "
        "the reference |Sigma_xy|; the wall balance |F^w + F^FDM,parts| "
        "over |F^w| (Table 4.8, eq 4.14) of the setting and of its "
        "reference.  Core-seconds of the step's solve, serial, "
        "on %s (%d cores), %s." % (os.uname().nodename, os.cpu_count(),
                                   date.today().isoformat()),
        "",
        "| snapshot | setting | core-s | outer | lambda residual | U rms | "
        "U max | U - mean rms | U - mean max | Omega rms | Omega max | "
        "hydro Sxy, N1, N2 | contact Sxy, N1, N2 | wall balance x, y, z "
        "| the reference's |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        parts = ["%.1e, %.1e, %.1e" % tuple(r[p]) if p in r else "-"
                 for p in ("hydro", "contact", "wallBalance",
                           "wallBalanceReference")]
        lines.append("| %s | %s | %.2f | %d | %.1e | %.1e | %.1e | %.1e | "
                     "%.1e | %.1e | %.1e | %s | %s | %s | %s |"
                     % (r["snapshot"], r["setting"], r["coreSeconds"],
                        r["outer"], r["residual"], *r["velocity"],
                        *r["relativeVelocity"], *r["angularVelocity"],
                        *parts))
    with open(os.path.join(HERE, "report.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", os.path.join(HERE, "report.md"))


if __name__ == "__main__":
    main()
