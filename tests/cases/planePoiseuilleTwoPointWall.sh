#!/bin/bash
# Case test: plane Poiseuille flow as planePoiseuille.sh but with the stock
# fixedValue wall (two-point wall gradient, the thesis' discretisation),
# against the exact solution of its discrete equations.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir planePoiseuilleTwoPointWall)
cloneCase planeChannel "$work"
(
    cd "$work" || exit 1
    foamDictionary -entry meanPressureGradient -set "(-8 0 0)" constant/flowProperties > /dev/null
    for wall in bottomWall topWall
    do
        foamDictionary -entry "boundaryField.$wall.value" -set "uniform (0 0 0)" 0/U > /dev/null
    done
) || exit 1
runSerialAndParallel "$work" || exit 1

"$FDM_PYTHON" "$caseTemplates/checkChannelProfile.py" --case "$work" --time 1 \
    --profile poiseuille --gradp -8 --nu 1 --delta 0.0625 --wall-gradient two-point
