#!/bin/bash
# Case test: bad input stops the solver with a message naming the file and
# the keyword.  Each variant starts from a valid case: planeChannel for the
# flow dictionaries, shearedSphere for the particle input.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir badInput)
for template in planeChannel shearedSphere
do
    cloneCase "$template" "$work/mesh-$template"
    ( cd "$work/mesh-$template" && runLogged blockMesh ) || exit 1
done

failures=0

# expectFatal variant file sed-expression keyword...   (uses $template)
expectFatal()
{
    local variant=$1 file=$2 edit=$3
    shift 3
    local dir="$work/$variant"
    cloneCase "$template" "$dir"
    cp -r "$work/mesh-$template/constant/polyMesh" "$dir/constant/"
    sed -i "$edit" "$dir/$file"
    expectFatalRun "$dir" fdmSuspensionFoam "$variant" "$file" "$@" \
        || failures=$((failures + 1))
}

template=planeChannel
expectFatal misspeltMeanPressureGradient constant/flowProperties \
    's/meanPressureGradient/meanPresureGradient/' meanPressureGradient
expectFatal missingViscosity constant/transportProperties \
    's/^nu .*$//' "'nu'"
expectFatal missingCorrectors system/fvSolution \
    's/nCorrectors .*$//' nCorrectors
expectFatal negativeCorrectors system/fvSolution \
    's/nCorrectors .*$/nCorrectors -1;/' nCorrectors ">= 1"
expectFatal negativeCorrectorsBetweenRecords system/fvSolution \
    's/^ *nCorrectors .*$/&\n    nCorrectorsBetweenRecords 0;/' \
    "nCorrectorsBetweenRecords 0" ">= 1"
expectFatal misspeltBetweenRecordsSolver system/fvSolution \
    's/^    U$/    UBetweenRecord { solver PCG; preconditioner DIC; tolerance 1e-8; relTol 0; }\n&/' \
    "Unknown solver 'UBetweenRecord'" "nearest valid spelling: 'UBetweenRecords'"
expectFatal missingRelaxation system/fvSolution \
    's/U               0.9;//' relaxationFactors "0 < U < 1"
expectFatal unknownAcceleration system/fvSolution \
    's/^ *nCorrectors .*$/&\n    acceleration fast;/' "acceleration fast" \
    "none (thesis outer iteration) and anderson"
expectFatal smallLayerMeanViscosity system/fvSolution \
    's/^ *nCorrectors .*$/&\n    layerMeanCorrection on; layerMeanViscosityRatio 0.5;/' \
    "layerMeanViscosityRatio 0.5" "finite numbers >= 1"
expectFatal largeRhieChowFactor system/fvSolution \
    's/^ *nCorrectors .*$/&\n    RhieChowFactor 1.5;/' \
    "RhieChowFactor 1.5" "0 < RhieChowFactor <= 1"
expectFatal misspeltSimplecKey system/fvSolution \
    's/nOuterCorrectors/nOuterCorrector/' "Unknown keyword 'nOuterCorrector'" \
    "nearest valid spelling: 'nOuterCorrectors'"
expectFatal unknownFlowKey constant/flowProperties \
    '$a meanPressureGradent (0 0 0);' "Unknown keyword 'meanPressureGradent'" \
    "nearest valid spelling: 'meanPressureGradient'"
expectFatal unknownTransportKey constant/transportProperties \
    '$a nu2 1;' "Unknown keyword 'nu2'" "nearest valid spelling: 'nu'"
expectFatal stressFunctionKey system/controlDict \
    '$a functions { stress { type suspensionStress; libs ("libfdmParticles.so"); walLayer 1; } }' \
    "Unknown keyword 'walLayer'" "nearest valid spelling: 'wallLayer'"

template=shearedSphere
pp=constant/particleProperties
expectFatal overlappingParticles $pp \
    's/^    (pushed (5.05 0.03 4.97) 1)/&\n    (pushed (5.05 1.9 4.97) 1)/' \
    overlapping "particles 0"
expectFatal particleOutsideDomain $pp 's/(5.05 0.03 4.97)/(5.05 4.5 4.97)/' \
    "Particle 0" "not inside the domain" "within [-4"
expectFatal meshTooCoarse $pp 's/(5.05 0.03 4.97) 1)/(5.05 0.03 4.97) 0.3)/' \
    "too coarse" "1.5 cells"
expectFatal unknownGroup $pp 's/(pushed (5.05/(pulled (5.05/' \
    "group pulled" "defined groups"
expectFatal badTranslation $pp 's/force (0 0 18.85);/translation moving;/' \
    translation "free, fixed or a velocity vector"
expectFatal unknownGroupKeyword $pp 's/force (0 0 18.85);/forse (0 0 1);/' \
    "Unknown keyword 'forse'" "nearest valid spelling: 'force'" \
    "allowed keywords"
expectFatal missingLambdaTolerance $pp 's/lambdaTolerance .*;//' \
    "'lambdaTolerance'"
expectFatal tightBetweenRecords $pp \
    's/^ *lambdaTolerance .*;/&\n    lambdaToleranceBetweenRecords 1e-7;/' \
    "allowed values are lambdaToleranceBetweenRecords >=" \
    "at least lambdaTolerance"
expectFatal missingFluidDensity constant/transportProperties 's/^rho .*$//' \
    "'rho'"
expectFatal unknownSubGridModel $pp '$a subGrid { model fancy; }' \
    "Unknown subGrid model 'fancy'" "frameInvariant" "none"
expectFatal missingSubGridTable $pp \
    '$a subGrid { model frameInvariant; pairTables ("noSuchTable"); }' \
    "Cannot read the sub-grid table" "noSuchTable" "subGridCalibration"
expectFatal subGridTableOtherSettings $pp \
    '$a indicator { b 4; } subGrid { model frameInvariant; }' \
    "subGridPair_lambda1" "b = 5" "b = 4" "subGridCalibration"
expectFatal badGapFloor $pp '$a gapFloor 0;' "gapFloor" "0 < gapFloor < 0.1"
expectFatal unknownContactModel $pp \
    '$a contact { model sticky; roughness 5e-3; friction 0.5; kn 1e4; }' \
    "Unknown contact model 'sticky'" "adhesiveHertz" "hertz"
expectFatal contactStiffnessTwice $pp \
    '$a contact { roughness 5e-3; friction 0.5; kn 1e4; shearRate 1; meanDeformation 0.2; }' \
    "contact" "either as kn" "not both"
expectFatal contactRoughTooLarge $pp \
    '$a contact { roughness 0.5; friction 0.5; kn 1e4; }' \
    "roughness 0.5" "0 < roughness < 0.1"
# Misspelt optional blocks and keywords: each once (a run without them
# would go on without lubrication, contacts or gravity)
expectFatal misspeltSubGrid $pp '$a subgrid { model frameInvariant; }' \
    "Unknown keyword 'subgrid'" "nearest valid spelling: 'subGrid'"
expectFatal misspeltContact $pp \
    '$a contacts { roughness 5e-3; friction 0.5; kn 1e4; }' \
    "Unknown keyword 'contacts'" "nearest valid spelling: 'contact'"
expectFatal misspeltGravity $pp '$a gravty (0 -1 0);' \
    "Unknown keyword 'gravty'" "nearest valid spelling: 'gravity'"
expectFatal misspeltCouplingKey $pp \
    's/particleSolveTolerance/particleSolveTol/' \
    "Unknown keyword 'particleSolveTol'" \
    "nearest valid spelling: 'particleSolveTolerance'"
expectFatal misspeltContactKey $pp \
    '$a contact { roughness 5e-3; frictoin 0.5; kn 1e4; }' \
    "Unknown keyword 'frictoin'" "nearest valid spelling: 'friction'"
expectFatal misspeltSubGridKey $pp \
    '$a subGrid { model frameInvariant; wall false; }' \
    "Unknown keyword 'wall'" "nearest valid spelling: 'walls'"
expectFatal misspeltIndicatorKey $pp '$a indicator { bb 5; }' \
    "Unknown keyword 'bb'" "nearest valid spelling: 'b'"
expectFatal misspeltOutputKey $pp '$a output { timeSeriesIntervall 2; }' \
    "Unknown keyword 'timeSeriesIntervall'"
expectFatal missingHeader $pp '/^FoamFile/,/^}/d' "needs the FoamFile header"
expectFatal stressFunctionAxis system/controlDict \
    '$a functions { stress { type suspensionStress; libs ("libfdmParticles.so"); normal w; } }' \
    "keyword normal is w" "allowed: x, y, z"
expectFatal stressFunctionLayer system/controlDict \
    '$a functions { stress { type suspensionStress; libs ("libfdmParticles.so"); wallLayer 6; } }' \
    "keyword wallLayer is 6" "0 <= wallLayer < half the channel height"

[ "$failures" -eq 0 ]
