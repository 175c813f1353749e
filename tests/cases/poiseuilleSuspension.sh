#!/bin/bash
# Case test: the Poiseuille suspension tutorial's set-up (39 bidisperse
# frictional spheres at phi0 = 0.3 between stationary walls, uniform
# pressure gradient, sub-grid lubrication, contacts) for 10 steps on 2
# ranks.  checkPoiseuilleSuspension.py checks the whole-channel x-momentum
# balance (pressure-gradient force = wall shear + particles' lambda) and
# the slope of the shear-stress profile against dP0/dx (eq F.6a).  The same
# on 2 ranks with the particle system solved by subdomain
# (parallelParticleSolve distributed: each rank assembles the rows of the
# spheres centred in its half from their integrals summed on it, and
# solves them with the others as ghosts) gives the same particle series
# over its first 5 steps.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir poiseuilleSuspension)
tutorial="$FDM_PROJECT_DIR/tutorials/poiseuille"
cp -r "$tutorial"/{0,constant,system} "$work"/
(
    cd "$work" || exit 1
    sed -i -e 's/^endTime .*/endTime 0.05;/' \
        -e 's/^writeInterval .*/writeInterval 5;/' system/controlDict
    foamDictionary -entry output.timeSeriesInterval -set 1 \
        constant/particleProperties > /dev/null || exit 1
    fdmPackParticles --box 10 10 8 --walls y --phi 0.3 --seed 1 \
        -o constant/particleList > log.fdmPackParticles || exit 1
    mkdir distributed && cp -r 0 constant system distributed/ || exit 1
    foamDictionary -entry endTime -set 0.025 distributed/system/controlDict \
        > /dev/null || exit 1
    runLogged blockMesh || exit 1
    runLogged decomposePar || exit 1
    runLogged mpirun -np 2 fdmSuspensionFoam -parallel || exit 1
    runLogged reconstructPar -fields '(U p)' || exit 1
) || exit 1
runBySubdomain "$work/distributed" || exit 1

"$FDM_PYTHON" "$caseTemplates/checkPoiseuilleSuspension.py" "$work"
