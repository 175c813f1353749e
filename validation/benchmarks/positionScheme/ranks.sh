#!/bin/bash
#------------------------------------------------------------------------------
# How the adhesion campaign should use the two cores: one point on 2 ranks
# (runCampaign today) or two points at once, one rank each.
#
#   ./ranks.sh [WINDOW]
#
# From adhesiveState/particleState.15.5 (phi0 0.37, G_0 4.4, 10 x 20 x 10
# a1, 120 spheres), WINDOW strain (default 0.3) at the campaign's setting
# (gammaDot deltaT 1e-3, a record every 0.16 strain): on 2 ranks alone, on
# 1 rank alone, and on 1 rank twice at the same time (two copies, the
# load of two campaign points side by side).  Prints the wall seconds per
# strain of each and the machine's throughput (strain per wall hour, all
# runs together; from the solver's step times), and the outer iterations
# per step, so that the runs are seen to do the same work.  Cases in
# build/benchmarks/positionScheme/ranks; about 5 min on 2 cores, alone on
# the machine.
#------------------------------------------------------------------------------
cd "${0%/*}" || exit 1
source ../../../etc/bashrc
. "$FDM_PROJECT_DIR/etc/caseFunctions"

window=${1:-0.3}
work=$FDM_PROJECT_DIR/build/benchmarks/positionScheme/ranks
. adhesiveState/restore
point=$adhesivePoint
end=$(awk -v w="$window" 'BEGIN { print 15.5 + w }')

# setUp NPROCS: the point restored at strain 15.5 in $work/np<NPROCS>
setUp()
{
    restoreAdhesiveState "$work/np$1" 1e-3 "$1"
}

# start NPROCS NAME: a copy of the restored point run to $end in the
# background
start()
{
    local case=$work/$2
    rm -rf "$case"
    cp -r "$work/np$1/$point" "$case"
    (
        cd "$case" || exit 1
        rm -f log.*
        setTimeStep 1e-3 0.16 "$window"
        foamDictionary -entry endTime -set "$end" system/controlDict > /dev/null
        runSolver "$1" log.fdmSuspensionFoam
    ) &
}

# report NAME RUNS_AT_ONCE: the solver's own step times summed (start-up
# and set-up left out), per strain, and the machine's throughput
report()
{
    grep "^Step" "$work/$1/log.fdmSuspensionFoam" | awk -v n="$1" \
        -v k="$2" -v w="$window" '{
            for (i = 1; i < NF; i++) {
                if ($i == "stepTime") t += $(i + 1)
                if ($i == "outer") o += $(i + 1)
            }
            steps++ }
        END {
            printf "| %s | %d | %.0f | %.0f | %.2f |\n", n, k, t/w,
                k*3600*w/t, o/steps }'
}

setUp 2 || { echo "ranks.sh: set-up on 2 ranks failed"; exit 1; }
setUp 1 || { echo "ranks.sh: set-up on 1 rank failed"; exit 1; }
{
    echo "# One point on 2 ranks or two points on 1 rank each ($(date +%F), $window strain from strain 15.5)"
    echo
    echo "| run | runs at once | wall s per strain | machine: strain per hour | outer per step |"
    echo "|---|---|---|---|---|"
    start 2 twoRanks; wait; report twoRanks 1
    start 1 oneRank; wait; report oneRank 1
    start 1 oneRankA; start 1 oneRankB; wait
    report oneRankA 2; report oneRankB 2
} | tee report_ranks.md
#------------------------------------------------------------------------------
