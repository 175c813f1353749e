#!/bin/bash
# Case test: bad input to lubricatedDEMFoam and to the utilities
# (fdmPackParticles, fdmSuspensionBalance, subGridCalibration) stops with a message naming the
# file and the keyword or option, exit status non-zero, before anything is
# written.  Each solver variant edits a valid small case (the
# lubricatedShear tutorial in a 13^3 cell, 0.001 strain).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir badInputDEM)
base="$work/base"
mkdir -p "$base"
cp -r "$FDM_PROJECT_DIR/tutorials/lubricatedShear"/{system,constant} "$base"/
sed -i 's/(16 16 16)/(13 13 13)/' "$base/constant/particleProperties"
sed -i -e 's/^endTime .*/endTime 0.001;/' -e 's/^writeInterval .*/writeInterval 1;/' \
    "$base/system/controlDict"
(cd "$base" && runLogged fdmPackParticles --box 13 13 13 --walls '' \
    --phi 0.3 --seed 2 -o constant/particleList) || exit 1
(cd "$base" && runLogged lubricatedDEMFoam) || exit 1
rm -rf "$base/postProcessing" "$base/log.lubricatedDEMFoam"

failures=0
pp=constant/particleProperties
list=constant/particleList

# expectFatal variant file sed-expression message...   (the messages must
# name the file at fault, which is not always the one edited)
expectFatal()
{
    local variant=$1 file=$2 edit=$3
    shift 3
    local dir="$work/$variant"
    cp -r "${from:-$base}" "$dir"
    sed -i "$edit" "$dir/$file"
    expectFatalRun "$dir" lubricatedDEMFoam "$variant" "$@" \
        || failures=$((failures + 1))
}

# The first row of the list: (suspended (x y z) a)
row1='0,/^(suspended/s/^(suspended (\([^)]*\)) \(.*\))$/'
expectFatal zeroRadius $list "${row1}(suspended (\1) 0)/" \
    particleList "has radius 0" "allowed values are > 0"
expectFatal negativeRadius $list "${row1}(suspended (\1) -1)/" \
    particleList "has radius -1" "allowed values are > 0"
expectFatal emptyList $list '/^[0-9][0-9]*$/,$c 0\n(\n)' particleList "is empty"
# (the count line removed: it is optional)
expectFatal repeatedRow $list '/^[0-9][0-9]*$/d; 0,/^(suspended/{/^(suspended/p}' \
    particleList "overlapping particle pair" "the same row twice"
expectFatal overlapping $list \
    '/^[0-9][0-9]*$/d; 0,/^(suspended/s/^(suspended .*$/(suspended (6.5 6.5 6.5) 1)\n(suspended (7.5 6.5 6.5) 1)/' \
    particleList "overlapping particle pair" "centre distance"
expectFatal countMismatch $list 's/^\([0-9][0-9]*\)$/1\1/' \
    particleList "announces" "rows"
expectFatal hugeNumber $list "${row1}(suspended (1e400 1 1) \2)/" \
    particleList "could not get scalar value"
expectFatal outsideOpenCell $pp 's/shearRate   1;/&\n    open (y);/' \
    particleList "not inside the domain" "along direction y"
expectFatal hugeTimeStep system/controlDict 's/^deltaT .*/deltaT 1e400;/' \
    controlDict "starting at keyword 'deltaT'"
expectFatal zeroTimeStep system/controlDict 's/^deltaT .*/deltaT 0;/' \
    controlDict "deltaT"
expectFatal negativeEnd system/controlDict 's/^endTime .*/endTime -1;/' \
    controlDict "endTime"
expectFatal missingHeader $pp '/^FoamFile/,/^}/d' particleProperties "needs the FoamFile header"
expectFatal misspeltTopLevel $pp 's/^density /densty /' \
    particleProperties "Unknown keyword 'densty'" "nearest valid spelling: 'density'"
expectFatal misspeltBlock $pp 's/^output/outputs/' \
    particleProperties "Unknown keyword 'outputs'" "nearest valid spelling: 'output'"
expectFatal misspeltCellKey $pp 's/shearRate   1;/shearrate 1;/' \
    particleProperties "Unknown keyword 'shearrate'" "nearest valid spelling: 'shearRate'"
expectFatal misspeltContactKey $pp 's/friction   /frictoin   /' \
    particleProperties "Unknown keyword 'frictoin'" "nearest valid spelling: 'friction'"
expectFatal zeroInterval $pp 's/interval    100;/interval 0;/' \
    particleProperties "interval" "steps between time-series rows"
expectFatal misspeltNeighbours $pp 's/^output/neighbours { selection delauney; }\noutput/' \
    particleProperties "delauney" "nearest valid spelling: 'delaunay'"
expectFatal intervalWithCutoff $pp 's/^output/neighbours { selection cutoff; interval 5; }\noutput/' \
    particleProperties "interval" "selection delaunay only"
expectFatal zeroDelaunayInterval $pp 's/^output/neighbours { selection delaunay; interval 0; }\noutput/' \
    particleProperties "interval" "steps between Delaunay triangulations"
expectFatal trackMissing $pp 's/interval    100;/& track (5000);/' \
    particleProperties "particle 5000 does not exist"

# Restarts: a run written to 0.002, then a newest time 0.003 holding only
# the temporary file of a killed particleState write: set aside, the run
# continues from 0.002
restart="$work/restart"
cp -r "$base" "$restart"
sed -i -e 's/^endTime .*/endTime 0.002;/' -e 's/^writeInterval .*/writeInterval 0.001;/' \
    "$restart/system/controlDict"
(cd "$restart" && runLogged lubricatedDEMFoam) || exit 1
mkdir "$restart/0.003"
echo "(suspended (1 2" > "$restart/0.003/particleState.tmp"
sed -i 's/^endTime .*/endTime 0.004;/' "$restart/system/controlDict"
(cd "$restart" && mv log.lubricatedDEMFoam log.first \
    && runLogged lubricatedDEMFoam) || exit 1
if grep -q "Time 0.003 was not completely written" \
        "$restart/log.lubricatedDEMFoam" \
    && grep -q "Continuing from .*0.002/particleState" \
        "$restart/log.lubricatedDEMFoam" \
    && [ -d "$restart/0.003.incomplete" ] \
    && [ -f "$restart/0.004/particleState" ]
then
    echo "  ok   halfWrittenTime: 0.003 set aside, continued from 0.002"
else
    echo "  FAIL halfWrittenTime: not set aside, or no restart from 0.002"
    failures=$((failures + 1))
fi
rm -rf "$restart/0.004"
# Asked to start at 0.002 whose particleState is gone: stops (rather than
# restart from the list's positions)
noState="$work/restartWithoutState"
cp -r "$restart" "$noState"
rm "$noState/0.002/particleState"
sed -i -e 's/^startFrom .*/startFrom startTime;/' -e 's/^startTime .*/startTime 0.002;/' \
    "$noState/system/controlDict"
if ! (cd "$noState" && lubricatedDEMFoam > log.lubricatedDEMFoam 2>&1) \
    && grep -q '0.002/particleState" is missing' \
        "$noState/log.lubricatedDEMFoam"
then
    echo "  ok   restartWithoutState: stops, the state is missing"
else
    echo "  FAIL restartWithoutState: ran from the list's positions"
    failures=$((failures + 1))
fi
from=$restart expectFatal restartChangedRadius $list "${row1}(suspended (\1) 1.01)/" \
    particleState "particle 0 has radius 1 but the particle list gives 1.01"

# Utilities: refused with the option and what is allowed, without a
# traceback and without output ($out: where the variant asks it written)
expectRefused()
{
    local variant=$1 message=$2 utility=$3
    shift 3
    if "$utility" "$@" > "$work/$variant.log" 2>&1
    then
        echo "  FAIL $variant: $utility accepted $*"
        failures=$((failures + 1))
    elif ! grep -qF -- "$message" "$work/$variant.log" \
        || grep -q Traceback "$work/$variant.log" || ls "$out"* > /dev/null 2>&1
    then
        echo "  FAIL $variant: no '$message', a traceback, or output written"
        tail -n 5 "$work/$variant.log"
        failures=$((failures + 1))
    else
        echo "  ok   $variant: $utility refused: $message"
    fi
}
out=$work/utilities/out
mkdir -p "$work/utilities"
expectRefused packNegativeGap "--gap -1" fdmPackParticles \
    --box 8 8 8 --phi 0.3 --gap -1 -o "$out"
expectRefused packUnreachablePhi "give 0.2681" fdmPackParticles \
    --box 2.5 2.5 2.5 --phi 0.5 -o "$out"
expectRefused packZeroRadius "--radius 0" fdmPackParticles \
    --box 8 8 8 --phi 0.3 --radius 0 -o "$out"
expectRefused sbmJammingAboveDensest "--phij 1.5" fdmSuspensionBalance \
    poiseuille --phi0 0.3 --phij 1.5 -o "$out"
expectRefused sbmZeroWidth "--width 0" fdmSuspensionBalance \
    poiseuille --phi0 0.3 --width 0 --times 100 -o "$out"
expectRefused sbmZeroShields "Shields numbers must be > 0" \
    fdmSuspensionBalance resuspension --sh 0 --volume 8 -o "$out"
expectRefused sbmNegativeVolume "--volume -1" fdmSuspensionBalance \
    resuspension --sh 1 --volume -1 -o "$out"
expectRefused calibrationZeroRatio "--ratio 0: allowed > 0" \
    subGridCalibration run --kind pair --ratio 0 --work "$out"
expectRefused calibrationNegativeGap "--gaps 0.1,-1" \
    subGridCalibration run --kind pair --gaps 0.1,-1 --work "$out"
echo "a table" > "$work/utilities/table.dat"
expectRefused calibrationTableExists "table.dat exists" \
    subGridCalibration table --kind pair --measured m --theory t \
    --out "$work/utilities/table.dat"
grep -qx "a table" "$work/utilities/table.dat" \
    || { echo "  FAIL calibrationTableExists: the table was changed"; \
         failures=$((failures + 1)); }

[ "$failures" -eq 0 ]
