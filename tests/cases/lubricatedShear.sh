#!/bin/bash
# Case test: lubricatedDEMFoam (lubrication-only DEM, Lees-Edwards cell).
# A dilute bidisperse packing (phi 0.3, 13^3 cell) sheared to strain 0.4:
#  - a restart from the state written at 0.25, the first run's last step
#    (between the write times 0.2 and 0.4: a run's last step is written
#    too), ends bitwise where the straight run ends (positions, velocities,
#    pair history);
#  - the time series is written and the mean fluctuation momentum stays
#    zero (pairwise forces, checked to 1e-10 of the rms momentum);
#  - output{track} writes the tracked particles' positions (last row equal
#    to the final particleState to the 12 digits written);
#  - particles.h5 (the FDM series format) holds a record per stress.dat
#    row, the restarted run's series bitwise the straight run's;
#  - a deltaT above the critical step min sqrt(m/k) stops before the run
#    with a message naming system/controlDict and deltaT.
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir lubricatedShear)
tutorial="$FDM_PROJECT_DIR/tutorials/lubricatedShear"
setUp()
{
    mkdir -p "$1"
    cp -r "$tutorial"/{system,constant} "$1"/
    sed -i -e 's/(16 16 16)/(13 13 13)/' "$1/constant/particleProperties"
    sed -i -e 's/^endTime .*/endTime 0.4;/' -e 's/^writeInterval .*/writeInterval 0.2;/' \
        -e 's/^deltaT .*/deltaT 1e-4;/' "$1/system/controlDict"
    sed -i -e 's/^    stiffness .*/    stiffness 1e5;/' \
        -e 's/^    interval .*/    interval 100; track (0 5);/' \
        "$1/constant/particleProperties"
    (cd "$1" && fdmPackParticles --box 13 13 13 --walls '' --phi 0.3 \
        --seed 2 -o constant/particleList > log.fdmPackParticles)
}

setUp "$work/straight"
(cd "$work/straight" && runLogged lubricatedDEMFoam) || exit 1

setUp "$work/restarted"
(
    cd "$work/restarted" || exit 1
    sed -i 's/^endTime .*/endTime 0.25;/' system/controlDict
    runLogged lubricatedDEMFoam || exit 1
    [ -f 0.25/particleState ] || { echo "FAIL: the last step, 0.25, not written"; exit 1; }
    sed -i 's/^endTime .*/endTime 0.4;/' system/controlDict
    mv log.lubricatedDEMFoam log.first
    runLogged lubricatedDEMFoam
) || exit 1

setUp "$work/badDeltaT"
sed -i 's/^deltaT .*/deltaT 0.01;/' "$work/badDeltaT/system/controlDict"
expectStop "$work/badDeltaT" lubricatedDEMFoam \
    "deltaT 0.01 in system/controlDict is above the critical step" || exit 1

"$FDM_PYTHON" - "$work" <<'PY' || exit 1
import glob, os, re, sys
import numpy as np
from fdmPost.particleCase import read_list
work = sys.argv[1]

def state(case):
    times = [d for d in os.listdir(case) if re.match(r"^[0-9.]+$", d)]
    last = max(times, key=float)
    return last, open(os.path.join(case, last, "particleState")).read()

WIDTH = {"position": 3, "velocity": 3, "angularVelocity": 3, "radius": 1,
         "pairs": 2, "pairActive": 1, "pairLogGap": 1, "pairShearForce": 3}

def numbers(text, key):
    return read_list(text, key, WIDTH[key])

ok = True
ts, s = state(os.path.join(work, "straight"))
tr, r = state(os.path.join(work, "restarted"))
print("   last times: straight %s, restarted %s" % (ts, tr))
for key in ("position", "velocity", "angularVelocity"):
    a, b = numbers(s, key), numbers(r, key)
    same = a.shape == b.shape and np.array_equal(a, b)
    print("   restart %-16s bitwise %s" % (key, same))
    ok &= same and ts == tr

def history(text):
    """Active pairs -> (ln gap, shear force); inactive entries are stale"""
    pairs = numbers(text, "pairs").astype(int)
    active = numbers(text, "pairActive").astype(bool)
    gap = numbers(text, "pairLogGap")
    force = numbers(text, "pairShearForce")
    return {tuple(p): (g, tuple(f)) for p, a, g, f
            in zip(pairs, active, gap, force) if a}

hs, hr = history(s), history(r)
same = hs == hr
print("   restart pair history (%d active pairs) bitwise %s" % (len(hs), same))
ok &= same and len(hs) > 0

v = numbers(s, "velocity")
rad = numbers(s, "radius")
m = rad ** 3
p = (m[:, None] * v).sum(0)
rms = np.sqrt(((m[:, None] * v) ** 2).sum())
print("   net fluctuation momentum %.2e of rms %.2e" % (np.abs(p).max(), rms))
ok &= np.abs(p).max() < 1e-10 * rms

d = np.loadtxt(glob.glob(os.path.join(work, "straight", "postProcessing",
                                      "lubricatedDEM", "0", "stress.dat"))[0])
print("   %d time-series rows, final strain %.3f, eta_r %.3f"
      % (len(d), d[-1, 1], d[-1, 9::4].sum()))
ok &= len(d) > 10 and abs(d[-1, 1] - 0.4) < 1e-3 and np.isfinite(d).all()

tracks = np.loadtxt(os.path.join(work, "straight", "postProcessing",
                                  "lubricatedDEM", "0", "tracks.dat"))
x = numbers(s, "position")
err = np.abs(tracks[-1, 1:] - np.concatenate([x[0], x[5]])).max()
print("   tracks.dat: %d rows, last row against particleState %.1e"
      % (len(tracks), err))
ok &= len(tracks) == len(d) and err < 1e-9 * np.abs(x).max()

# particles.h5 (the FDM format): a record per stress.dat row; the restart
# continues the first run's series, so both series are the same records
import h5py
series = {}
for case in ("straight", "restarted"):
    with h5py.File(os.path.join(work, case, "postProcessing",
                                "particles.h5"), "r") as f:
        series[case] = {k: f[k][...] for k in ("time", "position",
                                               "contactForce")}
a, b = series["straight"], series["restarted"]
# The record times are OpenFOAM's accumulated times: 1e-4 steps summed from
# 0 or from 0.25 differ in the last digits
same = (all(a[k].shape == b[k].shape and np.array_equal(a[k], b[k])
            for k in ("position", "contactForce"))
        and np.allclose(a["time"], b["time"], rtol=0, atol=1e-12))
last = np.array_equal(a["position"][-1], x)
print("   particles.h5: %d records (stress.dat %d), restarted series bitwise"
      " %s, last record at the final particleState %s"
      % (len(a["time"]), len(d), same, last))
ok &= len(a["time"]) == len(d) and same and last
sys.exit(0 if ok else 1)
PY

# ParaView files of the DEM: the VTK series from t = 0, each particle once
# at its particleState position, the interactions as lines; particles.h5
# with its units, run attributes, named groups and XDMF companion
echo "   VTK and HDF5 files:"
out=$("$FDM_PYTHON" -m fdmPost.particleFiles "$work/straight"); rc=$?
echo "$out" | sed 's/^/   /'
[ $rc -eq 0 ] && [ -f "$work/straight/VTK/particles_0.vtp" ] \
    && grep -q "contact lines" <<< "$out" \
    && ! grep -q " 0 contact lines" <<< "$(grep "VTK:" <<< "$out" | tail -n 1)"
