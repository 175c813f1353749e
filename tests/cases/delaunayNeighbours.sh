#!/bin/bash
# Case test: lubricatedDEMFoam with neighbours { selection delaunay; }
# (thesis 2, article 2: the lubricated pairs are the edges of the Delaunay
# triangulation).  A dense monodisperse packing (phi 0.45, 12^3 cell, no
# shear, so nothing moves) run for two steps:
#  - the pairs of the written particleState are exactly the edges of the
#    periodic Delaunay triangulation that Qhull (scipy.spatial.Delaunay)
#    gives for the centres and their 26 periodic images, edges with at
#    least one end in the cell;
#  - a pair interacts (pairActive) exactly when its gap is below the
#    cut-off (set to 0.5 a here, so that some Delaunay pairs are out of
#    reach).
# The same packing sheared (triangulated every 3 steps) for 0.01 strain: a
# restart from the state written halfway ends bitwise where the straight
# run ends (the triangulation schedule is part of the state), and a state
# written with the cut-off pairs is searched again when the case switches
# to the Delaunay pairs.  With walls along y (article 2's cell) the pairs
# are Qhull's edges with the spheres' mirror images in the walls (without
# them this packing would list 78 edges of the convex hull too).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir delaunayNeighbours)
mkdir -p "$work"
cp -r "$FDM_PROJECT_DIR/tutorials/lubricatedShear"/{system,constant} "$work"/
pp="$work/constant/particleProperties"
sed -i -e 's/(16 16 16)/(12 12 12)/' -e 's/shearRate   1;/shearRate   0;/' \
    -e 's/^    cutoff .*/    cutoff              0.5;/' \
    -e 's/^output/neighbours\n{\n    selection   delaunay;\n    interval    1;\n}\n\noutput/' "$pp"
sed -i -e 's/^endTime .*/endTime 8e-5;/' -e 's/^writeInterval .*/writeInterval 8e-5;/' \
    "$work/system/controlDict"
(cd "$work" && runLogged fdmPackParticles --box 12 12 12 --walls '' --ratio 1 \
    --phi 0.45 --gap 0.05 --seed 4 -o constant/particleList) || exit 1
(cd "$work" && runLogged lubricatedDEMFoam) || exit 1
grep -q "lubricated pairs: Delaunay neighbours" "$work/log.lubricatedDEMFoam" \
    || { echo "FAILED: the log does not name the Delaunay neighbours"; exit 1; }

"$FDM_PYTHON" "$caseTemplates/checkDelaunayPairs.py" \
    "$work/8e-05/particleState" 12 periodic || exit 1

# Sheared: straight against restarted halfway, every 3 steps
sheared()
{
    rm -rf "$1" && mkdir -p "$1"
    cp -r "$work"/{system,constant} "$1"/
    sed -i -e 's/shearRate   0;/shearRate   1;/' -e 's/interval    1;/interval    3;/' \
        "$1/constant/particleProperties"
    sed -i -e "s/^endTime .*/endTime $2;/" -e 's/^writeInterval .*/writeInterval 0.005;/' \
        "$1/system/controlDict"
}
sheared "$work/straight" 0.01
(cd "$work/straight" && runLogged lubricatedDEMFoam) || exit 1
sheared "$work/restarted" 0.005
(cd "$work/restarted" && runLogged lubricatedDEMFoam \
    && sed -i 's/^endTime .*/endTime 0.01;/' system/controlDict \
    && mv log.lubricatedDEMFoam log.first && runLogged lubricatedDEMFoam) || exit 1
if cmp -s "$work/straight/0.01/particleState" "$work/restarted/0.01/particleState"
then
    echo "   sheared, triangulated every 3 steps: the restart ends bitwise on the straight run"
else
    echo "FAILED: the restarted run's particleState at 0.01 differs from the straight run's"
    exit 1
fi

# A cut-off state continued with the Delaunay pairs: searched at once
sheared "$work/switched" 0.005
sed -i 's/selection   delaunay;/selection   cutoff;/; /interval    3;/d' \
    "$work/switched/constant/particleProperties"
(cd "$work/switched" && runLogged lubricatedDEMFoam \
    && sed -i 's/^endTime .*/endTime 0.01;/' system/controlDict \
    && cp ../straight/constant/particleProperties constant/ \
    && mv log.lubricatedDEMFoam log.first && runLogged lubricatedDEMFoam) || exit 1
grep -q "lists cutoff pairs; the delaunay pairs are searched at the first step" \
    "$work/switched/log.lubricatedDEMFoam" \
    || { echo "FAILED: a cut-off state was not searched again"; exit 1; }
echo "   a state with cut-off pairs continued with the Delaunay pairs: searched again"

# Walls along y (article 2's cell): the pairs are the Qhull edges between
# the spheres of the centres, their periodic images along x and z and the
# mirror images of all these in the planes tangent to the lowest and the
# highest sphere (the power cells clipped to the slab between them)
walled="$work/walled"
rm -rf "$walled" && mkdir -p "$walled"
cp -r "$work"/{system,constant} "$walled"/
foamDictionary -entry cell -set "{ min (0 0 0); max (12 14 12); shearRate 0; open (y); }" \
    "$walled/constant/particleProperties" > /dev/null
(cd "$walled" && runLogged fdmPackParticles --box 12 14 12 --walls y --ratio 1 \
    --phi 0.45 --gap 0.05 --seed 4 -o constant/particleList \
    && runLogged lubricatedDEMFoam) || exit 1
"$FDM_PYTHON" "$caseTemplates/checkDelaunayPairs.py" \
    "$walled/8e-05/particleState" 12 walls || exit 1
