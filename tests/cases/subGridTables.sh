#!/bin/bash
# Case test: every shipped sub-grid table is what subGridCalibration's table
# step makes from the measurement kept beside it (data/resistance/measured),
# at every mesh spacing (Delta = a1/5, a1/4 and a1/6): the tables are reproducible
# from the repository alone, and a change of the tool or of a table that
# breaks that is caught.  Compared line by line except the FoamFile header
# (which names the file).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir subGridTables)
tool="$FDM_PROJECT_DIR/applications/utilities/subGridCalibration/subGridCalibration"
data="$FDM_PROJECT_DIR/data/resistance"
failures=0
# table kind measurement theory
while read -r table kind measured theory
do
    if ! "$FDM_PYTHON" "$tool" table --kind "$kind" \
        --measured "$data/measured/$measured" --theory "$data/$theory" \
        --out "$work/$table" > "$work/log.$table" 2>&1
    then
        echo "FAILED: $table: the table step stopped (log.$table)"
        failures=$((failures + 1))
    elif ! diff -q <(tail -n +2 "$work/$table") <(tail -n +2 "$data/$table") \
        > /dev/null
    then
        echo "FAILED: $table differs from what $measured makes"
        failures=$((failures + 1))
    else
        echo "  ok   $table from measured/$measured"
    fi
done << 'TABLES'
subGridPair_lambda1 pair pairL10.dat twoSphereTheory_lambda1
subGridPair_lambda1.4 pair pair14L10.dat twoSphereTheory_lambda1.4
subGridWall wall wallL10.dat wallTheory
subGridPair_lambda1_Delta0.25 pair pairL10_Delta0.25.dat twoSphereTheory_lambda1
subGridPair_lambda1.4_Delta0.25 pair pair14L10_Delta0.25.dat twoSphereTheory_lambda1.4
subGridWall_Delta0.25 wall wallL10_Delta0.25.dat wallTheory
subGridPair_lambda1_Delta0.1667 pair pairL8_Delta0.1667.dat twoSphereTheory_lambda1
subGridPair_lambda1.4_Delta0.1667 pair pair14L8_Delta0.1667.dat twoSphereTheory_lambda1.4
subGridWall_Delta0.1667 wall wallL8_Delta0.1667.dat wallTheory
TABLES
[ "$failures" -eq 0 ]
