#!/bin/bash
# Case test: the layer-mean coarse correction of the outer iteration
# (SIMPLEC layerMeanCorrection, layerMeanViscosityRatio 1) on the
# particle-free plane Poiseuille and Couette channels, serial and 2 MPI
# ranks (split across the walls, so the layers span ranks).  The flows are
# one-dimensional, so the correction solves them at once: the step must
# converge to outerTolerance 1e-14 in at most 5 outer iterations (without
# it: 518 for Poiseuille) to the analytic profiles.
source "${0%/*}/caseTestFunctions"

withCorrection()
{
    foamDictionary -entry coeffs.n -set "(1 2 1)" \
        "$1/system/decomposeParDict" > /dev/null &&
    foamDictionary -entry SIMPLEC.layerMeanCorrection -set on \
        "$1/system/fvSolution" > /dev/null &&
    foamDictionary -entry SIMPLEC.layerMeanViscosityRatio -set 1 \
        "$1/system/fvSolution" > /dev/null
}

# Outer iterations of every run of the case (serial and parallel logs)
checkOuterIterations()
{
    local log n
    for log in "$1/log.fdmSuspensionFoam" "$1/parallel/log.fdmSuspensionFoam.parallel"
    do
        n=$(sed -n 's/^SIMPLEC: converged in \([0-9]*\) outer.*/\1/p' "$log")
        if [ -z "$n" ] || [ "$n" -gt 5 ]
        then
            echo "FAILED: $log: converged in '${n:-never}' outer iterations" \
                 "(allowed: at most 5)"
            return 1
        fi
        echo "   $(basename "$log"): $n outer iterations"
    done
}

poiseuille=$(caseWorkDir layerMeanPoiseuille)
poiseuilleChannel "$poiseuille" fixedValue || exit 1
withCorrection "$poiseuille" || exit 1
runSerialAndParallel "$poiseuille" || exit 1
checkOuterIterations "$poiseuille" || exit 1
"$FDM_PYTHON" "$caseTemplates/checkChannelProfile.py" --case "$poiseuille" \
    --time 1 --profile poiseuille --gradp -8 --nu 1 --delta 0.0625 || exit 1

couette=$(caseWorkDir layerMeanCouette)
cloneCase planeChannel "$couette"
withCorrection "$couette" || exit 1
runSerialAndParallel "$couette" || exit 1
checkOuterIterations "$couette" || exit 1
"$FDM_PYTHON" "$caseTemplates/checkChannelProfile.py" --case "$couette" \
    --time 1 --profile couette --wall-speed 0.5 --delta 0.0625
