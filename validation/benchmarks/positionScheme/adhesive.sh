#!/bin/bash
#------------------------------------------------------------------------------
# The time step of the adhesive Couette suspension (thesis 1, chapter 5;
# the campaign of tutorials/adhesion/runCampaign):
#
#   ./adhesive.sh [WINDOW]
#
# From adhesiveState/particleState.15.5 (phi0 0.37, G_0 4.4, 10 x 20 x 10
# a1, 120 spheres, strain 15.5 of a run at gammaDot dt 4e-3), WINDOW strain
# (default 0.32) on 2 ranks with runPoint -adhesion's setting (the steps
# between records to the loose lambda residual): at 5e-4, 1e-3, 2e-3 and
# 4e-3 with a record every 0.02 strain, compared record by record with
# 5e-4, and at 1e-3, 2e-3 and 4e-3 with the campaign's record every 0.16
# strain for the cost (compareSteps.py; report_adhesive.md).  Each log has
# the velocity alternation per step.  Cases in
# build/benchmarks/positionScheme/adhesive; about 15 min on 2 cores.
#------------------------------------------------------------------------------
cd "${0%/*}" || exit 1
source ../../../etc/bashrc
. "$FDM_PROJECT_DIR/etc/caseFunctions"

window=${1:-0.32}
work=$FDM_PROJECT_DIR/build/benchmarks/positionScheme/adhesive
. adhesiveState/restore
point=$adhesivePoint
restoreAdhesiveState "$work" 4e-3 2 || exit 1
end=$(awk -v w="$window" 'BEGIN { print 15.5 + w }')
for run in "5e-4 0.02" "1e-3 0.02" "2e-3 0.02" "4e-3 0.02" \
    "1e-3 0.16" "2e-3 0.16" "4e-3 0.16"
do
    set -- $run
    case=$work/dt$1_records$2
    if ! grep -qs "^End" "$case/log.fdmSuspensionFoam"
    then
        rm -rf "$case"
        cp -r "$work/$point" "$case"
        (
            cd "$case" || exit 1
            rm -f log.*
            setTimeStep "$1" "$2" "$window"
            foamDictionary -entry endTime -set "$end" system/controlDict \
                > /dev/null
            runSolver 2 log.fdmSuspensionFoam
        ) || { echo "adhesive.sh: the run at $1 failed ($case)"; continue; }
    fi
    rm -rf "$case/records"
    "$FDM_PYTHON" -m fdmPost.checkpoint save "$case" "$case/records" \
        --layer 5 > /dev/null
done
{
    echo "# The adhesive suspension's time step ($(date +%F), $window strain from strain 15.5)"
    echo
    "$FDM_PYTHON" compareSteps.py "$work"
} | tee report_adhesive.md
#------------------------------------------------------------------------------
