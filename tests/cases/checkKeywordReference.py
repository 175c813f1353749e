"""Every keyword and option the code reads is in README's reference, and
the reference names nothing the code does not read.

    checkKeywordReference.py [PROJECT_DIR]

Keywords read by the code: every string literal naming a keyword in a
dictionary lookup (get, getOrDefault, found, subDict, readBounded, ...)
or in an allowed-keyword list (checkKeywords, the lubricatedDEMFoam block
lists, the contact law's common keywords) in src/fdmParticles and
applications/solvers.  Lookups in files the solvers write themselves
(particleState, the resistance tables) and in FoamFile headers are set
apart by the source file and the variable they are read from (INTERNAL
below).

Each keyword is attributed to the solver(s) reading it by its source path:
lubricatedDEMFoam (dem/, the solver), fdmSuspensionFoam (everything else),
or both (particle list, VTK writer, time controls, restart).  It must be a
first-column entry of a table under a "### fdmSuspensionFoam ..." or
"### lubricatedDEMFoam ..." heading of README's "## Reference" section.

Options: argList::add*Option names of the solvers (written -name) and the
argparse options of the utilities in applications/utilities (--name);
each must be a first-column entry of a table under "### <tool>" there
(a heading's entries starting with - are its options, the others its
keywords).

The reverse holds too: a first-column entry that no code reads is an
error, except the OpenFOAM keywords listed in OPENFOAM (read by
OpenFOAM's own classes, documented because users set them).

Prints what is missing or stale and the counts; exit status 1 on any.
"""

import glob
import os
import re
import sys

LOOKUP = re.compile(
    r"(\w+)\s*(?:\.|->)\s*(?:get|getOrDefault|lookup|lookupOrDefault|found|"
    r"subDict|findDict|subOrEmptyDict|isDict|readIfPresent|getCheck|"
    r"getCheckOrDefault|readEntry)\s*(?:<(?:[^<>;]|<[^<>;]*>)*>)?\s*"
    r"\(\s*\"(\w+)\"")
# Free functions taking (dictionary, "keyword", ...)
FREE = re.compile(
    r"\b(?:readBounded|readBoundedOrDefault|readMotion|readAxis|"
    r"requirePositive)\s*\(\s*(\w+)\s*,\s*\"(\w+)\"")
CHECK_LIST = re.compile(r"checkKeywords\s*\(\s*\w+\s*,\s*\{([^}]*)\}")
# lubricatedDEMFoam's {"block", {"keyword", ...}} lists and the contact
# law's common keywords: a word list in braces after "allowed" or a block
BLOCK_LIST = re.compile(r"\{\s*\"(\w+)\"\s*,\s*\{([^}]*)\}\s*\}")
WORD_LIST = re.compile(r"wordList\s+allowed\s*\(\s*\{([^}]*)\}")
LITERAL = re.compile(r"\"(\w+)\"")
OPTION_CXX = re.compile(r"argList::add(?:Bool)?Option\s*\(\s*\"(\w+)\"")
OPTION_PY = re.compile(
    r"add_argument\(\s*\"(-[\w-]+)\"(?:\s*,\s*\"(--[\w-]+)\")?")

# (source file, variable) of lookups in files the solvers write: the
# particleState of both solvers and the resistance tables; and in the
# FoamFile header of any file (its format, read for the check of the
# start fields)
INTERNAL = {
    ("src/fdmParticles/core/input/readableDictionaries.C", "header"),
    ("src/fdmParticles/cloud/fdmParticleCloudInput.C", "state"),
    ("src/fdmParticles/contact/particleContactsIO.C", "state"),
    ("src/fdmParticles/functionObjects/suspensionStress/suspensionStress.C",
     "state"),
    ("src/fdmParticles/dem/lubricatedDEM/lubricatedDEMState.C", "dict"),
    ("src/fdmParticles/dem/lubricatedInteraction/lubricatedInteractionIO.C",
     "dict"),
    ("src/fdmParticles/subGrid/resistanceTableRead.C", "dict"),
    ("src/fdmParticles/subGrid/resistanceTableRead.C", "fd"),
    ("src/fdmParticles/subGrid/subGridModel/frameInvariantSubGrid.C",
     "table"),
}

# Read by OpenFOAM's classes, not ours, yet documented for the user
OPENFOAM = {"relaxationFactors", "transportModel", "writePrecision",
            "writeFormat", "writeInterval", "libs", "functions"}

SHARED = ("src/fdmParticles/io/particleList/",
          "src/fdmParticles/io/particleVTK/",
          "src/fdmParticles/control/timeControls/",
          "src/fdmParticles/io/restart/",
          "src/fdmParticles/core/gravity/")
DEM = ("src/fdmParticles/dem/", "applications/solvers/lubricatedDEMFoam/")


def solvers_of(path):
    if path.startswith(SHARED):
        return ("fdmSuspensionFoam", "lubricatedDEMFoam")
    if path.startswith(DEM):
        return ("lubricatedDEMFoam",)
    return ("fdmSuspensionFoam",)


def strip_comments(text):
    return re.sub(r"//[^\n]*|/\*.*?\*/", "", text, flags=re.S)


def sources(root):
    for pattern in ("src/fdmParticles/**/*.[CH]",
                    "applications/solvers/**/*.[CH]"):
        for path in sorted(glob.glob(os.path.join(root, pattern),
                                     recursive=True)):
            rel = os.path.relpath(path, root)
            if "/lnInclude/" not in rel and "/Make/" not in rel:
                yield rel, strip_comments(open(path).read())


def keywords_read(root):
    """{solver: {keyword: first source file}} and {tool: {option}}."""
    read = {"fdmSuspensionFoam": {}, "lubricatedDEMFoam": {}}
    options = {}
    for rel, text in sources(root):
        found = set()
        for m in list(LOOKUP.finditer(text)) + list(FREE.finditer(text)):
            if (rel, m.group(1)) not in INTERNAL and m.group(1) != "args":
                found.add(m.group(2))
        for m in CHECK_LIST.finditer(text):
            found.update(LITERAL.findall(m.group(1)))
        for m in BLOCK_LIST.finditer(text):
            inner = LITERAL.findall(m.group(2))
            if inner:
                found.add(m.group(1))
                found.update(inner)
        for m in WORD_LIST.finditer(text):
            found.update(LITERAL.findall(m.group(1)))
        for solver in solvers_of(rel):
            for k in found:
                read[solver].setdefault(k, rel)
        if rel.startswith("applications/solvers/"):
            tool = rel.split("/")[2]
            for name in OPTION_CXX.findall(text):
                options.setdefault(tool, set()).add("-" + name)
    for path in sorted(glob.glob(os.path.join(root, "applications",
                                              "utilities", "*", "*"))):
        tool = os.path.basename(path)
        if os.path.isfile(path) and tool == os.path.basename(
                os.path.dirname(path)):
            for names in OPTION_PY.findall(open(path).read()):
                options.setdefault(tool, set()).update(n for n in names if n)
    return read, options


def reference_tables(readme):
    """{heading's first word: {first-column names}} of README's
    "## Reference" section."""
    text = open(readme).read()
    m = re.search(r"^## Reference\b.*?(?=^## |\Z)", text, re.M | re.S)
    if not m:
        raise SystemExit("README has no '## Reference' section")
    tables, heading = {}, None
    for line in m.group(0).splitlines():
        h = re.match(r"### `?([\w.-]+)", line)
        if h:
            heading = h.group(1)
            tables.setdefault(heading, set())
        elif heading and line.startswith("|") and not line.startswith("|-"):
            first = line.split("|")[1]
            tables[heading].update(re.findall(r"`(-{0,2}[\w-]+)`", first))
    return tables


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                           os.path.join(os.path.dirname(__file__), "..", ".."))
    read, options = keywords_read(root)
    tables = reference_tables(os.path.join(root, "README.md"))
    problems = 0

    def report(msg):
        nonlocal problems
        problems += 1
        print("  " + msg)

    def named(heading, options):
        return {n for n in tables.get(heading, set())
                if n.startswith("-") == options}

    for solver, keys in read.items():
        documented = named(solver, False)
        for k, where in sorted(keys.items()):
            if k not in documented:
                report("%s keyword %s (read in %s) is not in README's "
                       "reference under '### %s'" % (solver, k, where, solver))
        for k in sorted(documented - set(keys) - OPENFOAM):
            report("README's '### %s' reference lists %s, which %s does "
                   "not read" % (solver, k, solver))
    for tool, opts in sorted(options.items()):
        documented = named(tool, True)
        for o in sorted(opts - documented):
            report("%s option %s is not in README's reference under "
                   "'### %s'" % (tool, o, tool))
        for o in sorted(documented - opts):
            report("README's '### %s' reference lists %s, which %s does "
                   "not take" % (tool, o, tool))

    nKeys = sum(len(k) for k in read.values())
    nOpts = sum(len(o) for o in options.values())
    print("keyword reference: %d keywords (by solver) and %d options read "
          "by the code, %d not documented or stale"
          % (nKeys, nOpts, problems))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
