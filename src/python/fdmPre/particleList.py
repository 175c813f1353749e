"""Read the particle list of constant/particleList (thesis 1, 4.2 set-up):
a count, then one `(group (x y z) radius)` per sphere, as fdmPackParticles
writes it and the particle cloud reads it."""

import re

import numpy as np

NUMBER = r"([-+0-9.eE]+)"
ENTRY = re.compile(r"\(\s*(\w+)\s*\(\s*%s\s+%s\s+%s\s*\)\s*%s\s*\)"
                   % ((NUMBER,) * 4))


def read_particle_list(path):
    """Groups (list of str), positions (N x 3) and radii (N) of a particle
    list file; ValueError naming the file if the count does not match."""
    text = re.sub(r"//[^\n]*", "", open(path).read())
    count = re.search(r"^\s*(\d+)\s*\(", text, flags=re.M)
    if not count:
        raise ValueError("%s: no particle count before the list" % path)
    entries = ENTRY.findall(text[count.end() - 1:])
    if len(entries) != int(count.group(1)):
        raise ValueError("%s: %s particles announced, %d read"
                         % (path, count.group(1), len(entries)))
    groups = [e[0] for e in entries]
    positions = np.array([[float(v) for v in e[1:4]] for e in entries])
    radii = np.array([float(e[4]) for e in entries])
    return groups, positions, radii
