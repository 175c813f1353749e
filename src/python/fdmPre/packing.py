"""Random non-overlapping packings of spheres in a box (thesis 1, 4.2:
random initial positions; chapter 5: particles attached to the walls).

The spheres start at random positions with radii shrunk by a factor s and
grow to full size while overlaps are relaxed by steepest descent on a
harmonic overlap energy (a soft-sphere compression).  Every contact, wall
included, is required to keep a clearance `gap` (in units of the smallest
radius), so that no pair starts inside the contact roughness.  The result
depends only on the inputs and the seed.

Directions are periodic or bounded by walls at the box faces.
"""

import numpy as np
from scipy.spatial import cKDTree


def bidisperse_counts(volume, phi, a1=1.0, ratio=1.4):
    """Numbers of small (a1) and large (ratio a1) spheres filling a
    fraction phi of the volume in equal parts (thesis 4.2)."""
    v1 = 4.0 / 3.0 * np.pi * a1**3
    v2 = v1 * ratio**3
    return int(round(0.5 * phi * volume / v1)), int(round(0.5 * phi * volume / v2))


class Box:
    """Axis-aligned box, origin lo, edges span, periodic flags."""

    def __init__(self, lo, span, periodic):
        self.lo = np.asarray(lo, float)
        self.span = np.asarray(span, float)
        self.periodic = np.asarray(periodic, bool)

    def image(self, d):
        """Minimum image of separation vectors d (..., 3)."""
        p = self.periodic
        d[..., p] -= self.span[p] * np.round(d[..., p] / self.span[p])
        return d

    def wrap(self, x):
        p = self.periodic
        x[:, p] = self.lo[p] + np.mod(x[:, p] - self.lo[p], self.span[p])
        return x


def _pairs(x, r, box, skin):
    """Pairs (i < j, sorted by i then j) with surface gap below skin: the
    candidates within the largest pair's reach from SciPy's k-d tree
    (periodic axes as its box, walled ones padded so that nothing wraps),
    then the gap test on the minimum image."""
    if len(x) < 2:
        return np.zeros(0, int), np.zeros(0, int)
    reach = 2 * r.max() + skin
    p = box.periodic
    u = x - np.where(p, box.lo, x.min(axis=0))
    periodic = np.mod(u[:, p], box.span[p])
    periodic[periodic >= box.span[p]] = 0.0    # mod's rounding up
    u[:, p] = periodic
    size = np.where(p, box.span, u.max(axis=0) + 2 * reach + 1)
    ij = cKDTree(u, boxsize=size).query_pairs(reach * (1 + 1e-9),
                                                output_type="ndarray")
    ij = ij[np.lexsort((ij[:, 1], ij[:, 0]))]
    I, J = ij[:, 0], ij[:, 1]
    d = box.image(x[J] - x[I])
    near = np.sqrt((d**2).sum(-1)) < r[I] + r[J] + skin
    return I[near], J[near]


def _relax(x, r, box, gap, iters, tol, free):
    """Steepest descent on sum of squared overlaps (pairs and walls) with
    clearance gap, moving the spheres flagged free; returns the largest
    remaining overlap.

    The pair list holds the pairs within gap + skin and is rebuilt once a
    sphere has moved a quarter skin along an axis (at most 0.43 skin), so
    no pair closer than gap is ever missing.  Half a radius is enough:
    the list is a seventh of that of a skin of two radii, the sums the
    same."""
    skin = 0.5 * r.max()
    I, J = _pairs(x, r, box, gap + skin)
    walls = ~box.periodic
    moved = np.zeros_like(x)
    worst = np.inf
    for it in range(iters):
        if np.abs(moved).max() > 0.25 * skin:
            I, J = _pairs(x, r, box, gap + skin)
            moved[:] = 0
        dx = np.zeros_like(x)
        d = box.image(x[J] - x[I])
        dist = np.sqrt((d**2).sum(-1))
        over = r[I] + r[J] + gap - dist
        hit = over > 0
        worst = over[hit].max() if hit.any() else 0.0
        if hit.any():
            n = d[hit] / dist[hit, None]
            push = 0.5 * over[hit, None] * n
            # One pass in the order np.add.at would take (I, then J):
            # the same sums to the last bit, a fraction of its time
            ends = np.concatenate((I[hit], J[hit]))
            for k in range(3):
                dx[:, k] = np.bincount(ends, np.concatenate(
                    (-push[:, k], push[:, k])), len(x))
        for k in np.nonzero(walls)[0]:
            lo = box.lo[k] + r + gap
            hi = box.lo[k] + box.span[k] - r - gap
            below = (x[:, k] < lo) & free
            above = (x[:, k] > hi) & free
            dx[below, k] += lo[below] - x[below, k]
            dx[above, k] -= x[above, k] - hi[above]
            if below.any() or above.any():
                worst = max(worst, (lo - x[:, k])[below].max(initial=0),
                            (x[:, k] - hi)[above].max(initial=0))
        if worst <= tol:
            return worst
        dx[~free] = 0
        x += dx
        moved += dx
        box.wrap(x)
    return worst


def pack(box, radii, seed=1, gap=0.01, fixed_positions=None,
         max_stages=2000, log=None, stratify=None):
    """Positions (N, 3) for spheres of the given radii in box.

    fixed_positions: optional (M, 3) positions of the first M spheres,
    which stay where they are (spheres attached to a wall, chapter 5).
    gap: clearance kept between surfaces and from the walls, in units of
    the smallest radius.
    stratify: optional wall-normal axis along which the start positions
    are stratified: each radius spread evenly over the height, each
    centre at least its own radius from the walls.  Uniform random starts
    leave slabs of a small box over- or under-filled by their fluctuation
    (the two 5 a1 wall layers of a 10 x 20 x 10 a1 box at phi 0.42 differ
    by 0.07-0.16 for seeds 1-3), and the relaxation hardly moves them;
    stratified, phi(y) is flat.
    """
    radii = np.asarray(radii, float)
    n = len(radii)
    rng = np.random.default_rng(seed)
    free = np.ones(n, bool)
    m = 0 if fixed_positions is None else len(fixed_positions)
    free[:m] = False
    # Start the free spheres away from the walls, beyond any attached
    # layer (a sphere caught between a wall and an attached sphere could
    # not get out)
    margin = np.where(box.periodic, 0.0, radii.max() * (3 if m else 1))
    x = box.lo + margin + rng.random((n, 3)) * (box.span - 2 * margin)
    if stratify is not None:
        if m or box.periodic[stratify]:
            raise ValueError("stratify needs a wall-normal axis and no"
                             " attached spheres")
        for radius in np.unique(radii):
            k = np.nonzero(radii == radius)[0]
            u = (rng.permutation(len(k)) + rng.random(len(k))) / len(k)
            x[k, stratify] = (box.lo[stratify] + radius
                              + u * (box.span[stratify] - 2 * radius))
    if m:
        x[:m] = fixed_positions
    phi = (4 / 3 * np.pi * radii**3).sum() / np.prod(box.span)
    # Start dilute (phi 0.05 at most) and grow
    s = min(1.0, (0.05 / phi) ** (1 / 3)) if phi > 0 else 1.0
    growth = 1.02
    tol = 1e-6 * radii.min()
    for stage in range(max_stages):
        # Attached spheres keep their full size (they touch the wall)
        size = np.where(free, s * radii, radii)
        worst = _relax(x, size, box, gap * radii.min(), 1000, tol, free)
        if worst <= tol:
            if s >= 1.0:
                return x
            s = min(1.0, s * growth)
        else:
            # Not relaxed yet: relax more at the same size, grow slower
            growth = 1 + 0.5 * (growth - 1)
            if growth < 1 + 1e-7:
                break
        if log and stage % 20 == 0:
            log(f"  stage {stage}: size {s:.4f}, overlap {worst:.2e}")
    raise RuntimeError(
        f"packing did not converge at volume fraction {phi:.3f} (size factor"
        f" {s:.4f}): lower the volume fraction or the clearance gap")


def volume_fraction(box, radii):
    return (4 / 3 * np.pi * np.asarray(radii)**3).sum() / np.prod(box.span)


def min_clearance(x, radii, box):
    """Smallest surface gap between spheres and to the walls."""
    radii = np.asarray(radii, float)
    I, J = _pairs(x, radii, box, 10 * radii.max())
    d = box.image(x[J] - x[I])
    g = np.sqrt((d**2).sum(-1)) - radii[I] - radii[J]
    worst = g.min() if len(g) else np.inf
    for k in np.nonzero(~box.periodic)[0]:
        worst = min(worst, (x[:, k] - box.lo[k] - radii).min(),
                    (box.lo[k] + box.span[k] - x[:, k] - radii).min())
    return worst


def _plane_offsets(pts, p, box, plane):
    """In-plane separations of the points pts from p, minimum image along
    the periodic directions of the plane."""
    d = np.asarray(pts, dtype=float) - p
    for k, ax in enumerate(plane):
        if box.periodic[ax]:
            d[..., k] -= box.span[ax] * np.round(d[..., k] / box.span[ax])
    return d


def row_layer(box, axis, side, radius, gap=0.01):
    """A floor of straight rows along x on the wall normal to axis (y or
    z): as many spheres per row and rows as fit at clearance gap, evenly
    spaced (s_x, s_r).  Every point of the plane lies within
    sqrt(s_x^2 + s_r^2)/2 of a centre whatever the rows' shifts along x,
    which must stay below 2a: no sphere of radius a passes even when the
    rows slide past each other (a floor carried by a shear along x across
    the rows: gravity along the vorticity).  Returns the centres and the
    radii."""
    other = 3 - axis                      # the in-plane direction besides x
    n = [int(box.span[k] // (2 * radius * (1 + gap))) for k in (0, other)]
    sx, sr = box.span[0] / max(n[0], 1), box.span[other] / max(n[1], 1)
    if min(n) < 1 or np.hypot(sx, sr) / 2 >= 2 * radius:
        raise RuntimeError(f"no row floor closes a wall of {box.span[0]} x"
                           f" {box.span[other]} for radius {radius}")
    gx, gr = np.meshgrid(box.lo[0] + (np.arange(n[0]) + 0.5) * sx,
                         box.lo[other] + (np.arange(n[1]) + 0.5) * sr,
                         indexing="ij")
    x = np.zeros((n[0] * n[1], 3))
    x[:, 0], x[:, other] = gx.ravel(), gr.ravel()
    height = radius * (1 + gap)
    x[:, axis] = (box.lo[axis] + height if side == "lower"
                  else box.lo[axis] + box.span[axis] - height)
    return x, np.full(len(x), float(radius))


def _plane_grid(box, plane, spacing):
    """Cell centres of a grid of about the given spacing over the plane."""
    n = [max(2, int(np.ceil(box.span[ax] / spacing))) for ax in plane]
    return np.stack(np.meshgrid(
        *[box.lo[ax] + (np.arange(m) + 0.5) * box.span[ax] / m
          for ax, m in zip(plane, n)], indexing="ij"), -1).reshape(-1, 2)


def wall_layer(box, axis, side, radius, coverage, seed=1, gap=0.01,
               jammed=False, pass_radius=None):
    """Spheres touching (at clearance gap) the wall normal to axis on side
    'lower' or 'upper', placed by random sequential addition in the plane
    up to an area coverage (fraction of the wall covered by their discs;
    random sequential addition jams near 0.547).  Returns the centres and
    the radii.

    jammed: go on until no disc fits anywhere (holes found on a grid of
    spacing radius/10), so that no sphere of the same radius can pass
    through the layer: a floor under an open top (resuspension).  A
    smaller sphere can still pass a jammed layer (a hole admits one of
    radius up to radius(1 + gap)): with pass_radius, the holes where a
    sphere of that radius would pass are plugged with smaller spheres
    centred in the plane of the layer, each as large as its hole allows,
    until none is left (the grid's resolution, spacing/sqrt 2, is taken
    off pass_radius): a floor for polydisperse free spheres."""
    rng = np.random.default_rng(seed + 7919 * (side == "upper") + 104729 * axis)
    plane = [k for k in range(3) if k != axis]
    area = box.span[plane[0]] * box.span[plane[1]]
    target = int(coverage * area / (np.pi * radius**2))
    clearance = 2 * radius + gap * radius
    pts = []
    for attempt in range(200 * max(target, 1)):
        if len(pts) >= target and not jammed:
            break
        p = box.lo[plane] + rng.random(2) * box.span[plane]
        if pts and (np.sqrt((_plane_offsets(pts, p, box, plane)**2).sum(1))
                    < clearance).any():
            continue
        pts.append(p)
    radii = [radius] * len(pts)
    if jammed:
        # room: distance from each grid point to the nearest sphere surface
        grid = _plane_grid(box, plane, radius / 10)
        room = np.full(len(grid), np.inf)

        def carve(p, r):
            np.minimum(room, np.sqrt((_plane_offsets(grid, p, box, plane)**2)
                                     .sum(1)) - r, out=room)

        def add(p, r):
            carve(p, r)
            pts.append(p)
            radii.append(r)

        for p in pts:
            carve(p, radius)
        resolution = radius / 10 / np.sqrt(2)
        while True:
            k = int(np.argmax(room))
            if room[k] >= radius * (1 + gap):
                add(grid[k], radius)
            elif pass_radius and room[k] >= pass_radius - resolution:
                add(grid[k], room[k] - gap * radius)
            else:
                break
    x = np.zeros((len(pts), 3))
    if pts:
        x[:, plane] = pts
    height = radius * (1 + gap)
    x[:, axis] = (box.lo[axis] + height if side == "lower"
                  else box.lo[axis] + box.span[axis] - height)
    return x, np.array(radii, dtype=float)
