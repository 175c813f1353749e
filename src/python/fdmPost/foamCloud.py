"""The particles as ParaView's .foam reader shows them: the OpenFOAM cloud
<time>/lagrangian/particles (fdmParticleCloud::writeLagrangian) read
through VTK's vtkOpenFOAMReader, the reader behind ParaView's built-in
.foam, from the Debian package python3-vtk9.

    python3 -m fdmPost.foamCloud CASE/NAME.foam [--png FILE]

checks every time with a particleState: the reader shows all particles,
each once (ids 0..N-1), with the fields id, group, d, U, omega, force,
torque, stresslet and contact parts, and their positions and velocities
equal the particleState's (to the write precision); prints a line per
time and with --png draws the last time (particles on the fluid velocity).
Exit status 1 when a check fails.
"""

import argparse
import os
import sys

import numpy as np

FIELDS = ("id", "group", "d", "U", "omega", "force", "torque", "stresslet",
          "contactForce", "contactTorque", "contactStresslet")


def _blocks(multiblock):
    """(name, dataset) of the direct children of a vtkMultiBlockDataSet."""
    import vtk
    for i in range(multiblock.GetNumberOfBlocks()):
        yield (multiblock.GetMetaData(i).Get(vtk.vtkCompositeDataSet.NAME()),
               multiblock.GetBlock(i))


def read_foam(foam_file, cloud="particles", decomposed=False):
    """{time: {"points": N x 3, "cells": cell centres, "Ucell": cell U,
    field: array}} of every time the reader lists; the cloud entries are
    absent where the reader shows no cloud."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    # The parallel reader knows decomposed cases (processor*/); it needs a
    # (here serial) process controller
    controller = vtk.vtkDummyController()
    vtk.vtkMultiProcessController.SetGlobalController(controller)
    reader = vtk.vtkPOpenFOAMReader()
    reader.SetController(controller)
    reader.SetFileName(foam_file)
    reader.SetCaseType(0 if decomposed else 1)
    reader.UpdateInformation()
    reader.SetPatchArrayStatus("lagrangian/" + cloud, 1)
    reader.EnableAllLagrangianArrays()
    reader.EnableAllCellArrays()
    out = {}
    for t in vtk_to_numpy(reader.GetTimeValues()):
        reader.UpdateTimeStep(t)
        reader.Update()
        entry = {}
        for name, block in _blocks(reader.GetOutput()):
            if name == "internalMesh":
                centres = vtk.vtkCellCenters()
                centres.SetInputData(block)
                centres.Update()
                entry["cells"] = vtk_to_numpy(
                    centres.GetOutput().GetPoints().GetData())
                entry["Ucell"] = vtk_to_numpy(block.GetCellData().GetArray("U"))
            if name == "lagrangian":
                for cname, poly in _blocks(block):
                    if cname != cloud or poly.GetNumberOfPoints() == 0:
                        continue
                    entry["points"] = vtk_to_numpy(poly.GetPoints().GetData())
                    data = poly.GetPointData()
                    for k in range(data.GetNumberOfArrays()):
                        entry[data.GetArrayName(k)] = vtk_to_numpy(
                            data.GetArray(k))
        out[float(t)] = entry
    return out


def check_case(foam_file, decomposed=False, png=None):
    """Compare the reader's cloud with each time's particleState; returns
    the number of failed checks."""
    from fdmPost.particleCase import particle_state
    case = os.path.dirname(os.path.abspath(foam_file))
    times = read_foam(foam_file, decomposed=decomposed)
    failed = 0
    for t, entry in sorted(times.items()):
        name = "%.12g" % t
        if not os.path.isfile(os.path.join(case, name, "particleState")):
            continue
        state = particle_state(case, name)
        n = len(state["position"])
        problems = []
        if "points" not in entry:
            problems.append("no particles")
        else:
            missing = [f for f in FIELDS if f not in entry]
            if missing:
                problems.append("fields missing: " + " ".join(missing))
            ids = np.asarray(entry.get("id", []), int)
            if sorted(ids.tolist()) != list(range(n)):
                problems.append("ids %d of %d, not each once" % (len(ids), n))
            else:
                order = np.argsort(ids)
                dx = np.abs(entry["points"][order] - state["position"]).max()
                dU = np.abs(entry["U"][order] - state["velocity"]).max()
                scale = max(np.abs(state["velocity"]).max(), 1e-300)
                if dx > 1e-5 * np.abs(state["position"]).max():
                    problems.append("positions off by %.2e" % dx)
                if dU > 1e-5 * scale:
                    problems.append("U off by %.2e" % dU)
        print("time %-8s %3d particles in the .foam reader, %d fields: %s"
              % (name, len(entry.get("points", [])),
                 sum(f in entry for f in FIELDS),
                 "; ".join(problems) or "ok"))
        failed += bool(problems)
    shown = [t for t, e in times.items() if "points" in e]
    if png and shown:
        plot(times[max(shown)], max(shown), png)
    if not shown:
        print("no time shows particles")
        failed += 1
    return failed


def plot(entry, time, png):
    """Particles (discs of diameter d in x, y; colour U_x) over the fluid
    U_x on the cells of the mid-z layer, as the .foam reader gives them."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cells, U = entry["cells"], entry["Ucell"]
    z = np.unique(np.round(cells[:, 2], 9))
    layer = np.isclose(cells[:, 2], z[len(z) // 2], atol=1e-9)
    fig, ax = plt.subplots(figsize=(6, 5.5))
    ax.tricontourf(cells[layer, 0], cells[layer, 1], U[layer, 0], 30,
                   cmap="coolwarm", alpha=0.6, vmin=U[:, 0].min(),
                   vmax=U[:, 0].max())
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Circle
    p = entry["points"]
    spheres = PatchCollection([Circle((x, y), 0.5 * d) for (x, y, _), d
                               in zip(p, entry["d"])], cmap="coolwarm",
                              edgecolors="k", linewidths=0.6)
    spheres.set_array(entry["U"][:, 0])
    spheres.set_clim(U[:, 0].min(), U[:, 0].max())
    ax.add_collection(spheres)
    fig.colorbar(spheres, ax=ax,
                 label="U_x (particles; fluid on the mid-z cell layer)")
    ax.set_xlim(cells[:, 0].min(), cells[:, 0].max())
    ax.set_ylim(cells[:, 1].min(), cells[:, 1].max())
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_title("%d particles through the .foam reader, t = %.6g"
                 % (len(p), time))
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote", png)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("foam")
    ap.add_argument("--decomposed", action="store_true",
                    help="read processor*/ (a run not reconstructed)")
    ap.add_argument("--png")
    args = ap.parse_args(argv)
    return 1 if check_case(args.foam, args.decomposed, args.png) else 0


if __name__ == "__main__":
    sys.exit(main())
