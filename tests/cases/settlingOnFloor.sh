#!/bin/bash
# Case test: three unit spheres of twice the fluid's density released
# 0.3, 0.6 and 1 radius above the floor in quiescent fluid (gravity on
# their density excess, buoyant weight W = 6 pi eta a^2 (1/s)), to time 10
# with deltaT 0.1.  Checks in checkSettlingOnFloor.py: the spheres reach
# the floor and rest there, each contact carrying W at the overlap of
# eq 2.57; at the start the walls carry the buoyant weight of all three
# through the fluid; at every step each sphere's forces balance (eq 4.17)
# and so do the fluid's (eq 4.14); where the squeeze film dominates the
# approach follows Brenner's exact drag on a sphere moving towards a wall
# (frameInvariant wall sub-grid correction).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir settlingOnFloor)
cloneCase settlingOnFloor "$work/run"
(
    cd "$work/run" || exit 1
    runLogged blockMesh && runLogged fdmSuspensionFoam
) || exit 1
"$FDM_PYTHON" "$caseTemplates/checkSettlingOnFloor.py" "$work/run"
