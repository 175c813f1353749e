"""tests/unit mirrors src/fdmParticles file for file (unitTestMirror.sh).

Each source X.C of src/fdmParticles has its unit test tests/unit/DIR/XTest.C
in the same folder DIR; a class split over several sources (YParts.C
beside Y.C) shares YTest.C.  Sources that act on meshes, fields or Time
are tested on the scratch cases and box meshes of tests/unit/
unitTestCase.H.  Each unit test mirrors a source (X.C or the header-only
X.H) and is built (tests/unit/Make/files)."""

import os
import sys


def sources(src):
    """Relative paths of the sources and headers (lnInclude, Make out)."""
    out = set()
    for d, dirs, files in os.walk(src):
        dirs[:] = [x for x in dirs if x not in ("lnInclude", "Make")]
        for f in files:
            if f.endswith((".C", ".H")):
                out.add(os.path.relpath(os.path.join(d, f), src))
    return out


def unit_tests(tests):
    out = set()
    for d, dirs, files in os.walk(tests):
        dirs[:] = [x for x in dirs if x != "Make"]
        for f in files:
            if f.endswith("Test.C"):
                out.add(os.path.relpath(os.path.join(d, f), tests))
    return out


def test_of(source, tests):
    """The unit test of a source: its own, or its class's (the longest
    test name that begins the source's name, in the same folder)."""
    folder, name = os.path.split(source[:-2])
    best = None
    for t in tests:
        tf, tn = os.path.split(t[:-len("Test.C")])
        if tf == folder and name.startswith(tn):
            if best is None or len(tn) > len(best[1]):
                best = (t, tn)
    return best[0] if best else None


def main(root):
    src = os.path.join(root, "src", "fdmParticles")
    tests_dir = os.path.join(root, "tests", "unit")
    files = sources(src)
    tests = unit_tests(tests_dir)
    built = set(open(os.path.join(tests_dir, "Make", "files")).read().split())
    problems = []

    for t in sorted(tests):
        base = t[:-len("Test.C")]
        if base + ".C" not in files and base + ".H" not in files:
            problems.append("%s mirrors no source (%s.C or .H)" % (t, base))
        if t not in built:
            problems.append("%s is not in tests/unit/Make/files" % t)

    n_unit = 0
    for s in sorted(f for f in files if f.endswith(".C")):
        if test_of(s, tests):
            n_unit += 1
        else:
            problems.append("%s has no unit test (tests/unit/%sTest.C)"
                            % (s, s[:-2]))

    for p in problems:
        print(p)
    print("%d sources with a unit test, %d header-only unit tests; %d problems"
          % (n_unit, sum(t[:-6] + ".C" not in files for t in tests),
             len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
