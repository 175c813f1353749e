"""Misspell each keyword of a dictionary once and run the solver on it.

    misspellEachKeyword.py CASE FILE SOLVER [--within BLOCK] [--timeout S]

CASE is a ready case (mesh, particle list), FILE a dictionary in it
(relative path), SOLVER the command.  Each keyword of FILE (inside the block
BLOCK only, when given; the FoamFile header and comments excepted) is
misspelt in turn by appending 'x', the solver is run in the case, and the
file restored.  Every variant must stop with a FOAM FATAL message naming
the misspelt keyword or the one it came from, before writing a time; one
that runs through (exit status 0), times out or dies without a message is a
failure.  Prints one line per variant and ends with the counts; exit status
1 when any failed.
"""

import argparse
import os
import re
import subprocess
import sys

# A keyword starts a statement: at the start of a line or after { or ;
KEYWORD = re.compile(r"(?:^|(?<=[{;]))([ \t]*)([A-Za-z_][A-Za-z0-9_]*)(?=\s)",
                     re.M)


def blank_comments(text):
    """The text with comments replaced by spaces (offsets kept)."""
    def spaces(m):
        return re.sub(r"[^\n]", " ", m.group(0))
    return re.sub(r"//[^\n]*|/\*.*?\*/", spaces, text, flags=re.S)


def block_span(text, name):
    """[start, end) of the body of the first block 'name { ... }'."""
    m = re.search(r"(?:^|[{;\s])" + re.escape(name) + r"\s*\{", text)
    if not m:
        raise SystemExit("no block %s" % name)
    depth, i = 1, m.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return m.end(), i - 1


def keyword_positions(text, within=None):
    """Offsets and names of the keywords to misspell."""
    clean = blank_comments(text)
    lo, hi = block_span(clean, within) if within else (0, len(clean))
    header = block_span(clean, "FoamFile") if "FoamFile" in clean else (0, 0)
    found = []
    for m in KEYWORD.finditer(clean, lo, hi):
        at = m.start(2)
        if header[0] - len("FoamFile {") <= at < header[1] + 1:
            continue
        found.append((m.end(2), m.group(2)))
    return found


def time_dirs(case):
    return {d for d in os.listdir(case)
            if re.fullmatch(r"[0-9.eE+-]+", d) and d != "0"}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("file")
    ap.add_argument("solver")
    ap.add_argument("--within")
    ap.add_argument("--timeout", type=float, default=60)
    args = ap.parse_args()

    path = os.path.join(args.case, args.file)
    original = open(path).read()
    before = time_dirs(args.case)
    failed = 0
    positions = keyword_positions(original, args.within)
    if not positions:
        raise SystemExit("no keyword found in %s" % path)
    try:
        for end, key in positions:
            with open(path, "w") as f:
                f.write(original[:end] + "x" + original[end:])
            try:
                run = subprocess.run([args.solver], cwd=args.case,
                                     stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT,
                                     timeout=args.timeout)
                log, rc = run.stdout.decode(errors="replace"), run.returncode
            except subprocess.TimeoutExpired:
                log, rc = "", "timeout"
            written = time_dirs(args.case) - before
            stopped = (rc not in (0, "timeout") and "FOAM FATAL" in log
                       and key in log and not written)
            failed += not stopped
            print("  %s %s: %s -> %s (rc %s)%s"
                  % ("ok  " if stopped else "FAIL", args.file, key, key + "x",
                     rc, " wrote " + " ".join(sorted(written))
                     if written else ""))
            if not stopped:
                print("\n".join(log.splitlines()[-12:]))
            for d in written:
                subprocess.run(["rm", "-rf", os.path.join(args.case, d)])
    finally:
        with open(path, "w") as f:
            f.write(original)
    print("  %s: %d keywords misspelt, %d stopped as they should"
          % (args.file, len(positions), len(positions) - failed))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
