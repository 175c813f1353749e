#!/bin/bash
# Case test: particle-free plane Poiseuille flow driven by the imposed mean
# pressure gradient, walls with the second-order wall gradient
# (secondOrderWallVelocity), serial and 2 MPI ranks, against the analytic
# parabola.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir planePoiseuille)
poiseuilleChannel "$work" secondOrderWallVelocity || exit 1
runSerialAndParallel "$work" || exit 1

"$FDM_PYTHON" "$caseTemplates/checkChannelProfile.py" --case "$work" --time 1 \
    --profile poiseuille --gradp -8 --nu 1 --delta 0.0625 --wall-gradient quadratic
