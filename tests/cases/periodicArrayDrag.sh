#!/bin/bash
# Case test (reduced Hasimoto validation, thesis 1 section 4.1.1): one
# sphere in a periodic cube L = 8a, Delta = a/5, at one position in a cell.
#  - held sphere driven by grad P0 with the thesis' outer iteration and
#    tolerances (lambda residual 1e-6)
#  - the same with the Anderson-accelerated outer iteration converged to
#    1e-8
#  - the same sphere shifted by half the box (20 cells) to x = 0.125, so
#    that its support crosses the cyclic patch: serial and on 2 MPI ranks
#    (there it also straddles the processor boundary, a processorCyclic
#    patch)
#  - the same sphere settling under gravity, free, in the solver-balanced
#    periodic box (accelerated)
# Checks in checkPeriodicArray.py.
source "${0%/*}/caseTestFunctions"
source "$caseTemplates/periodicArraySetup"

work=$(caseWorkDir periodicArrayDrag)
# Cell centre 4.1 plus offsets (1/8, 3/8, -1/8) Delta
periodicArrayCase "$work/held" 8 4.125 4.175 4.075 1e-6 8000 || exit 1
periodicArrayCase "$work/accelerated" 8 4.125 4.175 4.075 1e-8 2000 \
    || exit 1
periodicArrayCase "$work/wrapped" 8 0.125 4.175 4.075 1e-8 2000 || exit 1
periodicArrayCase "$work/settling" 8 4.125 4.175 4.075 1e-8 2000 settling \
    || exit 1
for name in accelerated wrapped settling
do
    tightenAndAccelerate "$work/$name" 1e-9 || exit 1
done

for name in held accelerated settling
do
    (
        cd "$work/$name" || exit 1
        runLogged blockMesh && runLogged fdmSuspensionFoam
    ) || exit 1
done
runSerialAndParallel "$work/wrapped" || exit 1

"$FDM_PYTHON" "$caseTemplates/checkPeriodicArray.py" "$work"
