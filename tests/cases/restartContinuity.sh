#!/bin/bash
# Case test: a restart continues the same trajectory.  Three particles
# (read with particlesFile, two groups, one heavy) in a sheared channel
# move for 4 Adams-Bashforth steps; the same case written every 2 steps and
# stopped after 3 (between write times: a run's last step is written too)
# and restarted from its latest time must reach the same particle state and
# the HDF5 series must hold each step once (the straight run started from
# outside its case directory with -case).  A run continued on another
# machine from a particle checkpoint (fdmPost.checkpoint: the particle
# state of 0.1 and the core records, no fields) must reach the same state
# within the accuracy of a solve and its joined records the straight run's.
# Checks in checkRestart.py.
# The suspensionStress function object runs at every write and again
# afterwards with postProcess; checkSuspensionStress.py compares it with
# fdmPost.rheology on the HDF5 records.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir restartContinuity)
cloneCase shearedSphere "$work/straight"
(
    cd "$work/straight" || exit 1
    # Smaller box 6 x 6 x 6, walls at -3 and 3 moving at -3 and 3
    sed -i -e 's/^    (0 -5 0) .*$/    (0 -3 0) (6 -3 0) (6 3 0) (0 3 0)/' \
        -e 's/^    (0 -5 10) .*$/    (0 -3 6) (6 -3 6) (6 3 6) (0 3 6)/' \
        -e 's/(50 50 50)/(30 30 30)/' system/blockMeshDict
    sed -i 's/uniform (-5 0 0)/uniform (-3 0 0)/; s/uniform (5 0 0)/uniform (3 0 0)/' 0/U
    foamDictionary -entry particles -remove constant/particleProperties \
        > /dev/null
    foamDictionary -entry particlesFile -add '"particleList"' \
        constant/particleProperties > /dev/null
    foamDictionary -entry groups -set \
        '{ light { } heavy { density 3; } }' \
        constant/particleProperties > /dev/null
    foamDictionary -entry gravity -add '(0 -1 0)' \
        constant/particleProperties > /dev/null
    foamDictionary -entry coupling.lambdaTolerance -set 1e-5 \
        constant/particleProperties > /dev/null
    cat > constant/particleList <<'LIST'
// group  position          radius
(
    (light (1.55 0.52 1.47) 1)
    (heavy (4.45 0.03 4.51) 1.2)
    (light (3.02 -1.48 2.97) 1)
)
LIST
    foamDictionary -entry functions -add \
        '{ stress { type suspensionStress; libs ("libfdmParticles.so");
           wallLayer 1; bins 6; } }' system/controlDict > /dev/null
    foamDictionary -entry deltaT -set 0.05 system/controlDict > /dev/null
    foamDictionary -entry endTime -set 0.2 system/controlDict > /dev/null
    runLogged blockMesh || exit 1
) || exit 1

cp -r "$work/straight" "$work/restarted"
cp -r "$work/straight" "$work/segment"
cp -r "$work/straight" "$work/continued"
# From outside the case (-case): particlesFile is found in its constant/
(
    cd "$work" && runLogged fdmSuspensionFoam -case straight &&
    mv log.fdmSuspensionFoam straight/
) || exit 1
(
    cd "$work/restarted" && runStoppedAndRestarted 0.15 0.2
) || exit 1

# On another machine: the first segment to 0.1 leaves a particle
# checkpoint (no fields), which a case set up anew continues from
checkpoint() { "$FDM_PYTHON" -m fdmPost.checkpoint "$@" >> log.checkpoint 2>&1 ||
    { echo "FAILED: checkpoint $* (log: $PWD/log.checkpoint)"; return 1; }; }
(
    cd "$work/segment" || exit 1
    foamDictionary -entry writeInterval -set 2 system/controlDict > /dev/null
    foamDictionary -entry endTime -set 0.1 system/controlDict > /dev/null
    runLogged fdmSuspensionFoam && checkpoint save . ../checkpoint --layer 1
) || exit 1
(
    cd "$work/continued" &&
    foamDictionary -entry startFrom -set latestTime system/controlDict \
        > /dev/null && checkpoint restore ../checkpoint . &&
    runLogged fdmSuspensionFoam && checkpoint save . ../checkpoint --layer 1
) || exit 1

(cd "$work/straight" && runLogged postProcess) || exit 1

"$FDM_PYTHON" "$caseTemplates/checkRestart.py" "$work" &&
"$FDM_PYTHON" "$caseTemplates/checkSuspensionStress.py" "$work"
