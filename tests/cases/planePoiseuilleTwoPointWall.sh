#!/bin/bash
# Case test: plane Poiseuille flow as planePoiseuille.sh but with the stock
# fixedValue wall (two-point wall gradient, the thesis' discretisation),
# against the exact solution of its discrete equations.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir planePoiseuilleTwoPointWall)
poiseuilleChannel "$work" fixedValue || exit 1
runSerialAndParallel "$work" || exit 1

"$FDM_PYTHON" "$caseTemplates/checkChannelProfile.py" --case "$work" --time 1 \
    --profile poiseuille --gradp -8 --nu 1 --delta 0.0625 --wall-gradient two-point
