#!/bin/bash
# Case test: the sphere of shearedSphere (a = 1, Delta = a/5), force- and
# torque-free (no walls to carry a push), in a Lees-Edwards box instead of
# between walls: the y faces (y = -5, 5) coupled at shear rate 1, x and z
# cyclic, solved at t = 0 (offset 0: the images across the faces move at
# +-10 along x) and after one step at t = 0.34 (offset 3.4, 17 cells).
# The same sphere at the box centre and moved up by 4.6 (23 cells), its
# support reaching across the sheared faces, at the same position relative
# to the cells: its rotation, slip from the affine flow and stresslet must
# not see the faces, and agree with free-sphere theory as in shearedSphere
# (checkShearedSphereLeesEdwards.py).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir shearedSphereLeesEdwards)
cloneCase shearedSphere "$work/centre"
leesEdwardsBox "$work/centre" || exit 1
(
    cd "$work/centre" || exit 1
    foamDictionary -entry groups -set "{ pushed { } }" \
        constant/particleProperties > /dev/null
    # The initial solve and one step: offsets 0 and 3.4
    foamDictionary -entry deltaT -set 0.34 system/controlDict > /dev/null
    foamDictionary -entry endTime -set 0.34 system/controlDict > /dev/null
) || exit 1
# Moved up by 4.6, in the flow moved by -4.6 along x (the mean velocity of
# a Lees-Edwards box is its initial one): the same flow around the sphere
cp -r "$work/centre" "$work/acrossFaces"
(
    cd "$work/acrossFaces" || exit 1
    foamDictionary -entry particles -set "((pushed (5.05 4.63 4.97) 1))" \
        constant/particleProperties > /dev/null || exit 1
    foamDictionary -entry internalField -set "uniform (-4.6 0 0)" 0/U \
        > /dev/null
) || exit 1

for c in centre acrossFaces
do
    (cd "$work/$c" && runLogged blockMesh && runLogged fdmSuspensionFoam) \
        || exit 1
done

"$FDM_PYTHON" "$caseTemplates/checkShearedSphereLeesEdwards.py" "$work"
