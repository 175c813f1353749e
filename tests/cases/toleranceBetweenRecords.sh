#!/bin/bash
# Case test: coupling.lambdaToleranceBetweenRecords.  Three free spheres
# (one heavy) in a sheared channel, 6 steps, an HDF5 record every 3rd step
# and fields at the end only, lambdaTolerance 1e-4 and 1e-2 between
# records, with their own U and p solvers (fvSolution UBetweenRecords
# smoothSolver, pBetweenRecords GAMG: PCG elsewhere) and one pressure
# correction (nCorrectorsBetweenRecords, 2 elsewhere); the same case
# without these keywords beside it.  Checks in
# checkToleranceBetweenRecords.py: the recorded steps stop below 1e-4 with
# the PCG solvers and 2 pressure corrections, the others between 1e-4 and
# 1e-2 in fewer outer iterations than the same steps of the tight run,
# with smoothSolver, GAMG and one correction; momentumBalance.dat holds
# the solves at 1e-4 only (the initial one and the recorded steps),
# particles.h5 the records.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir toleranceBetweenRecords)
cloneCase shearedSphere "$work/tight"
(
    cd "$work/tight" || exit 1
    # Box 6 x 6 x 6, walls at -3 and 3 moving at -3 and 3
    sed -i -e 's/^    (0 -5 0) .*$/    (0 -3 0) (6 -3 0) (6 3 0) (0 3 0)/' \
        -e 's/^    (0 -5 10) .*$/    (0 -3 6) (6 -3 6) (6 3 6) (0 3 6)/' \
        -e 's/(50 50 50)/(30 30 30)/' system/blockMeshDict
    sed -i 's/uniform (-5 0 0)/uniform (-3 0 0)/; s/uniform (5 0 0)/uniform (3 0 0)/' 0/U
    pp=constant/particleProperties
    foamDictionary -entry particles -set \
        '((light (1.55 0.52 1.47) 1) (heavy (4.45 0.03 4.51) 1.2)
          (light (3.02 -1.48 2.97) 1))' $pp > /dev/null
    foamDictionary -entry groups -set \
        '{ light { } heavy { density 3; } }' $pp > /dev/null
    foamDictionary -entry gravity -add '(0 -1 0)' $pp > /dev/null
    foamDictionary -entry coupling.lambdaTolerance -set 1e-4 $pp > /dev/null
    foamDictionary -entry output -add '{ timeSeriesInterval 3; }' $pp \
        > /dev/null
    foamDictionary -entry deltaT -set 0.05 system/controlDict > /dev/null
    foamDictionary -entry endTime -set 0.3 system/controlDict > /dev/null
    foamDictionary -entry writeInterval -set 6 system/controlDict > /dev/null
    runLogged blockMesh || exit 1
) || exit 1

cp -r "$work/tight" "$work/loose"
foamDictionary -entry coupling.lambdaToleranceBetweenRecords -add 1e-2 \
    "$work/loose/constant/particleProperties" > /dev/null || exit 1
fvSolution="$work/loose/system/fvSolution"
foamDictionary -entry solvers.UBetweenRecords -add \
    '{ solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8;
       relTol 0.3; }' "$fvSolution" > /dev/null || exit 1
foamDictionary -entry solvers.pBetweenRecords -add \
    '{ solver GAMG; smoother GaussSeidel; tolerance 1e-8; relTol 0.2; }' \
    "$fvSolution" > /dev/null || exit 1
foamDictionary -entry SIMPLEC.nCorrectorsBetweenRecords -add 1 \
    "$fvSolution" > /dev/null || exit 1

for name in tight loose
do
    (cd "$work/$name" && runLogged fdmSuspensionFoam) || exit 1
done

"$FDM_PYTHON" "$caseTemplates/checkToleranceBetweenRecords.py" "$work"
