"""Checks of the RhieChowFactor case test (RhieChowFactor.sh): the solution
at relaxation 0.97 with RhieChowFactor 0.9 is the one at relaxation 0.9,
and without the factor it is not; without the momentum predictor it is the
one at relaxation 0.9."""

import os
import sys

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.particleCase import read_list  # noqa: E402


def outputs(case):
    """Mean velocity along grad P0 (momentumBalance), torque, stresslet."""
    table = os.path.join(case, "postProcessing", "momentumBalance", "0",
                         "momentumBalance.dat")
    last = [line for line in open(table) if not line.startswith("#")][-1]
    mean_u = float(last.split()[-3])
    text = open(os.path.join(case, "1", "particleState")).read()
    return (mean_u, read_list(text, "torque", 3)[0],
            read_list(text, "stresslet", 6)[0])


def difference(a, b):
    """Largest difference of K, torque and stresslet, relative to K and
    to the largest component of torque and stresslet."""
    d = abs(a[0] - b[0])/abs(b[0])
    for x, y in zip(a[1:], b[1:]):
        scale = max(abs(v) for v in y)
        d = max(d, max(abs(u - v) for u, v in zip(x, y))/scale)
    return d


def main(work):
    ref = outputs(os.path.join(work, "relax0.9"))
    fixed = difference(outputs(os.path.join(work, "relax0.97fixed")), ref)
    moved = difference(outputs(os.path.join(work, "relax0.97")), ref)
    plain = difference(outputs(os.path.join(work, "noPredictor")), ref)
    ok = True
    for name, value, passes, bound in (
            ("relaxation 0.97, RhieChowFactor 0.9", fixed, fixed < 1e-7,
             "< 1e-7"),
            ("relaxation 0.97, thesis scheme", moved, moved > 1e-5,
             "> 1e-5"),
            ("relaxation 0.9, no momentum predictor", plain, plain < 1e-7,
             "< 1e-7")):
        print("   %s against relaxation 0.9: %.2e (%s) %s"
              % (name, value, bound, "PASS" if passes else "FAILED"))
        ok = ok and passes
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
