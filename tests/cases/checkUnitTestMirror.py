"""tests/unit mirrors src/fdmParticles file for file (unitTestMirror.sh).

Each source X.C of src/fdmParticles has its unit test tests/unit/DIR/XTest.C
in the same folder DIR; a class split over several sources (YParts.C
beside Y.C) shares YTest.C.  A source that acts on meshes, fields or Time
is listed in tests/unit/caseTested with the case tests (tests/cases/N.sh)
that run it instead.  Each unit test mirrors a source (X.C or the
header-only X.H) and is built (tests/unit/Make/files); each caseTested line
names a source without a unit test and existing case tests."""

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


def case_tested(path):
    """{source: [case tests]} from the list file."""
    out = {}
    for line in open(path):
        words = line.split("#")[0].split()
        if words:
            out[words[0]] = words[1:]
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
    listed = case_tested(os.path.join(tests_dir, "caseTested"))
    problems = []

    for t in sorted(tests):
        base = t[:-len("Test.C")]
        if base + ".C" not in files and base + ".H" not in files:
            problems.append("%s mirrors no source (%s.C or .H)" % (t, base))
        if t not in built:
            problems.append("%s is not in tests/unit/Make/files" % t)

    n_unit = n_case = 0
    for s in sorted(f for f in files if f.endswith(".C")):
        test = test_of(s, tests)
        if test and s in listed:
            problems.append("%s has %s: remove it from caseTested" % (s, test))
        elif test:
            n_unit += 1
        elif s in listed:
            missing = [c for c in listed[s] if not os.path.isfile(
                os.path.join(root, "tests", "cases", c + ".sh"))]
            if not listed[s] or missing:
                problems.append("caseTested: %s names no case test %s"
                                % (s, " ".join(missing)))
            n_case += 1
        else:
            problems.append("%s has no unit test (tests/unit/%sTest.C) and"
                            " is not in caseTested" % (s, s[:-2]))
    for s in sorted(set(listed) - files):
        problems.append("caseTested lists %s, which is not a source" % s)

    for p in problems:
        print(p)
    print("%d sources with a unit test, %d tested by case tests, %d header"
          "-only unit tests; %d problems"
          % (n_unit, n_case, sum(t[:-6] + ".C" not in files for t in tests),
             len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
