#!/bin/bash
# Case test (hostile-input tier): nothing a run wrote is lost, a diverging
# solve writes nothing, a kill at any moment leaves a case that restarts.
#   1. -postProcess on a finished case leaves particles.h5 as it was
#   2. a kill -9 at random moments (up to 6 times), each followed by a
#      restart from the latest time, ends in the uninterrupted run's final
#      state and HDF5 series, each record once and finite
#   3. a damaged particles.h5 is moved aside, the run starts
#   4. a diverging outer iteration stops with a message, exit status not 0,
#      nothing of the step written
#   5. physical input: deltaT 0, < 0 and 1e400, nu and U 1e400 (a clear error
#      under FOAM_SIGFPE, not a trap), endTime before the start, a
#      non-finite position, an empty list, a wrong count, a step that moves
#      a sphere by more than a mesh spacing where a step follows (deltaT 1,
#      endTime 2: nothing of it written; the same
#      deltaT with endTime 0, one solve and no step, runs), changed radii on
#      restart
# Checks in checkDataSafety.py.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir dataSafety)
failures=0
fail() { echo "  FAIL $*"; failures=$((failures + 1)); }

# Small sheared-sphere case: 6^3 box, 30^3 cells, 8 steps, written every 2
base="$work/base"
cloneCase shearedSphere "$base"
(
    cd "$base" || exit 1
    sed -i -e 's/^    (0 -5 0) .*$/    (0 -3 0) (6 -3 0) (6 3 0) (0 3 0)/' \
        -e 's/^    (0 -5 10) .*$/    (0 -3 6) (6 -3 6) (6 3 6) (0 3 6)/' \
        -e 's/(50 50 50)/(30 30 30)/' system/blockMeshDict
    sed -i 's/uniform (-5 0 0)/uniform (-3 0 0)/; s/uniform (5 0 0)/uniform (3 0 0)/' 0/U
    sed -i 's/^    (pushed (5.05 0.03 4.97) 1)/    (pushed (1.55 0.52 1.47) 1)\n    (pushed (4.45 0.03 4.51) 1)/' \
        constant/particleProperties
    foamDictionary -entry coupling.lambdaTolerance -set 1e-4 \
        constant/particleProperties > /dev/null
    foamDictionary -entry deltaT -set 0.05 system/controlDict > /dev/null
    foamDictionary -entry endTime -set 0.4 system/controlDict > /dev/null
    foamDictionary -entry writeInterval -set 2 system/controlDict > /dev/null
    foamDictionary -entry startFrom -set latestTime system/controlDict \
        > /dev/null
    runLogged blockMesh
) || exit 1

cp -r "$base" "$work/straight"
(cd "$work/straight" && runLogged fdmSuspensionFoam) || exit 1

# 1. -postProcess must not touch the series
(
    cd "$work/straight" || exit 1
    cp postProcessing/particles.h5 ../before.h5
    runLogged fdmSuspensionFoam -postProcess -latestTime || exit 1
    runLogged fdmSuspensionFoam -postProcess -time 0 || exit 1
    cmp -s postProcessing/particles.h5 ../before.h5
) || fail "-postProcess changed postProcessing/particles.h5"

# 2. Kill -9 at random moments, restart each time from the latest time
killed="$work/killed"
cp -r "$base" "$killed"
RANDOM=29
(
    cd "$killed" || exit 1
    for attempt in 1 2 3 4 5 6
    do
        fdmSuspensionFoam > "log.attempt$attempt" 2>&1 &
        pid=$!
        sleep "$((RANDOM % 4)).$((RANDOM % 10))"
        kill -9 "$pid" 2> /dev/null && echo "   killed attempt $attempt"
        wait "$pid" 2> /dev/null
    done
    runLogged fdmSuspensionFoam
) || fail "restart after kill -9 did not finish"

"$FDM_PYTHON" "$caseTemplates/checkDataSafety.py" "$work" \
    || fail "series or state after kills"

# 3. A damaged particles.h5 (garbage, as a kill of an older version left)
damaged="$work/damaged"
cp -r "$base" "$damaged"
mkdir -p "$damaged/postProcessing"
head -c 3000 /dev/urandom > "$damaged/postProcessing/particles.h5"
(cd "$damaged" && foamDictionary -entry endTime -set 0.1 system/controlDict \
    > /dev/null && runLogged fdmSuspensionFoam) \
    || fail "run with a damaged particles.h5"
[ -f "$damaged/postProcessing/particles.h5.unreadable" ] \
    || fail "damaged particles.h5 not kept aside"

# expectStopIn variant message edit-command...: the run must stop
expectStopIn()
{
    local variant=$1 message=$2
    shift 2
    local dir="$work/$variant"
    cp -r "$base" "$dir"
    (cd "$dir" && eval "$@") > /dev/null 2>&1
    expectStop "$dir" fdmSuspensionFoam "$message" || fail "$variant"
}

# 4. Divergence: the Couette tutorial's 25 spheres with U relaxation 0.99
#    and no acceleration diverge in the first solve
diverging="$work/diverging"
mkdir -p "$diverging"
cp -r "$FDM_PROJECT_DIR/tutorials/couette/"{0,constant,system} "$diverging"/
(
    cd "$diverging" || exit 1
    runLogged fdmPackParticles --box 8 8 8 --walls y --phi 0.3 --seed 1 \
        -o constant/particleList || exit 1
    runLogged blockMesh || exit 1
    sed -i 's/^\( *U  *\)0.9;/\1 0.99;/; s/acceleration .*;/acceleration none;/' \
        system/fvSolution
) || exit 1
expectStop "$diverging" fdmSuspensionFoam "outer iteration diverged" \
    || fail diverging
[ -z "$(ls -d "$diverging/"0.* 2> /dev/null)" ] \
    && [ ! -f "$diverging/0/particleState" ] \
    && [ ! -f "$diverging/postProcessing/particles.h5" ] \
    || fail "diverging run wrote a time or records"

# 5. Physical input
expectStopIn zeroDeltaT "allowed values are finite numbers > 0" \
    foamDictionary -entry deltaT -set 0 system/controlDict
expectStopIn negativeDeltaT "allowed values are finite numbers > 0" \
    foamDictionary -entry deltaT -set -0.05 system/controlDict
expectStopIn endBeforeStart "is before the start time" \
    foamDictionary -entry endTime -set -1 system/controlDict
expectStopIn hugeDeltaT "starting at keyword 'deltaT'" \
    "sed -i 's/^deltaT .*/deltaT 1e400;/' system/controlDict"
expectStopIn hugeViscosity "starting at keyword 'nu'" \
    "sed -i 's/^nu .*/nu 1e400;/' constant/transportProperties"
expectStopIn hugeVelocity "starting at keyword 'internalField'" \
    "sed -i 's/^internalField .*/internalField uniform (1e400 0 0);/' 0/U"
expectStopIn hugePosition "ill defined primitiveEntry starting at keyword 'particles'" \
    "sed -i 's/( 1.55 0.52 1.47 )/( 1e400 0.52 1.47 )/' constant/particleProperties"
expectStopIn emptyList "is empty" \
    "sed -i 's/^particles .*;/particles ();/' constant/particleProperties"
expectStopIn wrongCount "announces 3 particles but holds 2" \
    "sed -i 's/^particles *( (/particles 3( (/' constant/particleProperties"
# A step that would move a sphere by more than a mesh spacing (deltaT 1 on
# cells of 0.2, speeds of order 1) stops after the first solve, before
# anything of it is written
unresolved="$work/unresolvedStep"
expectStopIn unresolvedStep "mesh spacings) in one step" \
    "foamDictionary -entry deltaT -set 1 system/controlDict &&" \
    "foamDictionary -entry endTime -set 2 system/controlDict"
[ -z "$(ls -d "$unresolved/"0.* "$unresolved/"[1-9]* 2> /dev/null)" ] \
    && [ ! -f "$unresolved/0/particleState" ] \
    && [ ! -f "$unresolved/postProcessing/particles.h5" ] \
    || fail "unresolved step wrote a time or records"
# The same deltaT with endTime 0 is one steady solve that no step follows
# (subGridCalibration's and the validations' set-up): it runs and writes
# the record of that solve
single="$work/singleSolve"
cp -r "$base" "$single"
(
    cd "$single" || exit 1
    foamDictionary -entry deltaT -set 1 system/controlDict > /dev/null
    foamDictionary -entry endTime -set 0 system/controlDict > /dev/null
    runLogged fdmSuspensionFoam
) && [ -f "$single/postProcessing/particles.h5" ] \
    || fail "a single solve at endTime 0 with deltaT 1 stopped"
changed="$work/changedRadius"
cp -r "$work/straight" "$changed"
rm -rf "$changed/0.4"
sed -i 's/( 4.45 0.03 4.51 ) 1 )/( 4.45 0.03 4.51 ) 1.1 )/' \
    "$changed/constant/particleProperties"
expectStop "$changed" fdmSuspensionFoam \
    "differ from those of the run being continued" || fail changedRadius

[ "$failures" -eq 0 ]
