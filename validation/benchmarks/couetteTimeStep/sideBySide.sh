#!/bin/bash
# The commit before issue 30 built and run side by side with this tree
# (issue 30, "Must show"): STRAIN (default 0.24) of the sheared phi0 = 0.42
# suspension from a snapshot, at gammaDot deltaT 4e-3, with the old build
# and its tutorial's settings and with this build and the setting of one
# couetteTimeStep run, both at once on the 2 cores; prints each solver's
# Timing line, core-seconds per step and per strain (also per 10^6 cells)
# and peak resident memory.  A short window holds a share of written steps
# that depends on where it starts and ends (the last step of a run is
# always written), so each build's cost per strain is also composed from
# its Step lines as in a long run: (n - 1) steps between records and one
# written step per record interval of n steps (output.timeSeriesInterval),
# the run's last step (written with the fields) left out (builds that
# print no Step lines, as f09ef70, converge every step alike).
#
#   ./sideBySide.sh COMMIT NEWRUN [STRAIN [SNAPSHOT:T [N...]]]
#
# COMMIT: e.g. f09ef70 (the last before issue 30), built once by
# etc/buildCommit (a git worktree in build/sideBySide/COMMIT).  NEWRUN: a
# run case of run.py whose system/fvSolution, system/fvSchemes and
# constant/particleProperties give the new setting.  SNAPSHOT:T: a case
# and its written time to start from (default the couetteTimeStep
# snapshot, 10 x 20 x 10 a1 at strain 1; the thesis box: the frozenCouette
# snapshot of runPoint 0.42 20 20 0.02, build/benchmarks/frozenCouette/
# snapshots/phi0.42_20x20_0.02:0.02).  N...: record intervals (steps) to
# compose the new build's cost at besides its own.
cd "${0%/*}" || exit 1
source ../../../etc/bashrc
commit=${1:?usage: sideBySide.sh COMMIT NEWRUN [STRAIN [SNAPSHOT:T [N...]]]}
newRun=${2:?usage: sideBySide.sh COMMIT NEWRUN [STRAIN [SNAPSHOT:T [N...]]]}
strain=${3:-0.24}
start=${4:-$FDM_PROJECT_DIR/build/benchmarks/couetteTimeStep/snapshots/phi0.42_10x20x10_1:1}
snapshot=${start%:*}
t0=${start##*:}
composeAt=
[ $# -gt 4 ] && composeAt="${*:5}"
work=$FDM_PROJECT_DIR/build/sideBySide
[ -d "$snapshot/$t0" ] || { echo "no snapshot $snapshot/$t0 (couetteTimeStep: run ./Allrun first)"; exit 1; }
old=$("$FDM_PROJECT_DIR/etc/buildCommit" "$commit" fdmSuspensionFoam) || exit 1

# Old: the snapshot with the Couette tutorial's solver and coupling
# settings of that commit, as its users ran it
rm -rf "$work/case.old" "$work/case.new"
mkdir -p "$work/case.old"
cp -r "$snapshot"/{constant,system} "$snapshot/$t0" "$work/case.old"/
for f in system/fvSolution constant/particleProperties
do
    git -C "$FDM_PROJECT_DIR" show "$commit:tutorials/couette/$f" \
        > "$work/case.old/$f" || exit 1
done
# New: the same start with the run's solver and coupling settings
mkdir -p "$work/case.new"
cp -r "$snapshot"/{constant,system} "$snapshot/$t0" "$work/case.new"/
for f in system/fvSolution system/fvSchemes constant/particleProperties
do
    cp "$newRun/$f" "$work/case.new/$f" || exit 1
done
end=$(awk -v t="$t0" -v d="$strain" 'BEGIN { print t + d }')
for c in old new
do
    dict=$work/case.$c/system/controlDict
    foamDictionary -entry deltaT -set 4e-3 "$dict" > /dev/null
    foamDictionary -entry endTime -set "$end" "$dict" > /dev/null
    foamDictionary -entry writeControl -set runTime "$dict" > /dev/null
    foamDictionary -entry writeInterval -set "$strain" "$dict" > /dev/null
    foamDictionary -entry functions -set "{}" "$dict" > /dev/null
done
# Each from its case directory: builds before the fix of particlesFile
# paths cannot run with -case from elsewhere
timed() { /usr/bin/time -f "maxrss %M kB" -o time.log fdmSuspensionFoam; }
(cd "$work/case.old" && source "$old/etc/bashrc" > /dev/null 2>&1 &&
 timed > log 2>&1) &
(cd "$work/case.new" && timed > log 2>&1)
wait
cells=$(grep -o 'nCells: *[0-9]*' "$work/case.new/constant/polyMesh/owner" |
    grep -o '[0-9]*$')
for c in old new
do
    line=$(grep '^Timing' "$work/case.$c/log" | tail -1)
    echo "$c: $line"
    echo "$line" | awk -v s="$strain" -v n="$cells" '{
        printf "    %.2f core-s per step, %.0f per strain, %.0f per strain per 10^6 cells (%d cells; the time loop, all of it)\n",
            $11/$8, $11/s, $11/s*1e6/n, n }'
    n=$(foamDictionary -entry output.timeSeriesInterval -value \
        "$work/case.$c/constant/particleProperties" 2>/dev/null || echo 1)
    # Written steps are those of the run's own interval n; the cost is
    # composed at n and (new build) at each interval of composeAt
    every=$n
    [ "$c" = new ] && every="$n $composeAt"
    grep '^Step' "$work/case.$c/log" | awk -v n="$n" -v every="$every" -v c="$cells" '
        { step[NR] = $2; t[NR] = $(NF - 2); dt = $7 - prev; prev = $7 }
        END {
            if (NR < 3) { exit }    # builds without Step lines
            for (i = 1; i < NR; ++i)
            {
                if (n > 1 && step[i] % n == 0) { tr += t[i]; nr++ }
                else { tb += t[i]; nb++ }
            }
            k = split(every, at, " ")
            for (j = 1; j <= k; ++j)
            {
                m = at[j]
                interval = (m > 1 && nr > 0) ? (m - 1)*tb/nb + tr/nr : m*tb/nb
                printf "    composed: %.0f core-s per strain per 10^6 cells (%d steps between records at %.3g s, %d written at %.3g s, a record every %d steps)\n",
                    interval/(m*dt)*1e6/c, nb, tb/(nb ? nb : 1), nr, tr/(nr ? nr : 1), m
            }
        }'
    echo "    peak resident memory $(awk '{ printf "%.2f GiB", $2/1048576 }' "$work/case.$c/time.log")"
done
