#!/bin/bash
# Case test: every documented way to run the suspensionStress function
# object after a run (README "Output"; the template
# etc/caseDicts/postProcessing/suspension/suspensionStress) works and leaves
# what the run wrote untouched.  The contactOnWall case (walls normal to y)
# runs two steps, written each; then
#   postProcess -func suspensionStress
#   postProcess -func 'suspensionStress(bins=4, wallLayer=0)'
#   foamPostProcess -func suspensionStress
#   fdmSuspensionFoam -postProcess -func suspensionStress
#   postProcess   (system/controlDict: #includeFunc suspensionStress)
# each must exit 0, write a new suspensionStress*.dat with a row per written
# time, and change or remove no file that was there before it.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir postProcessInvocations)
cloneCase contactOnWall "$work"
cd "$work" || exit 1
foamDictionary -entry endTime -set 0.1 system/controlDict > /dev/null
foamDictionary -entry writeInterval -set 1 system/controlDict > /dev/null
runLogged blockMesh && runLogged fdmSuspensionFoam -quiet || exit 1

# The function object's tables (a name with arguments is its own folder)
datFiles()
{
    ls postProcessing/suspensionStress*/*/suspensionStress*.dat 2> /dev/null \
        | sort
}

# Bookkeeping outside the case
book=$(mktemp -d)
trap 'rm -rf "$book"' EXIT
fail=0
invoke()
{
    local name=$1
    shift
    find . -type f -not -name "log.*" | sort > "$book/files"
    xargs md5sum < "$book/files" > "$book/md5"
    datFiles > "$book/dat"
    if ! "$@" > "log.$name" 2>&1
    then
        echo "FAILED: $* exits with an error (log: $PWD/log.$name)"
        tail -n 10 "log.$name"
        fail=1
        return
    fi
    if grep -q "Cannot find functionObject" "log.$name"
    then
        echo "FAILED: $*: function object not found"
        fail=1
    fi
    if ! md5sum --quiet -c "$book/md5" > /dev/null 2>&1
    then
        echo "FAILED: $* changed or removed files of the run:"
        md5sum --quiet -c "$book/md5" 2>&1 | head -n 5
        fail=1
    fi
    local new
    new=$(datFiles | comm -13 "$book/dat" -)
    local rows
    rows=$([ -n "$new" ] && grep -vc "^#" $new)
    if [ "$rows" = 2 ]
    then
        echo "   $*: ok, $rows rows in ${new#./}"
    else
        echo "FAILED: $*: expected one new file with 2 rows, got '${new}' (${rows:-0} rows)"
        fail=1
    fi
}

invoke func postProcess -func suspensionStress
invoke funcArgs postProcess -func 'suspensionStress(bins=4, wallLayer=0)'
invoke foamPostProcess foamPostProcess -func suspensionStress
invoke solverPostProcess fdmSuspensionFoam -postProcess -func suspensionStress
cat >> system/controlDict <<'DICT'
functions
{
    #includeFunc suspensionStress
}
DICT
invoke controlDict postProcess
# With the time range option
invoke latestTime postProcess -func suspensionStress -time '0.05:0.1'
exit $fail
