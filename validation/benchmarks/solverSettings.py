"""Named solver settings of the issue-30 benchmarks (frozenCouette,
couetteTimeStep): the dictionary entries each changes from a case's own.

A setting is NAME, NAME+PART+... (their entries in order) or any of these
followed by @TOL (the lambda residual per step, coupling lambdaTolerance).
A part Delta<D> meshes the case again at Delta = D a1 with the sub-grid
tables calibrated there (apply_mesh).
"""

import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.caseRunner import (foam_get, foam_set, in_case,  # noqa: E402
                                run_logged)

FILES = {"fv": "system/fvSolution", "pp": "constant/particleProperties",
         "sc": "system/fvSchemes"}
# Laplacians and face-normal gradients with the explicit non-orthogonal
# correction (zero on these Cartesian meshes, yet computed: a gradient of
# each component per assembly), or without it
CORRECTED = (("laplacianSchemes.default", "Gauss linear corrected", "sc"),
             ("snGradSchemes.default", "corrected", "sc"))
UNCORRECTED = (("laplacianSchemes.default", "Gauss linear uncorrected",
                "sc"),
               ("snGradSchemes.default", "uncorrected", "sc"))
# The inner solves, the lambda residual of every step and the coupling of
# the Couette tutorial until issue 30 (a snapshot cloned from the tutorial
# since has looser steps between records, consistent overlaps, half the
# lambda step and uncorrected Laplacians)
PREVIOUS_SOLVES = CORRECTED + (
    ("SIMPLEC.momentumPredictor", "on", "fv"),
    ("SIMPLEC.nCorrectors", 2, "fv"),
    ("solvers.p.relTol", 0.05, "fv"),
    ("solvers.U.relTol", 0.1, "fv"),
    ("coupling.lambdaTolerance", 1e-3, "pp"),
    ("coupling.lambdaToleranceBetweenRecords", 1e-3, "pp"),
    ("coupling.overlaps", "thesis", "pp"),
    ("coupling.alphaLambdaFactor", 1, "pp"))
# The Anderson history kept when the residual grows (SIMPLEC
# accelerationRestart off)
NO_RESTART = (("SIMPLEC.accelerationRestart", "off", "fv"),)
# The tutorial's settings before issue 30: the layer means left to the
# outer iteration, no restarts
PREVIOUS = ((("SIMPLEC.layerMeanCorrection", "off", "fv"),) + NO_RESTART
            + PREVIOUS_SOLVES)
# (no restarts: with exact inner solves they cost iterations)
REFERENCE = NO_RESTART + (
    ("SIMPLEC.nOuterCorrectors", 3000, "fv"),
    ("coupling.lambdaTolerance", 1e-9, "pp"),
    ("coupling.lambdaToleranceBetweenRecords", 1e-9, "pp"),
    ("coupling.particleSolveTolerance", 1e-14, "pp"),
    ("solvers.p.tolerance", 1e-12, "fv"),
    ("solvers.p.relTol", 0, "fv"),
    ("solvers.U.tolerance", 1e-12, "fv"),
    ("solvers.U.relTol", 0, "fv"))
GAMG_U = (("solvers.U", "{solver GAMG; smoother GaussSeidel; "
           "tolerance 1e-7; relTol 0.1;}", "fv"),)
# Each setting: the dictionary entries it changes from the case's own
SETTINGS = {
    "default": PREVIOUS,
    "thesis": PREVIOUS + (("SIMPLEC.acceleration", "none", "fv"),
                          ("SIMPLEC.nOuterCorrectors", 3000, "fv")),
    "thesis10": PREVIOUS + (("SIMPLEC.acceleration", "none", "fv"),
                            ("SIMPLEC.nOuterCorrectors", 10, "fv"),
                            ("coupling.lambdaTolerance", 0, "pp"),
                            ("coupling.lambdaToleranceBetweenRecords", 0,
                             "pp")),
    "layerMean": PREVIOUS_SOLVES + (
        ("SIMPLEC.layerMeanCorrection", "on", "fv"),
        ("SIMPLEC.layerMeanViscosityRatio", 16, "fv")),
    # Parts to add to a setting with +: NAME+nCorr1
    "nCorr1": (("SIMPLEC.nCorrectors", 1, "fv"),),
    "loose": (("solvers.p.relTol", 0.2, "fv"), ("solvers.U.relTol", 0.3, "fv")),
    "gamgU": PREVIOUS + GAMG_U,
    "relax0.97": PREVIOUS + (("relaxationFactors.equations.U", 0.97, "fv"),),
    "reference": REFERENCE,
    # The steady solve of a frozen configuration (what validations do):
    # the reference's tolerances, old and new outer iteration
    "steady": PREVIOUS + REFERENCE,
    "steadyLayerMean": PREVIOUS_SOLVES + REFERENCE + (
        ("SIMPLEC.layerMeanCorrection", "on", "fv"),),
}

# The U under-relaxation as a part (layerMean+relaxU0.99): in SIMPLEC it is
# a pseudo-time step of about alpha/(1 - alpha) cell diffusion times per
# outer iteration, the rate at which a particle's rigid motion reaches the
# flow around it
SETTINGS.update(
    ("relaxU%s" % a, (("relaxationFactors.equations.U", a, "fv"),))
    for a in ("0.8", "0.98", "0.99", "0.995"))
# The Anderson depth as a part (layerMean+depth16)
SETTINGS.update(
    ("depth%d" % m, (("SIMPLEC.accelerationDepth", m, "fv"),))
    for m in (4, 12, 16, 24))
# The lambda step of eq 2.41, alpha_lambda = F Delta^2/nu (thesis F = 1),
# as a part (reference+alphaF0.5) and with the layer-mean correction
# (layerMeanAlphaF)
SETTINGS.update(
    ("alphaF%s" % F, (("coupling.alphaLambdaFactor", F, "pp"),))
    for F in ("0.25", "0.5", "2"))
SETTINGS.update(
    ("layerMeanAlpha%s" % F, SETTINGS["layerMean"] + SETTINGS["alphaF" + F])
    for F in ("0.25", "0.5", "2"))
# A looser lambda residual on the steps that write nothing, records every
# 5th step as in the tutorial (layerMean+betweenRecords1e-2; coupling
# lambdaToleranceBetweenRecords)
SETTINGS.update(
    ("betweenRecords%s" % t, (
        ("coupling.lambdaToleranceBetweenRecords", t, "pp"),
        ("output.timeSeriesInterval", 5, "pp")))
    for t in ("1e-3", "3e-3", "6.4e-3", "1e-2", "1.28e-2", "2e-2", "3e-2",
              "4e-2", "1e-1"))
# The Laplacians without the non-orthogonal correction as a part
# (TUTORIAL+uncorrected)
SETTINGS["uncorrected"] = UNCORRECTED
# The pressure corrections started from U as it is, without the momentum
# solve (part noPredictor)
SETTINGS["noPredictor"] = (("SIMPLEC.momentumPredictor", "off", "fv"),)
# ... on the steps between records only (part noPredictorBetween)
SETTINGS["noPredictorBetween"] = (
    ("SIMPLEC.momentumPredictorBetweenRecords", "off", "fv"),)
# Consistent overlapping supports as a part (reference+consistent)
SETTINGS["consistent"] = (("coupling.overlaps", "consistent", "pp"),)
# The Rhie-Chow coefficient of the converged face flux in units of 1/a_C as
# a part (reference+relaxU0.99+RC0.9: the fixed point of relaxation 0.9)
SETTINGS.update(
    ("RC%s" % f, (("SIMPLEC.RhieChowFactor", f, "fv"),))
    for f in ("0.9", "1"))
# Inexact inner solves on the steps between records only, as the "loose"
# part's but the records keep the case's own (fvSolution UBetweenRecords,
# pBetweenRecords, SIMPLEC nCorrectorsBetweenRecords)
SETTINGS["innerBetween"] = (
    ("solvers.UBetweenRecords", "{solver PCG; preconditioner DIC; "
     "tolerance 1e-7; relTol 0.3;}", "fv"),
    ("solvers.pBetweenRecords", "{solver GAMG; smoother GaussSeidel; "
     "tolerance 1e-7; relTol 0.2;}", "fv"),
    ("SIMPLEC.nCorrectorsBetweenRecords", 1, "fv"))
# A particle record every N steps (after a betweenRecords part)
SETTINGS.update(
    ("records%d" % n, (("output.timeSeriesInterval", n, "pp"),))
    for n in (5, 10, 20, 25, 40))
# Forward Euler for the positions instead of Adams-Bashforth (part euler,
# coupling positionScheme)
SETTINGS["euler"] = (("coupling.positionScheme", "euler", "pp"),)
# GAMG for U as a part (layerMean+relaxU0.99+gamg)
SETTINGS["gamg"] = GAMG_U
# The Anderson history dropped when the residual grows, or kept (parts
# restart, noRestart)
SETTINGS["restart"] = (("SIMPLEC.accelerationRestart", "on", "fv"),)
SETTINGS["noRestart"] = NO_RESTART
# The written steps' pressure to relTol 0.01 with one correction per outer
# iteration and U as loose as between records, with restarts (part
# tightP): inexact pressures make the outer iteration's map noisy and the
# Anderson extrapolation stall
SETTINGS["tightP"] = (("solvers.p.relTol", 0.01, "fv"),
                      ("solvers.U.relTol", 0.3, "fv"),
                      ("SIMPLEC.nCorrectors", 1, "fv")) + SETTINGS["restart"]
# The same with U as the case has it (part tightPonly)
SETTINGS["tightPonly"] = tuple(e for e in SETTINGS["tightP"]
                               if e[0] != "solvers.U.relTol")


# Mesh spacings as parts (NAME+Delta0.25): the case is meshed again at
# Delta = D a1, its start time's fields mapped from the old mesh and the
# sub-grid tables calibrated at D named (data/resistance/*_<part>, made
# with subGridCalibration --delta D).  apply_mesh does it; apply_setting
# leaves these parts alone.
MESH_PARTS = {"Delta0.25": 0.25, "Delta0.1667": 1/6}
# A field's nonuniform list (one level of parentheses inside)
NONUNIFORM = r"nonuniform List<(\w+)>\s*\d+\s*\((?:[^()]|\([^()]*\))*\)"
SETTINGS.update((name, ()) for name in MESH_PARTS)


def apply_mesh(case, setting, time):
    """Mesh the case again for the setting's spacing, if it names one."""
    for part in setting.partition("@")[0].split("+"):
        if part in MESH_PARTS:
            remesh(case, time, MESH_PARTS[part], "_" + part)


def remesh(case, time, delta, suffix):
    """blockMesh at spacing delta (the box kept), the fields U, p, lambda
    of `time` mapped from the old mesh (mapFields -consistent), and the
    sub-grid tables of that spacing (their names end in suffix)."""
    old = case + ".previousMesh"
    shutil.rmtree(old, ignore_errors=True)
    shutil.copytree(case, old)
    mesh_dict = os.path.join(case, "system", "blockMeshDict")
    text = open(mesh_dict).read()
    for axis in "xyz":
        length = float(re.search(r"^L%s\s+([^;]+);" % axis, text,
                                 re.M).group(1))
        text = re.sub(r"^n%s\s+[^;]+;" % axis,
                      "n%s      %d;" % (axis, round(length / delta)), text,
                      flags=re.M)
    open(mesh_dict, "w").write(text)
    shutil.rmtree(os.path.join(case, "constant", "polyMesh"))
    run_logged(["blockMesh"], case, "log.blockMesh")
    fields = os.path.join(case, time)
    for name in ("phi", "lagrangian"):
        path = os.path.join(fields, name)
        if os.path.isdir(path):
            shutil.rmtree(path)
        elif os.path.exists(path):
            os.remove(path)
    for name in ("U", "p", "lambda"):
        path = os.path.join(fields, name)
        # The old values as uniform zeros of the same type: templates that
        # mapFields fills
        text = re.sub(NONUNIFORM, lambda m: "uniform " + (
            "0" if m.group(1) == "scalar" else "(0 0 0)"),
            open(path).read(), flags=re.S)
        open(path, "w").write(text)
    run_logged(["mapFields", old, "-consistent", "-sourceTime", time],
               case, "log.mapFields")
    shutil.rmtree(old)
    pp = "constant/particleProperties"
    tables = re.findall(r'"([^"]+)"', foam_get(case, "subGrid.pairTables", pp))
    foam_set(case, "subGrid.pairTables",
             "(%s)" % " ".join('"%s%s"' % (t, suffix) for t in tables), pp)
    foam_set(case, "subGrid.wallTable",
             '"$FDM_PROJECT_DIR/data/resistance/subGridWall%s"' % suffix, pp)


def solve_as_between_records(case):
    """Make a written step of the case solve as a step between records:
    its BetweenRecords solvers and corrections (its own or a setting's,
    once applied) in place of the plain ones."""
    for entry, value, where in expanded_between_records(case):
        foam_set(case, entry.replace("BetweenRecords", ""), value,
                 FILES[where])


def expanded_between_records(case):
    """The case's fvSolution entries named *BetweenRecords (solvers,
    nCorrectors, momentumPredictor), macros expanded (foamDictionary
    -expand prints the whole file)."""
    out = subprocess.run(["foamDictionary", "-expand", FILES["fv"]],
                         cwd=case, stdout=subprocess.PIPE, check=True,
                         env=in_case(case)).stdout.decode()
    solvers = re.finditer(r"^    (\w+BetweenRecords)\s*\{(.*?)^    \}",
                          out, re.M | re.S)
    counts = re.finditer(r"^    (nCorrectorsBetweenRecords|"
                         r"momentumPredictorBetweenRecords)\s+(\w+);", out,
                         re.M)
    return ([("solvers.%s" % m.group(1), "{%s}" % m.group(2), "fv")
             for m in solvers]
            + [("SIMPLEC.%s" % m.group(1), m.group(2), "fv") for m in counts])


def check_setting(setting):
    """Stop on an unknown name in NAME[+PART...][@TOL]."""
    for part in setting.partition("@")[0].split("+"):
        if part not in SETTINGS:
            raise SystemExit("unknown setting %s (known: %s)"
                             % (part, ", ".join(sorted(SETTINGS))))


def case_suffix(setting):
    """The setting in a case name (no + or @)."""
    return setting.replace("@", "_tol").replace("+", "_")


def apply_setting(case, setting):
    """Write the setting's entries into the case's dictionaries."""
    check_setting(setting)
    name, _, tol = setting.partition("@")
    for part in name.split("+"):
        for entry, value, where in SETTINGS[part]:
            foam_set(case, entry, value, FILES[where])
    if tol:
        foam_set(case, "coupling.lambdaTolerance", tol, FILES["pp"])
