#!/bin/bash
# Case test: bad input stops the solver with a message naming the file and
# the keyword.  Each variant starts from the valid planeChannel case.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir badInput)
cloneCase planeChannel "$work/mesh"
( cd "$work/mesh" && runLogged blockMesh ) || exit 1

failures=0

# expectFatal variant file sed-expression keyword...
expectFatal()
{
    local variant=$1 file=$2 edit=$3
    shift 3
    local dir="$work/$variant"
    cloneCase planeChannel "$dir"
    cp -r "$work/mesh/constant/polyMesh" "$dir/constant/"
    sed -i "$edit" "$dir/$file"

    if (cd "$dir" && fdmSuspensionFoam > log.fdmSuspensionFoam 2>&1)
    then
        echo "  FAIL $variant: solver accepted the bad input"
        failures=$((failures + 1))
        return
    fi
    local expected
    for expected in "$file" "$@"
    do
        if ! grep -q -- "$expected" "$dir/log.fdmSuspensionFoam"
        then
            echo "  FAIL $variant: message does not name '$expected'"
            tail -n 12 "$dir/log.fdmSuspensionFoam"
            failures=$((failures + 1))
            return
        fi
    done
    echo "  ok   $variant: stops naming $file and $*"
}

expectFatal misspeltMeanPressureGradient constant/flowProperties \
    's/meanPressureGradient/meanPresureGradient/' meanPressureGradient
expectFatal missingViscosity constant/transportProperties \
    's/^nu .*$//' "'nu'"
expectFatal missingCorrectors system/fvSolution \
    's/nCorrectors .*$//' nCorrectors
expectFatal negativeCorrectors system/fvSolution \
    's/nCorrectors .*$/nCorrectors -1;/' nCorrectors ">= 1"
expectFatal missingRelaxation system/fvSolution \
    's/U               0.9;//' relaxationFactors "0 < U < 1"

[ "$failures" -eq 0 ]
