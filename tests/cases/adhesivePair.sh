#!/bin/bash
# Case test (adhesive contacts, thesis 1, chapter 5): two unit spheres in
# contact with the adhesive force F_adh = 6 pi eta a^2 (1/s)
# (adhesiveHertz, eq 5.1), in simple shear (walls at y = 0 and 6 moving at
# -+3: gammaDot = 1) with their line of centres along the vorticity z at
# mid-height, pulled apart along it by external forces of 0.9 F_adh and
# 1.1 F_adh, to time 2 with deltaT 0.05.  Along the vorticity the shear
# flow moves the two spheres neither apart nor together (E_zz = 0) and
# spins them alike about their line of centres, so the pull-off is the
# contact law's own.  Checks in checkAdhesivePair.py: below the pull-off
# force (F_adh, where the elastic force vanishes at the edge of the
# contact) the pair stays bonded, the contact holding the load at the
# overlap where F_el - F_adh balances it, while the flow turns it at
# -gammaDot/2; above it the pair separates.
# The bonded pair (0.9 F_adh) also runs on 2 ranks cut at z = 3 through the
# contact, to time 1, the particle system solved by subdomain
# (parallelParticleSolve distributed: each rank solves one sphere's rows,
# the other its ghost): its contact, sub-grid and FDM loads are compared
# with the serial run's.  Both solve the coupling to a lambda residual of
# 1e-5 (1e-3 for the separating pair), so that they stop close to the same
# state.
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
        foamDictionary -entry groups.left.force -set "(0 0 -$F)" \
            constant/particleProperties > /dev/null
        foamDictionary -entry groups.right.force -set "(0 0 $F)" \
            constant/particleProperties > /dev/null
        foamDictionary -entry boundaryField.floor.value \
            -set "uniform (-3 0 0)" 0/U > /dev/null
        foamDictionary -entry boundaryField.lid.value \
            -set "uniform (3 0 0)" 0/U > /dev/null
    ) || exit 1
done
foamDictionary -entry coupling.lambdaTolerance -set 1e-5 \
    "$work/load0.9/constant/particleProperties" > /dev/null || exit 1
twoRanks="$work/load0.9.2ranks"
mkdir -p "$twoRanks"
cp -r "$work/load0.9"/{0,constant,system} "$twoRanks"/
cp "$caseTemplates/adhesivePair/system/decomposeParDict" "$twoRanks/system/"
for entry in "endTime 1" "writeInterval 20"
do
    foamDictionary -entry ${entry% *} -set ${entry#* } \
        "$twoRanks/system/controlDict" > /dev/null || exit 1
done

for load in 0.9 1.1
do
    (
        cd "$work/load$load" || exit 1
        runLogged blockMesh && runLogged fdmSuspensionFoam
    ) || exit 1
done
runBySubdomain "$twoRanks" || exit 1
"$FDM_PYTHON" "$caseTemplates/checkAdhesivePair.py" "$work"
