#!/bin/bash
# Case test: particle-free shear in a Lees-Edwards box (the plane channel's
# walls replaced by a y-periodic patch with the leesEdwards coupling at
# shear rate 1), serial and on 2 ranks split along z, at t = 0.93: the
# offset 0.18 is 2.88 cells, not a whole number.  The uniform shear
# u_x = y - 1/2 is exact (tolerance 1e-10, the linear solvers at 1e-14),
# with PCG and with GAMG, and after 400 box passes (t = 100.93).
# On 2 ranks split along y (across the sheared faces) too, restarted.
# Particles in the sheared box: shearedSphereLeesEdwards.
source "${0%/*}/caseTestFunctions"

# The uniform shear u_x = y - 1/2 of TIME in a copy of the case (cell
# centres in ../0/C) to 1e-10:  uniformShearExact TIME LABEL
uniformShearExact()
{
    "$FDM_PYTHON" - "$1" "$2" <<'CHECK'
import sys
import numpy as np
from fdmPost.foamFields import read_internal_field
time, label = sys.argv[1:]
y = read_internal_field("../0/C")[:, 1]
err = np.abs(read_internal_field(f"{time}/U")[:, 0] - (y - 0.5)).max()
print(f"  {'ok' if err < 1e-10 else 'FAIL'}   {label}: max |u_x - (y - 1/2)|:"
      f" {err:.3e} (tolerance 1e-10)")
sys.exit(int(err >= 1e-10))
CHECK
}

work=$(caseWorkDir leesEdwardsFlow)
cloneCase planeChannel "$work"
leesEdwardsBox "$work" || exit 1
(
    cd "$work" || exit 1
    foamDictionary -entry endTime -set 0.93 system/controlDict > /dev/null
    foamDictionary -entry deltaT -set 0.93 system/controlDict > /dev/null
    foamDictionary -entry coeffs.n -set "(1 1 2)" system/decomposeParDict \
        > /dev/null
) || exit 1
runSerialAndParallel "$work" || exit 1

"$FDM_PYTHON" "$caseTemplates/checkChannelProfile.py" --case "$work" \
    --time 0.93 --profile couette --wall-speed 0.5 --delta 0.0625 \
    --tol 1e-10 || exit 1

# GAMG (its coarse levels couple the sheared faces as a plain cyclic, the
# finest level sheared): the same exact shear
mkdir -p "$work/gamg" && cp -r "$work"/{0,constant,system} "$work/gamg"/
(
    cd "$work/gamg" || exit 1
    for field in p U
    do
        foamDictionary -entry solvers.$field -set "{ solver GAMG;
            smoother GaussSeidel; tolerance 1e-14; relTol 0; }" \
            system/fvSolution > /dev/null
    done
    runLogged fdmSuspensionFoam && uniformShearExact 0.93 GAMG
) || exit 1

# After 400 box passes (t = 100.93: the offset 0.18 again, from
# gammaDot L_y t modulo L_x = 0.25): the same exact shear
mkdir -p "$work/passes" && cp -r "$work"/{0,constant,system} "$work/passes"/
(
    cd "$work/passes" || exit 1
    foamDictionary -entry endTime -set 100.93 system/controlDict > /dev/null
    foamDictionary -entry deltaT -set 100.93 system/controlDict > /dev/null
    runLogged fdmSuspensionFoam &&
        uniformShearExact 100.93 "after 400 box passes"
) || exit 1

# Split along y (across the sheared faces: their processorCyclic parts
# sheared by leesEdwardsProcessorCyclic): the same exact shear, and the
# fields written with that type restart as they ran
(
    cd "$work/parallel" || exit 1
    rm -rf processor*
    foamDictionary -entry coeffs.n -set "(1 2 1)" system/decomposeParDict \
        > /dev/null
    runLogged decomposePar || exit 1
    mpirun -np 2 --oversubscribe fdmSuspensionFoam -parallel > log.ySplit 2>&1 \
        || { echo "FAILED: the y split (log: $PWD/log.ySplit)"; tail -n 15 log.ySplit; exit 1; }
    grep -q "type *leesEdwardsProcessorCyclic" processor0/0.93/U \
        || { echo "FAIL: processor0/0.93/U has no leesEdwardsProcessorCyclic patch"; exit 1; }
    runLogged reconstructPar -latestTime || exit 1
    uniformShearExact 0.93 "on 2 ranks split along y" || exit 1
    foamDictionary -entry endTime -set 1.86 system/controlDict > /dev/null
    foamDictionary -entry startFrom -set latestTime system/controlDict \
        > /dev/null
    mpirun -np 2 --oversubscribe fdmSuspensionFoam -parallel > log.ySplitRestart 2>&1 \
        || { echo "FAILED: the y-split restart (log: $PWD/log.ySplitRestart)"; tail -n 15 log.ySplitRestart; exit 1; }
    runLogged reconstructPar -latestTime || exit 1
    uniformShearExact 1.86 "split along y, restarted (offset 0.36)"
) || exit 1
