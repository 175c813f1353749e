"""The particle files that ParaView opens besides the .foam case, checked
against the run's own state:

VTK/particles.vtp.series, contacts.vtp.series  (fdm::particleVTKWriter,
    both solvers) read with VTK's XML PolyData reader (python3-vtk9);
postProcessing/particles.h5  its self-description (units of every dataset,
    the run's attributes) and the XDMF companion particles.xmf.

    python3 -m fdmPost.particleFiles CASE [--contact-balance]

For every time with a particleState: the series lists it, the particles
file holds each particle once (ids 0..N-1) at its position with its
velocity (to the float precision of the files), and with
--contact-balance (fdmSuspensionFoam with contacts) the contact lines add
up, particle by particle, to the contact force of the particleState.
Exit status 1 when a check fails.
"""

import argparse
import json
import os
import sys

import numpy as np

H5_UNITS = ("time", "radius", "group", "position", "velocity",
            "angularVelocity", "force", "torque", "stresslet", "dipoleTrace",
            "contactForce", "contactTorque", "contactStresslet")
H5_ATTRIBUTES = ("solver", "groupNames", "viscosity", "shearRate", "boxMin",
                 "boxMax", "periodic", "particleProperties")
# fdmSuspensionFoam's also (the DEM has no mesh, and its gravity and fluid
# density are entries of particleProperties)
H5_FDM_ATTRIBUTES = ("fluidDensity", "gravity", "meshSpacing")
FLOAT = 1e-6    # the VTK files hold single precision


def read_series(case, base):
    """{time: file path} of VTK/<base>.vtp.series."""
    vtk_dir = os.path.join(case, "VTK")
    with open(os.path.join(vtk_dir, base + ".vtp.series")) as f:
        files = json.load(f)["files"]
    return {float(e["time"]): os.path.join(vtk_dir, e["name"]) for e in files}


def read_polydata(path):
    """{"points": array, name: array} of the point and cell data."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    out = {"points": vtk_to_numpy(poly.GetPoints().GetData())
           if poly.GetNumberOfPoints() else np.zeros((0, 3))}
    for data in (poly.GetPointData(), poly.GetCellData()):
        for k in range(data.GetNumberOfArrays()):
            out[data.GetArrayName(k)] = vtk_to_numpy(data.GetArray(k))
    return out


def contact_sums(contacts, n):
    """Per particle, the contact force of the network's lines: F on i,
    -F on j (j < 0: a wall)."""
    total = np.zeros((n, 3))
    if len(contacts.get("i", [])) == 0:
        return total
    i = contacts["i"].astype(int)
    j = contacts["j"].astype(int)
    F = contacts["force"].astype(float)
    np.add.at(total, i, F)
    pair = j >= 0
    np.add.at(total, j[pair], -F[pair])
    return total


def check_vtk(case, contact_balance=False):
    """Lines of findings per written time; returns the failed count."""
    from fdmPost.particleCase import read_list
    particles = read_series(case, "particles")
    contacts = read_series(case, "contacts")
    times = sorted(t for t in particles if os.path.isfile(
        os.path.join(case, "%.12g" % t, "particleState")))
    failed = 0
    for t in times:
        name = "%.12g" % t
        with open(os.path.join(case, name, "particleState")) as f:
            text = f.read()
        x = read_list(text, "position", 3)
        n = len(x)
        p = read_polydata(particles[t])
        problems = []
        ids = p.get("id", np.array([])).astype(int)
        if sorted(ids.tolist()) != list(range(n)):
            problems.append("ids %d of %d, not each once" % (len(ids), n))
        else:
            order = np.argsort(ids)
            dx = np.abs(p["points"][order] - x).max()
            if dx > FLOAT * max(np.abs(x).max(), 1):
                problems.append("positions off by %.2e" % dx)
            if "stresslet_normalContact" not in p:
                # fdmSuspensionFoam: the particleState's velocity (the DEM
                # keeps it relative to the affine flow, the file in the lab)
                U = read_list(text, "velocity", 3)
                dU = np.abs(p["velocity"][order] - U).max()
                if dU > FLOAT * max(np.abs(U).max(), 1e-300):
                    problems.append("velocity off by %.2e" % dU)
        if t not in contacts:
            problems.append("no contacts file")
        elif contact_balance:
            Fc = read_list(text, "contactForce", 3)
            c = read_polydata(contacts[t])
            dF = np.abs(contact_sums(c, n) - Fc).max()
            if dF > 1e-5 * max(np.abs(Fc).max(), 1e-300):
                problems.append("contact lines sum off by %.2e" % dF)
        nLines = len(read_polydata(contacts[t]).get("i", [])) \
            if t in contacts else 0
        print("time %-8s VTK: %d particles, %d contact lines: %s"
              % (name, len(ids), nLines, "; ".join(problems) or "ok"))
        failed += bool(problems)
    if not times:
        print("no VTK file at a written time")
        failed += 1
    return failed


def check_hdf5(case):
    """particles.h5 describes itself and particles.xmf covers its records;
    returns the failed count."""
    import h5py
    path = os.path.join(case, "postProcessing", "particles.h5")
    failed = 0
    with h5py.File(path, "r") as f:
        no_units = [k for k in H5_UNITS if "units" not in f[k].attrs]
        solver = f.attrs.get("solver", b"")
        solver = solver.decode() if isinstance(solver, bytes) else solver
        required = H5_ATTRIBUTES + (
            () if solver.startswith("lubricatedDEMFoam") else H5_FDM_ATTRIBUTES)
        missing = [k for k in required if k not in f.attrs]
        nT = len(f["time"])
        groups = f.attrs.get("groupNames", b"").decode().split()
        bad_group = int(f["group"][:].max()) >= len(groups)
    xmf = os.path.join(case, "postProcessing", "particles.xmf")
    with open(xmf) as x:
        nGrids = x.read().count('GridType="Uniform"')
    for ok, what in ((not no_units, "units of every dataset"
                      + (" (%s missing)" % " ".join(no_units)) * bool(no_units)),
                     (not missing, "run attributes"
                      + (" (%s missing)" % " ".join(missing)) * bool(missing)),
                     (not bad_group, "groups named"),
                     (nGrids == nT, "particles.xmf: %d records of %d"
                      % (nGrids, nT))):
        print("particles.h5 %-50s %s" % (what, "ok" if ok else "FAILED"))
        failed += not ok
    return failed


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("case")
    parser.add_argument("--contact-balance", action="store_true")
    parser.add_argument("--no-hdf5", action="store_true",
                        help="skip particles.h5")
    args = parser.parse_args(argv)
    failed = check_vtk(args.case, args.contact_balance)
    if not args.no_hdf5:
        failed += check_hdf5(args.case)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
