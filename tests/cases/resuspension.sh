#!/bin/bash
# Case test: lubricatedDEMFoam with an open top, a fixed floor and gravity
# (the resuspension tutorial's cell, strain 0.1):
#  - the start prints the Shields number and the inertial number the
#    density gives (0.0499 at Sh 2);
#  - the floor spheres stay at their height and particleState holds the
#    mobile flags and the stresslets by part;
#  - bad input stops with a message naming the keyword: an open direction
#    that is not x, y or z; a fixed group absent from the particle list;
#    a sphere leaving the cell through the open top (gravity upwards).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir resuspension)
tutorial="$FDM_PROJECT_DIR/tutorials/resuspension"
setUp()
{
    mkdir -p "$1"
    cp -r "$tutorial"/{system,constant} "$1"/
    sed -i -e 's/^endTime .*/endTime 0.1;/' -e 's/^writeInterval .*/writeInterval 0.05;/' \
        "$1/system/controlDict"
    (cd "$1" && fdmPackParticles --box 12 16 12 --walls y --phi 0.45 \
        --ratio 1 --polydispersity 0.05 --attach-walls 0.5 --jammed \
        --attach-sides lower --seed 1 -o constant/particleList \
        > log.fdmPackParticles) || exit 1
}

setUp "$work/run"
(cd "$work/run" && runLogged lubricatedDEMFoam) || exit 1
grep -q "Shields number 2, inertial number gammaDot sqrt(a/g) 0.049" \
    "$work/run/log.lubricatedDEMFoam" \
    || { echo "FAILED: Shields/inertial numbers not printed"; exit 1; }

setUp "$work/badOpen"
sed -i 's/^    open .*/    open        (w);/' "$work/badOpen/constant/particleProperties"
expectStop "$work/badOpen" lubricatedDEMFoam "open: direction 'w' is not one of x, y, z" || exit 1

setUp "$work/badGroup"
sed -i 's/^fixedGroups .*/fixedGroups     (floor);/' "$work/badGroup/constant/particleProperties"
expectStop "$work/badGroup" lubricatedDEMFoam "fixedGroups: no particle of group floor" || exit 1

setUp "$work/escape"
sed -i -e 's/^    max .*/    max         (12 17 12);/' \
    -e 's/^    direction .*/    direction       (0 1 0);/' \
    -e 's/^    shieldsNumber .*/    shieldsNumber   0.01;/' \
    "$work/escape/constant/particleProperties"
foamDictionary -entry drag/viscosity -set 0 \
    "$work/escape/constant/particleProperties" > /dev/null
expectStop "$work/escape" lubricatedDEMFoam "left the cell through its open direction y" || exit 1

"$FDM_PYTHON" - "$work/run" <<'PY'
import sys
import numpy as np
from fdmPost.particleCase import read_list
case = sys.argv[1]
ok = True
t0 = open(case + "/constant/particleList").read()
s = open(case + "/0.1/particleState").read()
x = read_list(s, "position", 3)
mobile = read_list(s, "mobile", 1) > 0.5
floor = ~mobile
print("   %d spheres, %d fixed" % (len(x), floor.sum()))
ok &= 10 < floor.sum() < len(x)
dy = np.abs(x[floor, 1] - 1.01).max()
print("   floor height drift %.1e" % dy)
ok &= dy < 1e-12
for part in ("normalContact", "shearContact", "normalLubrication",
             "shearLubrication"):
    S = read_list(s, "stresslet_" + part, 6)
    ok &= S.shape == (len(x), 6) and np.isfinite(S).all()
# The bed is under its weight: the mobile spheres' normal stresslets are
# compressive in the vertical (yy) on the whole
syy = sum(read_list(s, "stresslet_" + p, 6)[mobile, 3]
          for p in ("normalContact", "normalLubrication")).sum()
print("   total yy stresslet of the mobile spheres %.3g (< 0)" % syy)
ok &= syy < 0
sys.exit(0 if ok else 1)
PY
