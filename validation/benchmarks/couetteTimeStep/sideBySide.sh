#!/bin/bash
# The commit before issue 30 built and run side by side with this tree
# (issue 30, "Must show"): STRAIN (default 0.24) of the sheared phi0 = 0.42
# suspension from the couetteTimeStep snapshot, at gammaDot deltaT 4e-3,
# with the old build and its tutorial's settings and with this build and
# the setting of one couetteTimeStep run, both at once on the 2 cores;
# prints each solver's Timing line and core-seconds per strain.
#
#   ./sideBySide.sh COMMIT NEWRUN [STRAIN]
#
# COMMIT: e.g. f09ef70 (the last before issue 30), built once in
# build/sideBySide/COMMIT (a git worktree sharing ThirdParty/).  NEWRUN: a
# run case of run.py whose constant/ and system/ give the new setting.
cd "${0%/*}" || exit 1
source ../../../etc/bashrc
commit=${1:?usage: sideBySide.sh COMMIT NEWRUN [STRAIN]}
newRun=${2:?usage: sideBySide.sh COMMIT NEWRUN [STRAIN]}
strain=${3:-0.24}
work=$FDM_PROJECT_DIR/build/sideBySide
old=$work/$commit
snapshot=$FDM_PROJECT_DIR/build/benchmarks/couetteTimeStep/snapshots/phi0.42_10x20x10_1
[ -d "$snapshot/1" ] || { echo "no snapshot: run ./Allrun first"; exit 1; }
if [ ! -x "$old/platforms/linux64GccDPInt32Opt/bin/fdmSuspensionFoam" ]
then
    mkdir -p "$work"
    git -C "$FDM_PROJECT_DIR" worktree add -f "$old" "$commit" > /dev/null || exit 1
    ln -sfn "$FDM_PROJECT_DIR/ThirdParty" "$old/ThirdParty"
    (cd "$old" && ./Allwmake > "$work/log.Allwmake.$commit" 2>&1) || exit 1
fi

# Old: the snapshot with the Couette tutorial's solver and coupling
# settings of that commit, as its users ran it
rm -rf "$work/case.old" "$work/case.new"
cp -r "$snapshot" "$work/case.old"
for f in system/fvSolution constant/particleProperties
do
    git -C "$FDM_PROJECT_DIR" show "$commit:tutorials/couette/$f" \
        > "$work/case.old/$f" || exit 1
done
# New: the same start with the run's dictionaries
mkdir -p "$work/case.new"
cp -r "$newRun"/{constant,system} "$snapshot/1" "$work/case.new"/
end=$(awk -v d="$strain" 'BEGIN { print 1 + d }')
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
(cd "$work/case.old" && source "$old/etc/bashrc" > /dev/null 2>&1 &&
 fdmSuspensionFoam > log 2>&1) &
(cd "$work/case.new" && fdmSuspensionFoam > log 2>&1)
wait
for c in old new
do
    line=$(grep '^Timing' "$work/case.$c/log" | tail -1)
    echo "$c: $line"
    echo "$line" | awk -v s="$strain" \
        '{ printf "    %.0f core-s per strain (the time loop, all of it)\n", $11/s }'
done
