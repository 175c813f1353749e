#!/bin/bash
# Serial against 2 ranks (issue 30: parallel efficiency and memory): STRAIN
# (default 0.2) of one couetteTimeStep run from its start, once serial and
# once on 2 ranks, each alone on the machine; prints the solver's Timing
# line, the wall time and the peak resident memory of each.
#
#   ./ranks.sh RUNCASE [STRAIN]
#
# RUNCASE: a case of run.py, e.g. $FDM_PROJECT_DIR/build/benchmarks/
# couetteTimeStep/dt_4e-3_layerMean_consistent_alphaF0.5_betweenRecords2e-2_
# innerBetween_records10_tol1e-3_window1.0 (its start time is used).
cd "${0%/*}" || exit 1
source ../../../etc/bashrc
run=${1:?usage: ranks.sh RUNCASE [STRAIN]}
strain=${2:-0.2}
start=$(foamListTimes -case "$run" -withZero 2>/dev/null | head -1)
work=$FDM_PROJECT_DIR/build/benchmarks/couetteTimeStepRanks
end=$(awk -v s="$start" -v d="$strain" 'BEGIN { print s + d }')
for n in 1 2
do
    case=$work/np$n
    rm -rf "$case" && mkdir -p "$case" || exit 1
    cp -r "$run"/{constant,system,"$start"} "$case"/
    rm -rf "$case/$start/lagrangian"
    foamDictionary -entry endTime -set "$end" "$case/system/controlDict" \
        > /dev/null
    foamDictionary -entry writeInterval -set "$strain" \
        "$case/system/controlDict" > /dev/null
    command=(fdmSuspensionFoam -case "$case")
    if [ "$n" -gt 1 ]
    then
        foamDictionary -entry numberOfSubdomains -set "$n" \
            "$case/system/decomposeParDict" > /dev/null
        foamDictionary -entry coeffs.n -set "($n 1 1)" \
            "$case/system/decomposeParDict" > /dev/null
        decomposePar -case "$case" > "$case/log.decomposePar" 2>&1 || exit 1
        command=(mpirun -np "$n" fdmSuspensionFoam -parallel -case "$case")
    fi
    /usr/bin/time -f "wall %e s, peak resident memory of one rank %M kB" \
        "${command[@]}" > "$case/log" 2> "$case/time.log" || exit 1
    echo "$n rank(s): $(grep '^Timing' "$case/log" | tail -1)"
    echo "    $(tail -1 "$case/time.log")"
done
