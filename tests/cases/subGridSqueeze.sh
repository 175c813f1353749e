#!/bin/bash
# Case test: two free spheres (a = 1, Delta = a/5) at a surface gap of
# 0.02 a, pushed together by equal and opposite forces, walls at x = +-5,
# cyclic in y and z.  Solved with the frameInvariant sub-grid lubrication
# and without it, and with it on 2 ranks, the particle system solved whole
# on each rank and by subdomain (parallelParticleSolve distributed: each
# rank solves its sphere's rows, the other sphere a ghost);
# checkSubGridSqueeze.py compares the approach velocity with the two-sphere
# theory (Jeffrey & Onishi 1984) and the parallel runs with the serial one.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir subGridSqueeze)
for model in frameInvariant none
do
    cloneCase subGridSqueeze "$work/$model"
    # "none" takes no other keyword, so the block is replaced whole
    if [ "$model" = none ]
    then
        foamDictionary -entry subGrid -set "{ model none; }" \
            "$work/$model/constant/particleProperties" > /dev/null || exit 1
    fi
    (
        cd "$work/$model" || exit 1
        runLogged blockMesh && runLogged fdmSuspensionFoam
    ) || exit 1
done

# With the sub-grid model on 2 ranks, cut through the gap
cloneCase subGridSqueeze "$work/parallel"
runDecomposed "$work/parallel" || exit 1
cloneCase subGridSqueeze "$work/distributed"
runBySubdomain "$work/distributed" || exit 1

"$FDM_PYTHON" "$caseTemplates/checkSubGridSqueeze.py" "$work"
