"""Boundary-integral reference for free rigid spheres between plane walls
(Stokes flow; an independent check of the solver, which shares nothing
with it).

Why: the thesis' channel cases (sphere at the centre of a sheared channel,
sphere in confined plane Poiseuille flow, the Bhattacharya et al. 2006 pair;
thesis 1, sections 4.1.2b, 4.1.2c, 4.1.4) are compared there with published
two-wall solutions given in figures only.  This module computes those
solutions itself.

Method (Pozrikidis 1992, ch. 4, single-layer formulation for rigid bodies):
    u(x) = u_inf(x) - 1/(8 pi eta) sum_surfaces int G(x - y) . f(y) dS(y),
    G(r) = I/|r| + r r/|r|^3,
where u_inf is an ambient Stokes flow that already satisfies the wall
conditions (plane Couette or plane Poiseuille), f is the traction exerted by
the fluid on each sphere (sigma.n, n into the fluid) and the disturbance
traction jump on each wall, which is a zero-thickness square sheet of half
width R (truncated: 4 channel widths, or 30 a for a single wall).  No-slip
on the sphere,
u = U + Omega x (x - c), and zero disturbance on the walls give one vector
equation per element; force- and torque-free conditions close the system.

Discretisation: piecewise-constant traction on triangles, collocation at
the element centres.  Sphere elements are curved (the radial projection of
an icosahedral triangle onto the sphere, exact geometry); wall elements are
flat.  Both meshes are refined adaptively so that no element is larger
than `beta` times its distance to another surface (the lubrication region of
a near-wall sphere is then resolved).  Quadrature: 3-point rule for distant
pairs, 16 sub-triangles x 6 points for near pairs, and a Duffy transform on
three sub-triangles around the collocation point for the weakly singular
self term.  The error falls as O(h^2); `reference` solves on two meshes
(h and 2h) and returns the fine solution with its error estimate.

Units: eta = 1; lengths and velocities as given.  Checked in
test_boundaryElement.py against the isolated sphere (Stokes drag, Faxen
stresslet) and the single-wall free sphere in shear (Goldman, Cox & Brenner
1967 / Chaoui & Feuillebois 2003).
"""

import numpy as np

EIGHT_PI = 8.0 * np.pi
LEVI_CIVITA = np.zeros((3, 3, 3))
LEVI_CIVITA[0, 1, 2] = LEVI_CIVITA[1, 2, 0] = LEVI_CIVITA[2, 0, 1] = 1
LEVI_CIVITA[0, 2, 1] = LEVI_CIVITA[2, 1, 0] = LEVI_CIVITA[1, 0, 2] = -1

# --------------------------------------------------------------------------
# quadrature on the unit triangle (xi, eta >= 0, xi + eta <= 1), area 1/2
# --------------------------------------------------------------------------
_Q3 = (np.array([[1 / 6, 1 / 6], [2 / 3, 1 / 6], [1 / 6, 2 / 3]]),
       np.full(3, 1 / 6))
_a, _b = 0.445948490915965, 0.091576213509771
_Q6 = (np.array([[_a, _a], [1 - 2 * _a, _a], [_a, 1 - 2 * _a],
                 [_b, _b], [1 - 2 * _b, _b], [_b, 1 - 2 * _b]]),
       0.5 * np.array([0.223381589678011] * 3 + [0.109951743655322] * 3))


def _subdivided(rule, levels):
    """`rule` applied on the 4**levels congruent sub-triangles."""
    tris = [np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])]
    for _ in range(levels):
        new = []
        for t in tris:
            m01, m12, m20 = (t[0] + t[1]) / 2, (t[1] + t[2]) / 2, \
                (t[2] + t[0]) / 2
            new += [np.array([t[0], m01, m20]), np.array([m01, t[1], m12]),
                    np.array([m20, m12, t[2]]), np.array([m12, m20, m01])]
        tris = new
    pts, wts = [], []
    for t in tris:
        pts.append(t[0] + rule[0][:, :1] * (t[1] - t[0])
                   + rule[0][:, 1:] * (t[2] - t[0]))
        wts.append(rule[1] / len(tris))
    return np.vstack(pts), np.concatenate(wts)


_QNEAR = _subdivided(_Q6, 2)


def _duffy_rule(n=10):
    """Points and weights on the unit triangle that integrate f/r around the
    centroid: three sub-triangles (centroid, vertex, vertex), each mapped
    from the unit square with the collapsed edge at the centroid."""
    g, w = np.polynomial.legendre.leggauss(n)
    g, w = (g + 1) / 2, w / 2
    u, v = np.meshgrid(g, g, indexing="ij")
    wu = np.outer(w, w) * u
    c = np.array([1 / 3, 1 / 3])
    verts = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    pts, wts = [], []
    for k in range(3):
        A, B = verts[k], verts[(k + 1) % 3]
        det = abs(np.cross(A - c, B - A))
        p = c + u[..., None] * ((A - c) + v[..., None] * (B - A))
        pts.append(p.reshape(-1, 2))
        wts.append((wu * det).ravel())
    return np.vstack(pts), np.concatenate(wts)


_QSELF = _duffy_rule()


# --------------------------------------------------------------------------
# meshes: an element is three vertices plus (centre, radius) of the sphere it
# is projected onto (radius 0: flat)
# --------------------------------------------------------------------------
def _icosahedron():
    t = (1 + 5 ** 0.5) / 2
    v = np.array([[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0],
                  [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
                  [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]], float)
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
         [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
         [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
         [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    v /= np.linalg.norm(v, axis=1)[:, None]
    return v[np.array(f)]


def _split(tri, curved):
    """Four children of each triangle (n, 3, 3); curved: midpoints on the
    unit sphere (the projection mapping is unchanged)."""
    m01, m12, m20 = ((tri[:, i] + tri[:, (i + 1) % 3]) / 2 for i in range(3))
    if curved:
        m01, m12, m20 = (m / np.linalg.norm(m, axis=1)[:, None]
                         for m in (m01, m12, m20))
    return np.concatenate([
        np.stack([tri[:, 0], m01, m20], 1), np.stack([m01, tri[:, 1], m12], 1),
        np.stack([m20, m12, tri[:, 2]], 1), np.stack([m12, m20, m01], 1)])


class Surface:
    """Elements of one body: a sphere (centre, radius) or a wall sheet."""

    def __init__(self, tri, centre=None, radius=0.0):
        self.tri = tri                    # (n, 3, 3) vertices (unit sphere
        self.centre = centre              # coordinates when curved)
        self.radius = radius

    @property
    def curved(self):
        return self.radius > 0

    def map(self, rule):
        """Quadrature points (n, q, 3) and weights (n, q) of `rule`."""
        p, w = rule
        t = self.tri
        e1, e2 = t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]
        q = (t[:, None, 0] + p[None, :, :1] * e1[:, None]
             + p[None, :, 1:] * e2[:, None])
        if not self.curved:
            jac = np.linalg.norm(np.cross(e1, e2), axis=1)[:, None]
            return q, jac * w[None]
        r = np.linalg.norm(q, axis=2)
        # area of the radial projection: a^2 q.(e1 x e2)/|q|^3
        jac = self.radius ** 2 * np.abs(
            np.einsum("nqk,nk->nq", q, np.cross(e1, e2))) / r ** 3
        return self.centre + self.radius * q / r[..., None], jac * w[None]

    def centres(self):
        return self.map((np.array([[1 / 3, 1 / 3]]), np.array([0.5])))[0][:,
                                                                          0]

    def sizes(self):
        x, w = self.map(_Q3)
        return np.sqrt(w.sum(axis=1))

    def refine(self, distance, beta, max_passes=12):
        """Split elements larger than beta * distance(centre)."""
        for _ in range(max_passes):
            big = self.sizes() > beta * distance(self.centres())
            if not big.any():
                return
            self.tri = np.concatenate([self.tri[~big],
                                       _split(self.tri[big], self.curved)])


def sphere_surface(centre, radius, level):
    tri = _icosahedron()
    for _ in range(level):
        tri = _split(tri, True)
    return Surface(tri, np.asarray(centre, float), radius)


def wall_surface(y, centre_xz, half_width, cells=4):
    """Square sheet y = const, |x - cx|, |z - cz| <= half_width; each square
    cut into four triangles about its centre (mirror-symmetric in x and z)."""
    s = np.linspace(-half_width, half_width, cells + 1)
    tri = []
    for i in range(cells):
        for j in range(cells):
            p = [np.array([centre_xz[0] + s[i + a], y,
                           centre_xz[1] + s[j + b]])
                 for a, b in ((0, 0), (1, 0), (1, 1), (0, 1))]
            m = sum(p) / 4
            tri += [[p[k], p[(k + 1) % 4], m] for k in range(4)]
    return Surface(np.array(tri))


# --------------------------------------------------------------------------
# single-layer matrix
# --------------------------------------------------------------------------
def _oseen_sum(r, w):
    """sum_q w_q G(r_q) over the quadrature axis: r (..., q, 3), w (..., q);
    returns (..., 3, 3)."""
    d = np.linalg.norm(r, axis=-1)
    inv = w / d
    return (inv.sum(axis=-1)[..., None, None] * np.eye(3)
            + np.einsum("...q,...qi,...qj->...ij", inv / d ** 2, r, r))


def single_layer(surfaces, near_factor=3.0, chunk=256, targets=None,
                 out=None):
    """Matrix (3M, 3N) of int_e G(x_m - y) dS(y) (element e of `surfaces`,
    element-ordered, and collocation point x_m: the elements' own centres,
    M = N, or the points `targets`); also the elements' centres and
    areas.  The self term (own centres only) uses the Duffy rule.  out: a
    (3M, 3N) array (a block of a larger one) to write it into."""
    xe = np.vstack([s.centres() for s in surfaces])
    xs = xe if targets is None else np.asarray(targets, float)
    far = [s.map(_Q3) for s in surfaces]
    near = [s.map(_QNEAR) for s in surfaces]
    self_ = [s.map(_QSELF) for s in surfaces]
    yq = np.vstack([f[0] for f in far])
    wq = np.vstack([f[1] for f in far])
    areas = np.concatenate([n[1].sum(axis=1) for n in near])
    size = np.sqrt(areas)
    yn = np.vstack([n[0] for n in near])
    wn = np.vstack([n[1] for n in near])
    ys = np.vstack([s[0] for s in self_])
    ws = np.vstack([s[1] for s in self_])
    n, ne = len(xs), len(xe)
    if out is None:
        out = np.empty((3 * n, 3 * ne))
    A = out.reshape(n, 3, ne, 3)
    if not np.shares_memory(A, out):
        raise ValueError("single_layer: out must reshape without a copy")
    for m0 in range(0, n, chunk):
        m = slice(m0, min(n, m0 + chunk))
        blk = _oseen_sum(xs[m, None, None, :] - yq[None], wq[None])
        A[m] = blk.transpose(0, 2, 1, 3)               # (m, i, e, j)
    # near pairs and self terms
    for m0 in range(0, n, chunk):
        rows = np.arange(m0, min(n, m0 + chunk))
        dist = np.linalg.norm(xs[rows, None, :] - xe[None, :, :], axis=-1)
        mi, ei = np.nonzero(dist < near_factor * size[None, :])
        m, e = rows[mi], ei
        selfm = (m == e) if targets is None else np.zeros(len(m), bool)
        blk = np.empty((len(m), 3, 3))
        for sel, y, w in ((~selfm, yn, wn), (selfm, ys, ws)):
            if sel.any():
                blk[sel] = _oseen_sum(xs[m[sel], None, :] - y[e[sel]],
                                      w[e[sel]])
        A[m, :, e, :] = blk
    return out, xe, areas


# --------------------------------------------------------------------------
# mobility problem
# --------------------------------------------------------------------------
def _discretise(cs, rs, walls, level, beta, half_width):
    """Surfaces of the spheres (centres cs, radii rs) and of the walls,
    refined towards the gaps; sphere surfaces first."""
    mid = np.mean(cs, axis=0)
    if len(walls) > 1:
        # channel: disturbances decay over the width H, so walls of half
        # width 4 H with elements no larger than beta H (at H = 4 a, half
        # widths 3 H and 6 H give the same Omega and S within 2e-6)
        H = max(walls) - min(walls)
        R = half_width or 4.0 * H
        cap = beta * H
    else:
        R = half_width or 30.0 * max(rs)
        cap = np.inf

    def dist_to_spheres(x, skip=None):
        d = [np.linalg.norm(x - c, axis=1) - r
             for k, (c, r) in enumerate(zip(cs, rs)) if k != skip]
        return np.min(d, axis=0) if d else np.full(len(x), np.inf)

    surfaces = []
    for k, (c, r) in enumerate(zip(cs, rs)):
        s = sphere_surface(c, r, level)

        def distance(x, k=k):
            d = [np.abs(x[:, 1] - y) for y in walls] + [dist_to_spheres(x, k)]
            return np.maximum(np.min(d, axis=0), 1e-3 * r)
        s.refine(distance, beta)
        surfaces.append(s)
    h_sphere = np.sqrt(4 * np.pi * min(rs) ** 2 / (20 * 4 ** level))
    for y in walls:
        w = wall_surface(y, (mid[0], mid[2]), R)
        w.refine(lambda x: np.minimum(
            np.maximum(dist_to_spheres(x), h_sphere / beta), cap / beta),
            beta, max_passes=40)
        surfaces.append(w)
    return surfaces


def free_spheres(spheres, walls, ambient, level=3, beta=0.5, half_width=None,
                 forces=None):
    """Velocities, angular velocities and stresslets of torque-free spheres
    between plane walls (none: unbounded fluid) in an ambient flow, each
    force-free or under a given external force.

    spheres: list of (centre (3,), radius); walls: list of wall heights y;
    ambient(x) -> u_inf (m, 3), a Stokes flow satisfying the wall
    conditions; forces: external force on each sphere (ns, 3), balanced by
    the fluid's, int f dS = -F (default none).  Returns dict U (ns, 3),
    Omega (ns, 3), S (ns, 3, 3), elements (count)."""
    cs = [np.asarray(c, float) for c, _ in spheres]
    surfaces = _discretise(cs, [r for _, r in spheres], walls, level, beta,
                           half_width)
    A, xs, areas = single_layer(surfaces)
    n = len(xs)
    ns = len(spheres)
    owner = np.concatenate([np.full(len(s.tri), k if k < ns else -1)
                            for k, s in enumerate(surfaces)])
    M = np.zeros((3 * n + 6 * ns, 3 * n + 6 * ns))
    M[:3 * n, :3 * n] = -A / EIGHT_PI
    # disturbance u - u_inf: -u_inf + rigid motion on the spheres, zero on
    # the walls (u_inf satisfies their no-slip condition)
    rhs = np.zeros(3 * n + 6 * ns)
    on_sphere = owner >= 0
    rhs[:3 * n] = -(ambient(xs) * on_sphere[:, None]).ravel()
    if forces is not None:
        for k, F in enumerate(np.asarray(forces, float)):
            rhs[3 * n + 6 * k:3 * n + 6 * k + 3] = -F
    for k in range(ns):
        idx = np.nonzero(owner == k)[0]
        rel = xs[idx] - cs[k]
        col = 3 * n + 6 * k
        # (r x) as a matrix per element: (r x v)_i = cross[p, i, j] v_j
        cross = np.einsum("ijk,pj->pik", LEVI_CIVITA, rel)
        for i in range(3):
            M[3 * idx + i, col + i] = -1.0                  # -U
            # -(Omega x r)_i = (r x Omega)_i
            M[3 * idx + i, col + 3:col + 6] = cross[:, i, :]
            # force- and torque-free: sum f A = 0, sum (r x f) A = 0
            M[col + i, 3 * idx + i] = areas[idx]
            for j in range(3):
                M[col + 3 + i, 3 * idx + j] = cross[:, i, j] * areas[idx]
    sol = np.linalg.solve(M, rhs)
    f = sol[:3 * n].reshape(n, 3)
    out = {"U": [], "Omega": [], "S": [], "elements": n}
    for k in range(ns):
        idx = owner == k
        rel = xs[idx] - cs[k]
        fa = f[idx] * areas[idx, None]
        first = rel.T @ fa                              # int r_i f_j dS
        S = 0.5 * (first + first.T) - np.trace(first) / 3 * np.eye(3)
        out["U"].append(sol[3 * n + 6 * k:3 * n + 6 * k + 3])
        out["Omega"].append(sol[3 * n + 6 * k + 3:3 * n + 6 * k + 6])
        out["S"].append(S)
    for key in ("U", "Omega", "S"):
        out[key] = np.array(out[key])
    return out


def couette(H):
    """Plane Couette flow of unit shear rate, zero at the centre y = H/2."""
    return lambda x: np.stack([x[:, 1] - H / 2, 0 * x[:, 1], 0 * x[:, 1]], 1)


def poiseuille(H):
    """Plane Poiseuille flow, centre-line velocity 1, walls y = 0 and H."""
    return lambda x: np.stack([4 * x[:, 1] * (H - x[:, 1]) / H ** 2,
                               0 * x[:, 1], 0 * x[:, 1]], 1)


def with_error_estimate(solve, level, beta):
    """solve(level, beta) at (level, beta) and on the mesh twice as coarse
    (level - 1, 2 beta).  The error falls as h^2, so the fine solution's
    error is about |fine - coarse|/3; returned as "error" (checked against
    the exact single-wall solution in test_boundaryElement.py, where it
    overestimates the true error by up to 2x)."""
    fine = solve(level, beta)
    coarse = solve(level - 1, 2 * beta)
    fine["error"] = {k: np.abs(fine[k] - coarse[k]) / 3
                     for k in ("U", "Omega", "S")}
    return fine


def reference(spheres, walls, ambient, level=3, beta=0.5, **kw):
    """free_spheres with its error estimate (with_error_estimate)."""
    return with_error_estimate(
        lambda lev, b: free_spheres(spheres, walls, ambient, level=lev,
                                    beta=b, **kw), level, beta)


def channel_spheres(H, centres, flow, radius=1.0, **kw):
    """Free spheres (radius a, centres (n, 3), walls y = 0 and y = H) in
    plane Couette ("couette", unit shear rate, zero velocity at y = H/2) or
    plane Poiseuille ("poiseuille", centre-line velocity 1) flow.  Returns
    U (n, 3), Omega (n, 3), S (n, 3, 3), elements, and the estimated
    discretisation error of each ("error")."""
    ambient = {"couette": couette, "poiseuille": poiseuille}[flow](H)
    return reference([(c, radius) for c in centres], [0.0, H], ambient, **kw)
