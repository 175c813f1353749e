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
# The tumbling doublet runs on 2 ranks, the particle system solved by
# subdomain (parallelParticleSolve distributed): the bonded pair without the
# pull and with ten times the adhesion, its line of centres at 135 degrees
# in the shear plane, centred at (4.35, 3, 2) in a box of 8 x 6 x 4 cut at
# x = 4, to time 2.  The flow turns it by about 80 degrees: sphere 0 crosses
# to rank 1 first, then both are on rank 1 (rank 0 holds no particle of the
# pair, nor its contact), then sphere 1 crosses to rank 0 with a tangential
# contact force about a third of the normal one, which rank 0 must take
# over with the contact's accumulated slip.  Its positions, velocities and
# FDM, sub-grid and contact loads are compared with the serial run's.  Both
# solve the coupling to a lambda residual of 1e-4 (1e-5 for load0.9, 1e-3
# for load1.1), so that they stop close to the same state.  The 2-rank
# run's state at time 1, continued in serial to time 2 (a restart from
# another decomposition, the contact's slip read back), must follow the
# serial run record by record.
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

tumbling="$work/tumbling"
cp -r "$work/load0.9" "$tumbling"
cp "$caseTemplates/adhesivePair/tumbling/system/"* "$tumbling/system/"
(
    cd "$tumbling" || exit 1
    for entry in "contact.adhesionForce 188.5" "groups.left.force (0 0 0)" \
        "groups.right.force (0 0 0)" "coupling.lambdaTolerance 1e-4" \
        "particles ((left (3.6415 3.7085 2) 1) (right (5.0585 2.2915 2) 1))"
    do
        foamDictionary -entry "${entry%% *}" -set "${entry#* }" \
            constant/particleProperties > /dev/null || exit 1
    done
) || exit 1
mkdir -p "$tumbling.2ranks"
cp -r "$tumbling"/{0,constant,system} "$tumbling.2ranks"/
foamDictionary -entry writeInterval -set 20 \
    "$tumbling.2ranks/system/controlDict" > /dev/null || exit 1

for run in load0.9 load1.1 tumbling
do
    (
        cd "$work/$run" || exit 1
        runLogged blockMesh && runLogged fdmSuspensionFoam
    ) || exit 1
done
runBySubdomain "$tumbling.2ranks" || exit 1
# Restart from another decomposition: the 2-rank state of time 1 (the
# contact history with it) continued serially to time 2
(
    cd "$tumbling.2ranks" && runLogged reconstructPar -time 1 || exit 1
    mkdir -p "$tumbling.restart" || exit 1
    cp -r "$tumbling"/{constant,system} 1 "$tumbling.restart"/ || exit 1
    cd "$tumbling.restart" || exit 1
    foamDictionary -entry startFrom -set latestTime system/controlDict \
        > /dev/null && runLogged fdmSuspensionFoam
) || exit 1
"$FDM_PYTHON" "$caseTemplates/checkAdhesivePair.py" "$work"
