#!/bin/bash
# Case test (reduced Hasimoto validation, thesis 1 section 4.1.1): one
# sphere in a periodic cube L = 8a, Delta = a/5, at one position in a cell.
#  - held sphere driven by grad P0: serial and 2 MPI ranks (the sphere
#    straddles the processor boundary at x = 4)
#  - the same sphere settling under gravity, free, in the solver-balanced
#    periodic box
# Checks in checkPeriodicArray.py.
source "${0%/*}/caseTestFunctions"
source "$FDM_PROJECT_DIR/validation/periodicArrayDrag/caseSetup"

work=$(caseWorkDir periodicArrayDrag)
# Cell centre 4.1 plus offsets (1/8, 3/8, -1/8) Delta
periodicArrayCase "$work/held" 8 4.125 4.175 4.075 1e-6 8000 || exit 1
periodicArrayCase "$work/settling" 8 4.125 4.175 4.075 1e-6 8000 settling \
    || exit 1

runSerialAndParallel "$work/held" || exit 1
(
    cd "$work/settling" || exit 1
    runLogged blockMesh && runLogged fdmSuspensionFoam
) || exit 1

"$FDM_PYTHON" "$caseTemplates/checkPeriodicArray.py" "$work"
