#!/bin/bash
# Case test (issue 38): one free sphere (a = 1, Delta = a/4) settling along
# x in a periodic cube L = 5a under a buoyant weight that moves it about one
# radius per unit time, from x = 2.1 to time 3.6 in 18 steps: it crosses the
# processor boundary at x = 2.5 of a 2-rank decomposition along x, then the
# cyclic patch at x = 5, which on 2 ranks is also a processorCyclic boundary.
# Run serially and on 2 ranks with the particle system solved by subdomain
# (parallelParticleSolve distributed), where the rank that solves the
# sphere's rows changes at each crossing, and the other rank owns none.  (On
# 2 ranks with the system solved whole on every rank the trajectory is the
# distributed one to the last printed digit: 3e-8 from the serial one.)
# A restart that goes through reconstructPar and decomposePar (as when a
# run moves to another decomposition): the 2-rank run by subdomain stopped
# at time 1 (the fields in binary), reconstructed, its processor directories removed
# and decomposed again, continued for two steps, must follow the
# uninterrupted 2-rank run to round-off: decomposePar writes the cyclic's
# face values on the processorCyclic patch, not the neighbour cells' that
# the run held, and the solver must evaluate the coupled patches on reading
# (before it did, the first step after such a restart left the run by the
# solver's tolerance).
# Checks in checkProcessorCrossing.py.
source "${0%/*}/caseTestFunctions"
source "$caseTemplates/periodicArraySetup"

work=$(caseWorkDir processorCrossing)
# Buoyant weight L^3 g along x (periodicArraySetup's settling sphere) with
# g = 0.32: U about 1 (Hasimoto, phi 0.0335)
periodicArrayCase "$work/serial" 5 2.1 2.55 2.45 1e-8 2000 settling 4 \
    || exit 1
tightenAndAccelerate "$work/serial" 1e-9 || exit 1
for entry in "deltaT 0.2" "endTime 3.6"
do
    foamDictionary -entry ${entry% *} -set ${entry#* } \
        "$work/serial/system/controlDict" > /dev/null || exit 1
done
foamDictionary -entry gravity -set "(0.32 0 0)" \
    "$work/serial/constant/particleProperties" > /dev/null || exit 1

mkdir -p "$work/distributed"
cp -r "$work/serial"/{0,constant,system} "$work/distributed"/
(
    cd "$work/serial" || exit 1
    runLogged blockMesh && runLogged fdmSuspensionFoam
) || exit 1
cp -r "$work/distributed" "$work/redecomposed"
foamDictionary -entry endTime -set 1 "$work/redecomposed/system/controlDict" \
    > /dev/null || exit 1
runBySubdomain "$work/distributed" || exit 1
runBySubdomain "$work/redecomposed" || exit 1
(
    cd "$work/redecomposed" || exit 1
    runLogged reconstructPar -latestTime && rm -r processor* &&
    mv log.decomposePar log.decomposePar.first &&
    runLogged decomposePar -latestTime || exit 1
    foamDictionary -entry endTime -set 1.4 system/controlDict > /dev/null
    foamDictionary -entry startFrom -set latestTime system/controlDict \
        > /dev/null
    mv log.fdmSuspensionFoam.parallel log.first
    runParallel2 fdmSuspensionFoam
) || exit 1

"$FDM_PYTHON" "$caseTemplates/checkProcessorCrossing.py" "$work"
