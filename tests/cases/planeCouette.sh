#!/bin/bash
# Case test: particle-free plane Couette flow, walls at -0.5 and +0.5,
# serial and 2 MPI ranks; analytic linear profile.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir planeCouette)
cloneCase planeChannel "$work"
runSerialAndParallel "$work" || exit 1

"$FDM_PYTHON" "$caseTemplates/checkChannelProfile.py" --case "$work" --time 1 \
    --profile couette --wall-speed 0.5 --delta 0.0625
