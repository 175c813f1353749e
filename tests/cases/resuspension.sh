#!/bin/bash
# Case test: lubricatedDEMFoam with an open top, a fixed floor and gravity
# (the resuspension tutorial's cell, strain 0.1):
#  - the start prints the Shields number and the inertial number the
#    density gives (0.0499 at Sh 2);
#  - the floor spheres stay at their height and particleState holds the
#    mobile flags and the stresslets by part;
#  - the Acrivos number (9/2) a Sh/h_0 given instead, h_0 = V/phi_m from
#    the mobile spheres' volume per floor area computed here from the
#    particle list, gives the same Shields number;
#  - bad input stops with a message naming the keyword: an open direction
#    that is not x, y or z; a fixed group absent from the particle list;
#    a sphere leaving the cell through the open top (gravity upwards); an
#    Acrivos number without packingFraction, or with a Shields number.
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

# Sh 2 as an Acrivos number: V over the 12 x 12 floor, phi_m 0.58
setUp "$work/acrivos"
acrivos=$("$FDM_PYTHON" - "$work/acrivos/constant/particleList" <<'PY'
import re, sys
import numpy as np
text = open(sys.argv[1]).read()
rows = re.findall(r"^\((\w+) \([^)]*\) (\S+)\)$", text, re.M)
r = np.array([float(a) for g, a in rows if g != "attachedLower"])
h0 = 4 / 3 * np.pi * np.sum(r**3) / (12 * 12) / 0.58
print("%.12g" % (4.5 * r.mean() * 2 / h0))
PY
) || exit 1
props=$work/acrivos/constant/particleProperties
foamDictionary -entry gravity/shieldsNumber -remove "$props" > /dev/null
foamDictionary -entry gravity/acrivosNumber -set "$acrivos" "$props" > /dev/null
foamDictionary -entry gravity/packingFraction -set 0.58 "$props" > /dev/null
(cd "$work/acrivos" && runLogged lubricatedDEMFoam) || exit 1
# foamDictionary writes 6 digits of A: Sh 2 within 1e-5
sh=$(sed -n 's/^    gravity .* Shields number \([^,]*\),.*/\1/p' \
    "$work/acrivos/log.lubricatedDEMFoam")
awk -v s="$sh" 'BEGIN { exit !(s > 2 - 2e-5 && s < 2 + 2e-5) }' \
    || { echo "FAILED: Acrivos number $acrivos gives Sh '$sh', not 2"; exit 1; }
echo "   Acrivos number $acrivos (h_0 = V/0.58): Shields number $sh"
foamDictionary -entry gravity/packingFraction -remove "$props" > /dev/null
expectStop "$work/acrivos" lubricatedDEMFoam "packingFraction" || exit 1
foamDictionary -entry gravity/shieldsNumber -set 2 "$props" > /dev/null
expectStop "$work/acrivos" lubricatedDEMFoam \
    "give shieldsNumber or acrivosNumber, not both" || exit 1

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
