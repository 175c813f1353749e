#!/bin/bash
# Case test (adhesive contacts, thesis 1, chapter 5): two unit spheres in
# contact in quiescent fluid with the adhesive force F_adh = 6 pi eta a^2
# (1/s) (adhesiveHertz, eq 5.1), pulled apart along their line of centres
# by external forces of 0.9 F_adh and 1.1 F_adh, to time 2 with deltaT 0.05.
# Checks in checkAdhesivePair.py: below the pull-off force (F_adh, where
# the elastic force vanishes at the edge of the contact) the pair stays
# bonded at rest, the contact holding the load at the overlap where
# F_el - F_adh balances it; above it the pair separates.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir adhesivePair)
for load in 0.9 1.1
do
    # The settlingOnFloor case (box, walls, solvers) with this test's
    # particles and contact law, to time 2 in steps of 0.05
    cloneCase settlingOnFloor "$work/load$load"
    cp "$caseTemplates/adhesivePair/constant/particleProperties" \
        "$work/load$load/constant/"
    (
        cd "$work/load$load" || exit 1
        for entry in "endTime 2" "deltaT 0.05" "writeInterval 40"
        do
            foamDictionary -entry ${entry% *} -set ${entry#* } \
                system/controlDict > /dev/null
        done
        F=$(awk -v f="$load" 'BEGIN { printf "%.10g", f*6*atan2(0, -1) }')
        foamDictionary -entry groups.left.force -set "(-$F 0 0)" \
            constant/particleProperties > /dev/null
        foamDictionary -entry groups.right.force -set "($F 0 0)" \
            constant/particleProperties > /dev/null
        runLogged blockMesh && runLogged fdmSuspensionFoam
    ) || exit 1
done
"$FDM_PYTHON" "$caseTemplates/checkAdhesivePair.py" "$work"
