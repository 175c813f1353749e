#!/bin/bash
# Case test: a free sphere (a = 1, Delta = a/5) near the centre of a plane
# Couette flow (walls at y = -5, 5 moving at -5, 5: shear rate 1), cyclic
# in x and z, pushed along z by an external force.  Checks (shearedSphereCheck
# in checkShearedSphere.py): rotation rate and translation against
# unbounded-shear theory, and the wall force balancing lambda (eq 4.14).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir shearedSphere)
cloneCase shearedSphere "$work"
(
    cd "$work" || exit 1
    runLogged blockMesh && runLogged fdmSuspensionFoam
) || exit 1

"$FDM_PYTHON" "$caseTemplates/checkShearedSphere.py" "$work"
