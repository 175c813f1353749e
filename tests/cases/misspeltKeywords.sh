#!/bin/bash
# Case test: every keyword of the dictionaries the project reads, misspelt
# once (misspellEachKeyword.py appends an x), stops the solver with a FOAM
# FATAL message naming it, before any time is written:
#  - fdmSuspensionFoam on the shearedSphere case: particleProperties,
#    transportProperties, flowProperties, the SIMPLEC block of fvSolution;
#  - fdmSuspensionFoam on the Couette tutorial: particleProperties (output,
#    subGrid tables, contact) and the suspensionStress function object;
#  - lubricatedDEMFoam on the lubricatedShear and resuspension tutorials'
#    particleProperties (cell, drag, gravity, fixed groups, contact model).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir misspeltKeywords)
sweep="$FDM_PYTHON $caseTemplates/misspellEachKeyword.py"
failed=0

# shearedSphere
cloneCase shearedSphere "$work/sphere"
(cd "$work/sphere" && runLogged blockMesh) || exit 1
for file in constant/particleProperties constant/transportProperties \
    constant/flowProperties
do
    $sweep "$work/sphere" $file fdmSuspensionFoam || failed=1
done
$sweep "$work/sphere" system/fvSolution fdmSuspensionFoam --within SIMPLEC \
    || failed=1

# The Couette tutorial's particle input
couette="$work/couette"
mkdir -p "$couette"
cp -r "$FDM_PROJECT_DIR/tutorials/couette"/{0,constant,system} "$couette"/
(
    cd "$couette" && runLogged blockMesh \
        && runLogged fdmPackParticles --box 8 8 8 --walls y --phi 0.3 \
            --seed 1 -o constant/particleList
) || exit 1
$sweep "$couette" constant/particleProperties fdmSuspensionFoam || failed=1
$sweep "$couette" system/fvSolution fdmSuspensionFoam --within SIMPLEC \
    || failed=1
$sweep "$couette" system/controlDict fdmSuspensionFoam \
    --within suspensionStress || failed=1

# The DEM tutorials' particle input
for tutorial in lubricatedShear resuspension
do
    dir="$work/$tutorial"
    mkdir -p "$dir"
    cp -r "$FDM_PROJECT_DIR/tutorials/$tutorial"/{system,constant} "$dir"/
    sed -i -e 's/^endTime .*/endTime 0.001;/' "$dir/system/controlDict"
    case $tutorial in
        lubricatedShear)
            pack="--box 16 16 16 --walls '' --phi 0.3" ;;
        resuspension)
            pack="--box 12 16 12 --walls y --phi 0.3 --ratio 1
                --attach-walls 0.5 --jammed --attach-sides lower" ;;
    esac
    (cd "$dir" && eval runLogged fdmPackParticles $pack \
        -o constant/particleList) || exit 1
    $sweep "$dir" constant/particleProperties lubricatedDEMFoam || failed=1
done

[ "$failed" -eq 0 ]
