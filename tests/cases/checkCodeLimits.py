"""Size limits of the sources (codeLimits.sh): no file in src/ or
applications/ over 400 lines, no function over 80 lines.

C++ in OpenFOAM style: a function body opens and closes with a brace in the
first column (definitions in .C files and free inline functions); the
braces of namespaces, classes, structs and enums are not bodies.  Member
functions defined inside a class are indented and short by construction.
Python functions and methods are measured with ast."""

import ast
import os
import re
import sys

MAX_FILE = 400
MAX_FUNCTION = 80
NOT_BODIES = re.compile(r"^(namespace|class|struct|enum|union)\b|[=,]$")


def cpp_bodies(lines):
    """(first line, length) of each first-column brace block that follows a
    declaration (not a namespace, class, struct, enum or initialiser)."""
    out, i = [], 0
    while i < len(lines):
        if lines[i].rstrip() == "{":
            j = i - 1
            while j >= 0 and not lines[j].strip():
                j -= 1
            head = lines[j].strip() if j >= 0 else ""
            k = i + 1
            while k < len(lines) and not lines[k].startswith("}"):
                k += 1
            if not NOT_BODIES.search(head):
                out.append((i + 1, k - i + 1))
            i = k
        i += 1
    return out


def python_bodies(text):
    return [(n.lineno, n.end_lineno - n.lineno + 1)
            for n in ast.walk(ast.parse(text))
            if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))]


def sources(root):
    for top in ("src", "applications"):
        for d, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = [x for x in dirs if x not in ("lnInclude", "Make")]
            for f in sorted(files):
                if f.endswith((".C", ".H", ".py")):
                    yield os.path.join(d, f)


def main(root):
    bad, n_files, n_functions = [], 0, 0
    for path in sources(root):
        text = open(path, encoding="utf-8").read()
        lines = text.split("\n")
        n_files += 1
        if len(lines) - 1 > MAX_FILE:
            bad.append(f"{path}: {len(lines) - 1} lines > {MAX_FILE}")
        bodies = (python_bodies(text) if path.endswith(".py")
                  else cpp_bodies(lines))
        n_functions += len(bodies)
        bad += [f"{path}:{line}: function of {length} lines > "
                f"{MAX_FUNCTION}" for line, length in bodies
                if length > MAX_FUNCTION]
    for b in bad:
        print("   ", os.path.relpath(b, root) if b.startswith(root) else b)
    print(f"code limits: {n_files} files, {n_functions} functions, "
          f"{len(bad)} over the limits (file {MAX_FILE} lines, function "
          f"{MAX_FUNCTION} lines)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(os.path.abspath(sys.argv[1])))
