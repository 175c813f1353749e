#!/bin/bash
# Case test: SIMPLEC RhieChowFactor makes the converged solution independent
# of the U under-relaxation.  One held sphere driven by grad P0 in a
# periodic cube L = 4a (Delta = a/5), Anderson to lambda residual 1e-9,
# linear solvers to 1e-12:
#  - relaxation 0.9 (thesis scheme: the Rhie-Chow coefficient of the
#    converged face flux is the relaxed 1/a_C, 0.9/a_C);
#  - relaxation 0.97 with RhieChowFactor 0.9: must agree with the first to
#    1e-7 in the mean velocity (the drag coefficient K), the torque and the
#    stresslet (measured: 1e-9);
#  - relaxation 0.97 without it: must differ from the first by more than
#    1e-5 (measured: 3.6e-4 in K), so that the comparison can fail;
#  - relaxation 0.9 without the momentum predictor (SIMPLEC
#    momentumPredictor off), to lambda residual 1e-10 (stopped at 1e-9 it
#    is 4e-8 from the first): the same fixed point, within 1e-7 of the
#    first (measured: 3.3e-9).
source "${0%/*}/caseTestFunctions"
source "$caseTemplates/periodicArraySetup"

work=$(caseWorkDir RhieChowFactor)
for name in relax0.9 relax0.97 relax0.97fixed noPredictor
do
    tol=1e-9
    [ "$name" = noPredictor ] && tol=1e-10
    periodicArrayCase "$work/$name" 4 2.125 2.175 2.075 $tol 3000 || exit 1
    tightenAndAccelerate "$work/$name" 1e-12 || exit 1
done
for name in relax0.97 relax0.97fixed
do
    foamDictionary -entry relaxationFactors.equations.U -set 0.97 \
        "$work/$name/system/fvSolution" > /dev/null || exit 1
done
foamDictionary -entry SIMPLEC.RhieChowFactor -add 0.9 \
    "$work/relax0.97fixed/system/fvSolution" > /dev/null || exit 1
foamDictionary -entry SIMPLEC.momentumPredictor -add off \
    "$work/noPredictor/system/fvSolution" > /dev/null || exit 1

for name in relax0.9 relax0.97 relax0.97fixed noPredictor
do
    (
        cd "$work/$name" || exit 1
        runLogged blockMesh && runLogged fdmSuspensionFoam
    ) || exit 1
done

"$FDM_PYTHON" "$caseTemplates/checkRhieChowFactor.py" "$work"
