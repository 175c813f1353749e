#!/bin/bash
# Case test: rough contacts with a wall (thesis 1, section 2.6).  Three unit
# spheres pressed onto the bottom wall by W = 6 pi eta a^2: one at rest,
# one pushed along x by 0.3 W and one by 0.8 W (both without rotation), to
# time 2 with deltaT 0.05 (implicit contact stiffness).
# Checks in checkContactOnWall.py: normal force = W and the overlap of the
# contact law (eq 2.57, recomputed independently), sticking below and
# sliding at mu F_el above the Coulomb limit, a restart from t = 1 (slip
# history in particleState) reaching the same state and repeating the
# interrupted run's record at t = 1 (contact loads of the solved state,
# implicit share included; run with -quiet: one summary line per step
# whose contacts and smallest gap match the particles' file), a restart without its particleState stopping
# with a message, and the same run on 2
# MPI ranks cut through the middle sphere matching the serial one; the
# particles through ParaView's .foam reader at every written time (serial
# and decomposed, fdmPost.foamCloud); the VTK series with the contact
# network and particles.h5's attributes (fdmPost.particleFiles).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir contactOnWall)
cloneCase contactOnWall "$work/straight"
(
    cd "$work/straight" || exit 1
    runLogged blockMesh && runLogged fdmSuspensionFoam || exit 1
    # Restart from the state written at t = 1
    mkdir ../restart
    cp -r 0 1 constant system ../restart/
    cd ../restart || exit 1
    rm -rf 1/uniform
    foamDictionary -entry startFrom -set latestTime system/controlDict \
        > /dev/null
    runLogged fdmSuspensionFoam -quiet
    # The same restart without the particle state, asked for explicitly
    # (startTime 1), must stop, not go on from the initial positions; with
    # latestTime the time is incomplete: set aside, the run starts at 0
    mkdir ../noState
    cp -r 0 1 constant system ../noState/
    rm ../noState/1/particleState
    cp -r ../noState ../noStateLatest
    foamDictionary -entry startFrom -set startTime ../noState/system/controlDict \
        > /dev/null
    foamDictionary -entry startTime -set 1 ../noState/system/controlDict \
        > /dev/null
) || exit 1
expectStop "$work/noState" fdmSuspensionFoam 'particleState" is missing' \
    || exit 1
(
    cd "$work/noStateLatest" || exit 1
    foamDictionary -entry endTime -set 0 system/controlDict > /dev/null
    runLogged fdmSuspensionFoam || exit 1
    [ -d 1.incomplete ] && grep -q "was not completely written" \
        log.fdmSuspensionFoam
) || { echo "FAILED: incomplete time 1 not set aside"; exit 1; }
echo "   noStateLatest: time 1 set aside as 1.incomplete, started at 0"
cloneCase contactOnWall "$work/parallel"
runDecomposed "$work/parallel" || exit 1

# ParaView's .foam reader (vtkPOpenFOAMReader) on the serial and the
# decomposed run: the particles with their fields at every written time
touch "$work/straight/case.foam" "$work/parallel/case.foam"
"$FDM_PYTHON" "$caseTemplates/checkContactOnWall.py" "$work" || exit 1

# The VTK series (from t = 0, each particle once, the contact lines adding
# up to each particle's contact force) and the self-describing particles.h5
# with its XDMF companion, serial and decomposed (fdmPost.particleFiles)
for run in straight parallel
do
    echo "   $run run, VTK and HDF5 files:"
    out=$("$FDM_PYTHON" -m fdmPost.particleFiles "$work/$run" \
        --contact-balance); rc=$?
    echo "$out" | sed 's/^/   /'
    [ $rc -eq 0 ] || exit 1
    [ -f "$work/$run/VTK/particles_0.vtp" ] \
        || { echo "FAILED: no VTK file at t = 0"; exit 1; }
done
