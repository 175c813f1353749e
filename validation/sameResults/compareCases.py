"""Compare the last written time of each case run with two builds
(sameResults/Allrun): for particleState, U, p and lambda, "identical" when
the files are byte for byte the same, otherwise the largest difference of
any number relative to the largest magnitude in the file.  Two
particleStates whose pair histories list different pairs are compared
entry by entry, the pair entries over the pairs both list; the pairs only
one lists must join two fixed spheres (mobile false), whose loads move
nothing.

    compareCases.py WORK COMMIT CASE...

WORK holds old/CASE and new/CASE."""

import os
import re
import sys

FIELDS = ("particleState", "U", "p", "lambda")
NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")
ENTRY = re.compile(r"^(\w+)\s+(.*?);\s*$", re.M | re.S)
UNIFORM = re.compile(r"^\s*(\d+)\s*\{(.*)\}\s*$", re.S)
PAIR_ENTRIES = ("pairActive", "pairLogGap", "pairContact", "pairShearForce")


def last_time(case):
    """The latest written time directory (not 0) of a serial case."""
    times = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if t > 0 and os.path.isdir(os.path.join(case, d)):
            times.append((t, d))
    return max(times)[1] if times else None


def body(path):
    """A file's text after its banner."""
    with open(path) as f:
        return f.read().split("\\*", 1)[-1]


def numbers(path):
    return [float(x) for x in NUMBER.findall(body(path))]


def entries(path):
    """A dictionary file's entries as lists of numbers (a list written
    uniform, N{v}, expanded; words dropped)."""
    out = {}
    for key, value in ENTRY.findall(body(path)):
        uniform = UNIFORM.match(value)
        if uniform:
            out[key] = [float(x) for x in NUMBER.findall(uniform.group(2))]
            out[key] *= int(uniform.group(1))
        else:
            out[key] = [float(x) for x in NUMBER.findall(value)][1:] \
                if re.match(r"\s*\d+\s*\(", value) else \
                [float(x) for x in NUMBER.findall(value)]
    return out


def relative(x, y):
    scale = max(max((abs(v) for v in x), default=0), 1e-300)
    return max((abs(u - v) for u, v in zip(x, y)), default=0)/scale


def by_pair(state):
    """Each listed pair's history entries."""
    p = state["pairs"]
    pairs = [(int(p[2*k]), int(p[2*k + 1])) for k in range(len(p)//2)]
    width = {"pairShearForce": 3}
    return {pair: [v for e in PAIR_ENTRIES
                   for v in state[e][width.get(e, 1)*k:
                                     width.get(e, 1)*(k + 1)]]
            for k, pair in enumerate(pairs)}


def compare_pair_sets(old, new):
    """Particle entries number by number, the pair history over the common
    pairs; None when the pairs not in both are not all fixed-fixed."""
    a, b = entries(old), entries(new)
    mobile = a["mobile"]
    pa, pb = by_pair(a), by_pair(b)
    only = set(pa) ^ set(pb)
    if any(mobile[i] or mobile[j] for i, j in only):
        return None
    skip = set(PAIR_ENTRIES) | {"pairs"}
    particle = [k for k in a if k not in skip]
    if set(particle) != set(b) - skip or \
            any(len(a[k]) != len(b[k]) for k in particle):
        return None
    worst = max(relative(a[k], b[k]) for k in particle)
    common = sorted(set(pa) & set(pb))
    worst = max(worst, relative([v for q in common for v in pa[q]],
                                [v for q in common for v in pb[q]]))
    what = "identical" if worst == 0 else f"{worst:.2e} relative"
    return (f"{what} ({len(only)} pairs of two fixed spheres in one only, "
            f"{len(common)} common)")


def compare(old, new):
    """'identical', or the largest relative difference of two files."""
    with open(old, "rb") as a, open(new, "rb") as b:
        if a.read() == b.read():
            return "identical"
    x, y = numbers(old), numbers(new)
    if len(x) != len(y):
        if os.path.basename(old) == "particleState":
            pairs = compare_pair_sets(old, new)
            if pairs is not None:
                return pairs
        return f"differ in length ({len(x)} against {len(y)} numbers)"
    return f"{relative(x, y):.2e} relative"


def main(work, commit, cases):
    print(f"# Same results: {commit} against this tree\n")
    print("| case | time | " + " | ".join(FIELDS) + " |")
    print("|---" * (len(FIELDS) + 2) + "|")
    worst = 0.0
    for case in cases:
        old = os.path.join(work, "old", case)
        new = os.path.join(work, "new", case)
        t = last_time(old)
        if t is None or t != last_time(new):
            print(f"| {case} | written times differ or missing | "
                  + " | ".join("-" for _ in FIELDS) + " |")
            worst = float("inf")
            continue
        row = []
        for f in FIELDS:
            a, b = os.path.join(old, t, f), os.path.join(new, t, f)
            if not (os.path.exists(a) and os.path.exists(b)):
                row.append("absent" if not os.path.exists(a) and not
                           os.path.exists(b) else "in one only")
                continue
            r = compare(a, b)
            row.append(r)
            if "relative" in r:
                worst = max(worst, float(r.split()[0]))
            elif not r.startswith("identical"):
                worst = float("inf")
        print(f"| {case} | {t} | " + " | ".join(row) + " |")
    print(f"\nLargest relative difference: {worst:.2e}")
    return 0 if worst <= 1e-12 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3:]))
