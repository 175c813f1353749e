#!/bin/bash
# Case test: a restart across the sheared faces continues the same
# trajectory.  Two spheres pushed apart along y (opposite forces: the
# periodic box carries no net force) in a Lees-Edwards box of 6^3 a^3
# (shear rate 1, offset 6 t, 1.5 cells a step) cross the top and the
# bottom face in the second and third of 4 Adams-Bashforth steps of 0.05
# (measured: down at 0.1, up at 0.15).  The same case on 2 ranks split
# along y (the sheared faces between the ranks) must follow the serial
# run to the solver's tolerance; written every 2 steps, stopped after 3
# and restarted from its latest time (after both crossings), it must reach
# its uninterrupted state to round-off; and the crossing must have moved
# each sphere by the offset along x and changed its velocity by the shear
# velocity, and the box's mean velocity stays 0 (checks below).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir restartLeesEdwards)
cloneCase shearedSphere "$work/straight"
(
    cd "$work/straight" || exit 1
    # 6 x 6 x 6 from y = -3, as restartContinuity's box
    sed -i -e 's/^    (0 -5 0) .*$/    (0 -3 0) (6 -3 0) (6 3 0) (0 3 0)/' \
        -e 's/^    (0 -5 10) .*$/    (0 -3 6) (6 -3 6) (6 3 6) (0 3 6)/' \
        -e 's/(50 50 50)/(30 30 30)/' system/blockMeshDict
) || exit 1
leesEdwardsBox "$work/straight" || exit 1
(
    cd "$work/straight" || exit 1
    # 6 pi eta a times 2: about 2 a per unit time along -+y
    foamDictionary -entry groups -set \
        '{ up { force (0 37.7 0); } down { force (0 -37.7 0); } }' \
        constant/particleProperties > /dev/null
    foamDictionary -entry particles -set \
        '((up (1.55 2.84 1.47) 1) (down (4.45 -2.86 4.51) 1))' \
        constant/particleProperties > /dev/null
    foamDictionary -entry coupling.lambdaTolerance -set 1e-4 \
        constant/particleProperties > /dev/null
    foamDictionary -entry deltaT -set 0.05 system/controlDict > /dev/null
    foamDictionary -entry endTime -set 0.2 system/controlDict > /dev/null
    runLogged blockMesh
) || exit 1

for run in ySplit restarted
do
    cp -r "$work/straight" "$work/$run"
    (
        cd "$work/$run" || exit 1
        foamDictionary -entry coeffs.n -set "(1 2 1)" \
            system/decomposeParDict > /dev/null
        runLogged decomposePar
    ) || exit 1
done
(cd "$work/straight" && runLogged fdmSuspensionFoam) || exit 1
(cd "$work/ySplit" && runParallel2 fdmSuspensionFoam) || exit 1
(
    cd "$work/restarted" && runStoppedAndRestarted 0.15 0.2 parallel
) || exit 1

"$FDM_PYTHON" - "$work" <<'CHECK'
"""Reference of the split along y: the serial run, to 1e-5 relative (the
outer iterations stop at a lambda residual of 1e-4; measured 1.7e-6 in
the stresslet and 0.68 in Omega when the split faces were coupled
unsheared).  Reference of the restart: the uninterrupted run on the same
ranks, to round-off (1e-12 relative: positions, velocities and the
Adams-Bashforth history are read at full precision, the fields at 17
digits).  Reference of the crossing:
the Lees-Edwards image one period up is offset by s(t) = 6 t along x and
moves at +6 along x, so a sphere wrapped through the top face moves by
-s along x (modulo 6) and its velocity by -6; through the bottom face the
opposite.  Between the records before and after the crossing the sphere
moves by dt (u_x of the step) besides: tolerance 0.05 a on the position,
0.5 gamma a on the velocity (the step's change of the flow)."""
import glob
import os
import sys
import h5py
import numpy as np
from fdmPost.particleCase import particle_state
from fdmPost.checks import Checks

work = sys.argv[1]
checks = Checks()
serial = particle_state(os.path.join(work, "straight"), "0.2")
a = particle_state(os.path.join(work, "ySplit"), "0.2")
b = particle_state(os.path.join(work, "restarted"), "0.2")
checks.same_state("split along y vs serial", serial, a, tol=1e-5,
                  keys=("position", "velocity", "angularVelocity",
                        "stresslet"))
checks.same_state("restarted across the faces vs straight", a, b)

# The box's mean velocity is held at its initial value, 0 (the uniform
# part that the sheared box leaves free; it drifted where a sphere
# straddles the faces before it was held; the particle correction after
# the hold moves it by 1e-8): momentumBalance's meanU, every step
rows = np.vstack([np.loadtxt(f, ndmin=2) for f in sorted(glob.glob(
    os.path.join(work, "straight", "postProcessing", "momentumBalance",
                 "*", "momentumBalance.dat")))])
checks.check("mean velocity held at 0: max |meanU|",
             np.abs(rows[:, -3:]).max(), 1e-6)

with h5py.File(os.path.join(work, "straight", "postProcessing",
                            "particles.h5"), "r") as f:
    t, x, u = f["time"][:], f["position"][:], f["velocity"][:]
checks.check("HDF5 times differ from 0, 0.05 .. 0.2",
             float(len(t) != 5) + np.abs(t - 0.05 * np.arange(len(t))).max(),
             1e-12)
for p, side in ((0, 1), (1, -1)):
    k = np.flatnonzero(np.diff(np.sign(x[:, p, 1])) != 0)
    name = ["up (through the top face)", "down (through the bottom face)"][p]
    if len(k) != 1:
        checks.check(f"{name}: crossings (1 expected)", abs(len(k) - 1), 0)
        continue
    k = k[0]
    s = 6 * t[k + 1]
    dx = x[k + 1, p, 0] - x[k, p, 0] - 0.05 * u[k, p, 0] + side * s
    checks.check(f"{name}: x shifted by -+s (t {t[k + 1]:.2f})",
                 abs(dx - 6 * np.round(dx / 6)), 0.05)
    checks.check(f"{name}: u_x changed by -+6",
                 abs(u[k + 1, p, 0] - u[k, p, 0] + 6 * side), 0.5)
checks.finish()
CHECK
