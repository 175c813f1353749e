# YADE side of the lubricatedDEMFoam/YADE comparison (run by run.py):
#
#     yade -j1 -n -x yadeShear.py CASE OUT RESOLUTION
#
# Shears the lubricatedDEMFoam case CASE (constant/particleList,
# constant/particleProperties, system/controlDict: every parameter is read
# from there) with YADE's implicit lubricated contact
# (Law2_ScGeom_ImplicitLubricationPhys, the law of thesis 2) and writes OUT
# in the column layout of lubricatedDEMFoam's stress.dat, so that one
# reader serves both codes.  The parameter mapping (README.md beside this
# file) is the one that makes the two codes solve the same equations.
import os
import sys
import time

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.caseRunner import foam_get  # noqa: E402
from fdmPost.demRheology import PARTS  # noqa: E402
from fdmPre.particleList import read_particle_list  # noqa: E402

case, out, resolution = sys.argv[1], sys.argv[2], int(sys.argv[3])
PP = "constant/particleProperties"


def number(entry, path=PP, default=None):
    try:
        return float(foam_get(case, entry, path))
    except Exception:
        if default is None:
            raise
        return default


def vector(entry):
    return [float(v) for v in foam_get(case, entry, PP).strip("()").split()]


law = "lubricatedContact."
eta = number(law + "viscosity")
g = number(law + "stiffness")
roughness = number(law + "roughness")
friction = number(law + "friction")
cutoff = number(law + "cutoff", default=2)
stiffness_ratio = number(law + "stiffnessRatio", default=1)
tangential = number(law + "tangentialStiffness", default=0.5)
try:
    arms = foam_get(case, law + "shearArms", PP)
except Exception:
    arms = "contactPoint"
density = number("density")
rate = number("cell.shearRate")
lo, hi = vector("cell.min"), vector("cell.max")
dt = number("deltaT", "system/controlDict")
end = number("endTime", "system/controlDict")
interval = int(number("output.interval", default=100))
_, x, r = read_particle_list(os.path.join(case, "constant", "particleList"))

O.periodic = True
O.cell.setBox(*[h - l for h, l in zip(hi, lo)])
# One material per sphere: Ip2 takes k_n = 2 E_i r_i E_j r_j/(E_i r_i +
# E_j r_j), so E = g/r gives k_n = g for every pair; k_s = poisson k_n
for xi, ri in zip(x, r):
    mat = O.materials.append(FrictMat(young=g / ri, poisson=tangential,
                                      density=density,
                                      frictionAngle=atan(friction)))
    b = sphere([xi[d] - lo[d] for d in range(3)], ri, material=mat)
    O.bodies.append(b)
# Bodies start at rest: setting the affine velocity here as well would
# double it (see the first step below)

# Pairs while the gap is below cutoff*a, a = (r_i + r_j)/2: detection at
# distance < factor (r_i + r_j), erased by the law at gap > MaxDist a.
# YADE's contact condition is gap < 2 eps a: eps = roughness/2.
factor = 1 + cutoff / 2
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=factor)]),
    InteractionLoop(
        [Ig2_Sphere_Sphere_ScGeom6D(
            interactionDetectionFactor=factor,
            avoidGranularRatcheting=(arms == "radius"))],
        [Ip2_FrictMat_FrictMat_LubricationPhys(eta=eta, eps=roughness / 2,
                                               keps=stiffness_ratio)],
        [Law2_ScGeom_ImplicitLubricationPhys(
            activateTangencialLubrication=True,
            activateTwistLubrication=True, activateRollLubrication=True,
            resolution=resolution, theta=1, MaxDist=cutoff,
            label="lubrication")]),
    NewtonIntegrator(damping=0),
]
O.cell.velGrad = Matrix3(0, rate, 0, 0, 0, 0, 0, 0, 0)
O.dt = dt

solid = sum(4 / 3 * pi * ri ** 3 for ri in r)
f = open(out, "w")
f.write("# YADE %s, Law2_ScGeom_ImplicitLubricationPhys resolution %d, "
        "viscosity %g, shear rate %g\n" % (version, resolution, eta, rate))
f.write("# time strain phi interactions contacts stabilityNumber "
        + " ".join("%s_xx %s_yy %s_zz %s_xy" % ((p,) * 4) for p in PARTS)
        + "\n")


def record():
    stresses = lubrication.getTotalStresses()[:4]
    real = [i for i in O.interactions if i.isReal]
    contacts = sum(1 for i in real if i.phys.contact)
    row = [O.time, rate * O.time, solid / O.cell.volume, len(real), contacts,
           float("nan")]
    # YADE's tensors are sum F (x) l/V, not symmetrised, tension positive
    for s in stresses:
        row += [s[0, 0], s[1, 1], s[2, 2], 0.5 * (s[0, 1] + s[1, 0])]
    f.write(" ".join("%.10g" % v for v in row) + "\n")
    f.flush()


# A first step of negligible length puts the bodies on the affine flow
# (NewtonIntegrator adds the change of velGrad times the position), so
# that the first real step evaluates its forces there, as lubricatedDEMFoam
# does; started at rest instead, its forces see a fluid sheared past
# resting spheres (2e-3 of the mean sigma_xy at strain 4e-3)
O.dt = 1e-9 * dt
O.run(1, True)
O.dt = dt
steps = int(round(end / dt))
start = time.time()
for block in range(0, steps, interval):
    O.run(min(interval, steps - block), True)
    # Lees-Edwards cell flipped at skew 1/2 (the skew of lubricatedDEMFoam's
    # shear offset is kept within the same range)
    if O.cell.hSize[0, 1] / O.cell.hSize[1, 1] > 0.5:
        O.cell.flipCell()
    record()
seconds = time.time() - start
f.write("# wall seconds %.3f, particle-steps %d, us per particle-step %.4f\n"
        % (seconds, steps * len(r), 1e6 * seconds / (steps * len(r))))
f.close()
