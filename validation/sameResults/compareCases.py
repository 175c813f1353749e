"""Compare the last written time of each case run with two builds
(sameResults/Allrun): for particleState, U, p and lambda, "identical" when
the files are byte for byte the same, otherwise the largest difference of
any number relative to the largest magnitude in the file.

    compareCases.py WORK COMMIT CASE...

WORK holds old/CASE and new/CASE."""

import os
import re
import sys

FIELDS = ("particleState", "U", "p", "lambda")
NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")


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


def numbers(path):
    with open(path) as f:
        text = f.read()
    body = text.split("\\*", 1)[-1]
    return [float(x) for x in NUMBER.findall(body)]


def compare(old, new):
    """'identical', or the largest relative difference of two files."""
    with open(old, "rb") as a, open(new, "rb") as b:
        if a.read() == b.read():
            return "identical"
    x, y = numbers(old), numbers(new)
    if len(x) != len(y):
        return f"differ in length ({len(x)} against {len(y)} numbers)"
    scale = max(max(abs(v) for v in x), 1e-300)
    diff = max(abs(u - v) for u, v in zip(x, y))
    return f"{diff/scale:.2e} relative"


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
            if r.endswith("relative"):
                worst = max(worst, float(r.split()[0]))
            elif r != "identical":
                worst = float("inf")
        print(f"| {case} | {t} | " + " | ".join(row) + " |")
    print(f"\nLargest relative difference: {worst:.2e}")
    return 0 if worst <= 1e-12 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3:]))
