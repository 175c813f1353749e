#!/bin/bash
# Case test: particle-free plane Poiseuille flow driven by the imposed mean
# pressure gradient dP0/dx = -8 (nu = 1, H = 1: centre velocity 1), walls at
# rest with the second-order wall gradient (secondOrderWallVelocity), serial
# and 2 MPI ranks, against the analytic parabola.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir planePoiseuille)
cloneCase planeChannel "$work"
(
    cd "$work" || exit 1
    foamDictionary -entry meanPressureGradient -set "(-8 0 0)" constant/flowProperties > /dev/null
    for wall in bottomWall topWall
    do
        foamDictionary -entry "boundaryField.$wall" \
            -set "{ type secondOrderWallVelocity; value uniform (0 0 0); }" 0/U > /dev/null
    done
) || exit 1
runSerialAndParallel "$work" || exit 1

"$FDM_PYTHON" "$caseTemplates/checkChannelProfile.py" --case "$work" --time 1 \
    --profile poiseuille --gradp -8 --nu 1 --delta 0.0625 --wall-gradient quadratic
