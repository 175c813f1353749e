"""Check of tests/cases/delaunayNeighbours.sh: the pairs of a written
particleState are exactly the edges that Qhull (scipy.spatial.Delaunay)
gives for the centres of a cell of side L in x and z, edges with at least
one end among the centres.

    checkDelaunayPairs.py STATE L periodic   the 26 periodic images; and a
                                             pair interacts (pairActive)
                                             exactly when its gap is below
                                             the cut-off CUTOFF a
    checkDelaunayPairs.py STATE L walls      walls along y: the images
                                             along x and z and the mirror
                                             images of all these in the
                                             planes tangent to the lowest
                                             and the highest sphere

Exits 1 on a mismatch."""

import itertools
import sys

import numpy as np
from scipy.spatial import Delaunay

from fdmPost.particleCase import read_list

CUTOFF = 0.5


def edges_among(points, n, inside):
    """Qhull's edges of points with an end among the first n and both
    among the first inside, as pairs of indices modulo n."""
    edges = set()
    for simplex in Delaunay(points).simplices:
        for u, v in itertools.combinations(simplex, 2):
            if (u < n or v < n) and u < inside and v < inside:
                i, j = u % n, v % n
                edges.add((min(i, j), max(i, j)))
    return edges


def periodic_edges(x, L):
    shifts = [np.zeros(3)] + [L * np.array(s) for s in
                              itertools.product((-1, 0, 1), repeat=3)
                              if any(s)]
    points = np.concatenate([x + s for s in shifts])
    return edges_among(points, len(x), len(points))


def walled_edges(x, a, L):
    lo, hi = (x[:, 1] - a).min(), (x[:, 1] + a).max()
    images = [x + L * np.array((i, 0, k)) for i in (-1, 0, 1)
              for k in (-1, 0, 1)]
    images.sort(key=lambda p: np.abs(p - x).sum())      # the centres first
    plain = np.concatenate(images)
    mirrored = [plain * (1, -1, 1) + (0, 2 * plane, 0) for plane in (lo, hi)]
    return edges_among(np.concatenate([plain] + mirrored), len(x),
                       len(plain))


def active_matches_cutoff(text, x, a, pairs, L):
    """pairActive exactly where the gap is below CUTOFF times the mean
    radius, with some pairs on each side"""
    active = read_list(text, "pairActive", 1).astype(bool)
    d = x[pairs[:, 1]] - x[pairs[:, 0]]
    d -= L * np.round(d / L)
    mean = 0.5 * (a[pairs[:, 0]] + a[pairs[:, 1]])
    gap = np.linalg.norm(d, axis=1) - 2 * mean
    reach = gap < CUTOFF * mean
    print("   %d pairs within the cut-off %g a, %d interacting, %d mismatches"
          % (reach.sum(), CUTOFF, active.sum(), (reach != active).sum()))
    return (reach == active).all() and 0 < active.sum() < len(active)


def main(path, L, mode):
    text = open(path).read()
    x = read_list(text, "position", 3)
    a = read_list(text, "radius", 1)
    pairs = read_list(text, "pairs", 2).astype(int)
    if mode not in ("periodic", "walls"):
        sys.exit(f"checkDelaunayPairs.py: mode {mode}: allowed periodic,"
                 " walls")
    edges = (periodic_edges(x, L) if mode == "periodic"
             else walled_edges(x, a, L))
    listed = set(map(tuple, pairs))
    print("   %s: %d particles, %d listed pairs, %d Qhull edges, %d in both"
          % (mode, len(x), len(listed), len(edges), len(listed & edges)))
    ok = listed == edges and len(pairs) == len(listed)
    if mode == "periodic":
        ok &= active_matches_cutoff(text, x, a, pairs, L)
    return ok


if __name__ == "__main__":
    sys.exit(0 if main(sys.argv[1], float(sys.argv[2]), sys.argv[3]) else 1)
