"""Suspension rheology from the particle time series (thesis 1, section
2.7): volume fraction profile phi(y) (eq 2.70), particle velocity profile
u_p(y) (eq 6.4), core volume fraction (eq 2.71), core shear rate, particle
stresses Sigma^hp and Sigma^c (eqs 2.73-2.74) and the core viscosity
(eq 2.76), with time averages and their error bars.

Geometry: a plane Couette cell (walls normal to `normal`, y) or a
Lees-Edwards box; flow along x, vorticity along z; stresses in run units.
"""

import os
import re

import numpy as np


def slab_volume(yc, a, lo, hi):
    """Volume of spheres (centres yc, radii a) between planes y = lo, hi:
    pi int (a^2 - (y - yc)^2) dy over the overlap (exact indicator of
    eq 2.70, no sampling)."""
    u0 = np.clip(lo - yc, -a, a)
    u1 = np.clip(hi - yc, -a, a)
    F = lambda u: a**2 * u - u**3 / 3.0  # noqa: E731
    return np.pi * (F(u1) - F(u0))


def symm6_to_tensor(s):
    """(..., 6) xx xy xz yy yz zz -> (..., 3, 3)."""
    t = np.empty(s.shape[:-1] + (3, 3))
    idx = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]
    for k, (i, j) in enumerate(idx):
        t[..., i, j] = s[..., k]
        t[..., j, i] = s[..., k]
    return t


class CouetteSeries:
    """The particle series of a Couette run with the cell's geometry.

    data: dict of arrays as in postProcessing/particles.h5 (time,
    position, velocity, radius, stresslet, dipoleTrace, contactStresslet).
    """

    def __init__(self, data, lo, span, eta, layer, normal=1, flow=0,
                 shear_rate=None):
        self.t = np.asarray(data["time"])
        self.x = np.asarray(data["position"])
        self.u = np.asarray(data["velocity"])
        self.a = np.asarray(data["radius"])
        self.S = np.asarray(data["stresslet"])
        self.s = np.asarray(data["dipoleTrace"])
        zero = np.zeros_like(self.S)
        self.Sc = np.asarray(data.get("contactStresslet", zero))
        self.lo = np.asarray(lo, float)
        self.span = np.asarray(span, float)
        self.eta = eta
        self.layer = layer
        self.n = normal
        self.f = flow
        # A Lees-Edwards box imposes its mean velocity gradient
        self.imposed_rate = shear_rate
        self.lees_edwards = shear_rate is not None
        self.area = np.prod(self.span) / self.span[normal]
        self.core = (self.lo[normal] + layer,
                     self.lo[normal] + self.span[normal] - layer)
        if self.core[1] <= self.core[0]:
            raise ValueError(
                f"wall layer {layer} leaves no core in a cell of height"
                f" {self.span[normal]}")

    @staticmethod
    def from_h5(path, **geometry):
        import h5py
        with h5py.File(path, "r") as f:
            data = {k: f[k][...] for k in f.keys()}
        return CouetteSeries(data, **geometry)

    def images(self, yc):
        """(centres, flow velocity shift) of the particles and, in a
        Lees-Edwards box, of their images one period down and up (-+
        gammaDot L_y): a sphere across the sheared faces counts whole."""
        L = self.span[self.n]
        du = (self.imposed_rate or 0.0) * L
        shifts = (0, -1, 1) if self.lees_edwards else (0,)
        return [(yc + k * L, k * du) for k in shifts]

    def slab(self, yc, lo, hi):
        """Particle volume between the planes y = lo, hi, images included."""
        return sum(slab_volume(y, self.a, lo, hi) for y, _ in self.images(yc))

    # Profiles ----------------------------------------------------------

    def profiles(self, bins, steps):
        """phi(y) (eq 2.70) and the indicator-weighted particle velocity
        u_p(y) (eq 6.4) averaged over the records `steps`."""
        edges = np.linspace(self.lo[self.n], self.lo[self.n] + self.span[self.n],
                            bins + 1)
        vol = np.zeros(bins)
        mom = np.zeros(bins)
        for k in steps:
            for y, du in self.images(self.x[k, :, self.n]):
                for b in range(bins):
                    v = slab_volume(y, self.a, edges[b], edges[b + 1])
                    vol[b] += v.sum()
                    mom[b] += (v * (self.u[k, :, self.f] + du)).sum()
        dy = np.diff(edges)
        phi = vol / (len(steps) * self.area * dy)
        up = np.where(vol > 0, mom / np.maximum(vol, 1e-300), np.nan)
        return 0.5 * (edges[1:] + edges[:-1]), phi, up

    def stress_profiles(self, bins, steps):
        """Sigma^hp(y) and Sigma^c(y) (eqs 6.18-6.19, without the fluid
        terms): each particle's stresslet spread uniformly over its volume
        and averaged over the bins, then over the records `steps`; 3x3
        tensors per bin."""
        edges = np.linspace(self.lo[self.n], self.lo[self.n] + self.span[self.n],
                            bins + 1)
        dy = np.diff(edges)
        volume = 4.0 / 3.0 * np.pi * self.a**3
        hp = np.zeros((bins, 3, 3))
        c = np.zeros((bins, 3, 3))
        for k in steps:
            SH = symm6_to_tensor(self.S[k]) \
                + (self.s[k] / 3.0)[:, None, None] * np.eye(3)
            Sc = symm6_to_tensor(self.Sc[k])
            for b in range(bins):
                w = self.slab(self.x[k, :, self.n], edges[b],
                              edges[b + 1]) / volume
                hp[b] += np.einsum("p,pij->ij", w, SH)
                c[b] += np.einsum("p,pij->ij", w, Sc)
        scale = 1.0 / (len(steps) * self.area * dy)[:, None, None]
        return hp * scale, c * scale

    # Core quantities per record -----------------------------------------

    def in_core(self, k):
        y = self.x[k, :, self.n]
        return (y > self.core[0]) & (y < self.core[1])

    def core_volume_fraction(self, k):
        """Eq 2.71: particle volume between the core planes."""
        v = self.slab(self.x[k, :, self.n], *self.core)
        return v.sum() / (self.area * (self.core[1] - self.core[0]))

    def wall_volume_fraction(self, k):
        """Particle volume in the two wall layers over their volume (the
        wall depletion of chapter 5); NaN without layers."""
        lo, hi = self.lo[self.n], self.lo[self.n] + self.span[self.n]
        y, layers = self.x[k, :, self.n], 2 * self.layer * self.area
        v = slab_volume(y, self.a, lo, self.core[0]) \
            + slab_volume(y, self.a, self.core[1], hi)
        return v.sum() / layers if layers > 0 else np.nan

    def core_shear_rate(self, k):
        """Slope of u_x(y) of the core's particles (or the imposed rate)."""
        if self.lees_edwards:
            return self.imposed_rate
        c = self.in_core(k)
        if c.sum() < 2:
            return np.nan
        return np.polyfit(self.x[k, c, self.n], self.u[k, c, self.f], 1)[0]

    def core_stresses(self, k):
        """Sigma^hp and Sigma^c (eqs 2.73-2.74) of the particles centred in
        the core, as 3x3 tensors."""
        c = self.in_core(k)
        V = self.area * (self.core[1] - self.core[0])
        SH = symm6_to_tensor(self.S[k, c]) \
            + (self.s[k, c] / 3.0)[:, None, None] * np.eye(3)
        Sc = symm6_to_tensor(self.Sc[k, c])
        return SH.sum(0) / V, Sc.sum(0) / V

    def series(self):
        """Per record: core shear rate, phi_core, Sigma^hp, Sigma^c."""
        g = np.array([self.core_shear_rate(k) for k in range(len(self.t))])
        phi = np.array([self.core_volume_fraction(k) for k in range(len(self.t))])
        hp, c = zip(*(self.core_stresses(k) for k in range(len(self.t))))
        return g, phi, np.array(hp), np.array(c)


def block_mean(x, blocks=5):
    """Mean and standard error from `blocks` consecutive block means (the
    records are correlated over a strain unit or so)."""
    x = np.asarray(x, float)
    x = x[np.isfinite(x)]
    if len(x) < blocks:
        return (x.mean() if len(x) else np.nan), np.nan
    means = np.array([b.mean() for b in np.array_split(x, blocks)])
    return means.mean(), means.std(ddof=1) / np.sqrt(blocks)


def autocorrelation_time(x, dx):
    """Integrated autocorrelation time tau = dx (1/2 + sum_k rho_k) of an
    evenly sampled series, the sum cut at the first negative rho_k; a
    series of length T holds about T/(2 tau) independent samples."""
    x = np.asarray(x, float)
    x = x[np.isfinite(x)] - np.nanmean(x)
    f = np.fft.rfft(x, 2 * len(x))  # zero-padded: no wrap-around
    rho = np.fft.irfft(f * f.conj())[:len(x)] / (x.var() * len(x))
    cut = np.argmax(rho < 0) if (rho < 0).any() else len(rho)
    return dx * (0.5 + rho[1:cut].sum())


def core_series(cs, series=None):
    """Per record: the core eta (eq 2.76), N1/Sigma_xy, N2/Sigma_xy and the
    contact share of Sigma_xy (eq 4.13), as the columns of an array.
    `series` is cs.series(), passed when it is at hand already."""
    g, _, hp, c = cs.series() if series is None else series
    sxy = cs.eta * g + hp[:, 0, 1] + c[:, 0, 1]
    part = hp + c
    return np.column_stack((
        sxy / (cs.eta * g), (part[:, 0, 0] - part[:, 1, 1]) / sxy,
        (part[:, 1, 1] - part[:, 2, 2]) / sxy, c[:, 0, 1] / sxy))


def core_rheology(cs, start_time, blocks=5, end_time=np.inf, series=None):
    """Time-averaged core rheology over start_time <= t < end_time (eq 2.76,
    eq 4.13): dict of (mean, standard error) of gammaDotCore, shearStress
    (Sigma_12 of eq 2.72), phiCore, etaCore, contactShare, N1, N2 and
    contact11, contact22, contact33 (Sigma^c_ii/Sigma_12), and the number
    of records.  `series` is cs.series(), passed when it is at hand
    already."""
    g, phi, hp, c = cs.series() if series is None else series
    keep = (cs.t >= start_time) & (cs.t < end_time)
    g, phi, hp, c = g[keep], phi[keep], hp[keep], c[keep]
    gm = np.nanmean(g)
    # Total shear stress of eq 2.72: fluid eta gammaDot_core + particles
    sxy = cs.eta * g + hp[:, 0, 1] + c[:, 0, 1]
    part = hp + c
    out = {
        "gammaDotCore": block_mean(g, blocks),
        "shearStress": block_mean(sxy, blocks),
        "phiCore": block_mean(phi, blocks),
        # eq 2.76 with the time averages of stress and rate
        "etaCore": (1 + (np.mean(hp[:, 0, 1] + c[:, 0, 1])) / (cs.eta * gm),
                    block_mean(sxy / (cs.eta * g), blocks)[1]),
        "contactShare": block_mean(c[:, 0, 1] / sxy, blocks),
        "N1": block_mean((part[:, 0, 0] - part[:, 1, 1]) / sxy, blocks),
        "N2": block_mean((part[:, 1, 1] - part[:, 2, 2]) / sxy, blocks),
        # The contact normal stresses over Sigma_12 (eq 4.13: hat Sigma^c_ii)
        **{f"contact{i}{i}": block_mean(c[:, i - 1, i - 1] / sxy, blocks)
           for i in (1, 2, 3)},
        "records": int(keep.sum()),
    }
    return out


def mechanical_consistency(case, start_time, end_time=np.inf):
    """Mechanical consistency over start_time <= t < end_time (thesis 1,
    Table 4.8 columns, x y z each): wall force against the particles'
    lambda (eq 4.14), lambda over the volume against the particle sum
    (eq 4.16), per-particle force and torque balance F^h + F^c = 0
    (eq 4.17).  Each column is an RMS over records (and particles) over
    the RMS of the reference, the thesis' overbar read as the mean of the
    square: the means themselves vanish (the two walls' drags cancel, and
    so do the contact forces over particles).  Returns a 4 x 3 array."""
    import h5py
    from fdmPost.particleCase import momentum_balance
    with h5py.File(f"{case}/postProcessing/particles.h5", "r") as f:
        t = np.asarray(f["time"])
        keep = np.flatnonzero((t >= start_time) & (t < end_time))
        Fh, Fc = f["force"][keep], f["contactForce"][keep]
        Th, Tc = f["torque"][keep], f["contactTorque"][keep]
    mb = momentum_balance(case)
    late = (mb["time"] >= start_time) & (mb["time"] < end_time)
    lamV, parts, wall = (mb[k][late]
                         for k in ("lambdaV", "lambdaParts", "wall"))

    def rms(a):
        """RMS over all axes but the last (the components)."""
        return np.sqrt((a ** 2).mean(axis=tuple(range(a.ndim - 1))))

    return np.array([rms(wall + parts) / rms(wall),
                     rms(lamV - parts) / rms(lamV),
                     rms(Fh + Fc) / rms(Fc), rms(Th + Tc) / rms(Tc)])


def maron_pierce(phi, alpha=0.803, phi_j=0.59):
    """Thesis fit eq 4.12: eta = alpha/(1 - phi/phi_J)^2."""
    return alpha / (1 - np.asarray(phi) / phi_j) ** 2


def number(text, key):
    """The value of the first "key value;" entry of an OpenFOAM dictionary
    text that begins a line (at any depth)."""
    return float(re.search(rf"^\s*{key}\s+([^;\s]+)\s*;", text, re.M).group(1))


def vector(text, key):
    """The first "key (x y z);" entry of an OpenFOAM dictionary text."""
    m = re.search(rf"\b{key}\s+\(([^)]*)\)\s*;", text)
    return np.array(m.group(1).split(), float)


def run_description(path):
    """The run attributes of a particles.h5 (written by fdmSuspensionFoam
    at its first record; README "Output"): text attributes as str, numbers
    as floats or float arrays (boxMin, boxMax, viscosity, shearRate,
    meshSpacing, ...).  None for a file written before they existed."""
    import h5py
    with h5py.File(path, "r") as f:
        if "boxMin" not in f.attrs:
            return None
        out = {}
        for k, v in f.attrs.items():
            if isinstance(v, bytes):
                out[k] = v.decode()
            elif isinstance(v, str):
                out[k] = v
            else:
                v = np.asarray(v, float)
                out[k] = v.item() if v.size == 1 else v
        return out


def _description_from_dictionaries(case):
    """Box, viscosity and wall shear rate of a channel case whose
    particles.h5 predates the run attributes: Lx Ly Lz of
    system/blockMeshDict (box from the origin), rho nu of
    constant/transportProperties, topWall and bottomWall speeds of 0/U."""
    def read(name):
        with open(f"{case}/{name}") as f:
            return f.read()

    mesh = read("system/blockMeshDict")
    L = np.array([number(mesh, k) for k in ("Lx", "Ly", "Lz")])
    transport = read("constant/transportProperties")
    U0 = read("0/U")

    def speed(patch):
        block = U0[U0.index(patch):]
        return float(re.search(r"uniform\s*\(\s*(\S+)", block).group(1))

    return {"boxMin": np.zeros(3), "boxMax": L,
            "viscosity": number(transport, "rho") * number(transport, "nu"),
            "shearRate": abs(speed("topWall") - speed("bottomWall")) / L[1],
            "meshSpacing": L[0] / number(mesh, "nx")}


def series_path(case):
    """The particles.h5 of a case directory, or of a particle checkpoint
    (fdmPost.checkpoint save --particles: the series of every segment)."""
    kept = f"{case}/particles.h5"
    return kept if os.path.isfile(kept) else \
        f"{case}/postProcessing/particles.h5"


def case_description(case):
    """The run description of a case directory (or checkpoint): its
    particles.h5's attributes, or for a file without them the case's
    dictionaries."""
    return (run_description(series_path(case))
            or _description_from_dictionaries(case))


def channel_case(case, layer):
    """The particle series of a channel case directory (walls normal to y)
    with its run description (case_description: box, viscosity eta, wall
    shear rate, mesh spacing).  Returns (series, box edges L, description)."""
    path = series_path(case)
    run = case_description(case)
    lo = np.asarray(run["boxMin"], float)
    L = np.asarray(run["boxMax"], float) - lo
    cs = CouetteSeries.from_h5(
        path, lo=lo, span=L, eta=run["viscosity"], layer=layer,
        shear_rate=run["shearRate"] if lees_edwards(run) else None)
    return cs, L, run


def lees_edwards(run):
    """Whether a run is in a Lees-Edwards box (periodic along y, sheared)."""
    return bool(run.get("periodic", np.zeros(3))[1]) and run["shearRate"] > 0


def couette_case(case, layer):
    """The particle series of a Couette case directory (channel_case) and
    its imposed shear rate |U_top - U_bottom|/L_y."""
    cs, _, run = channel_case(case, layer)
    return cs, run["shearRate"]


def morris_boulay_normal(phi, component, phi_m=0.68, Kn=0.75, l2=0.8,
                         l3=0.5):
    """Normal viscosity eta_ii = lambda_i K_n r^2/(1 - r)^2, r = phi/phi_m,
    lambda = (1, l2, l3): Morris & Boulay (1999) with their published
    constants (particle normal stress -eta_n gammaDot diag(1, l2, l3))."""
    r = np.asarray(phi, float) / phi_m
    return {1: 1.0, 2: l2, 3: l3}[component] * Kn * r**2 / (1 - r) ** 2


def morris_boulay(phi, phi_m=0.68, Kn=0.75, Ks=0.1, l2=0.8, l3=0.5):
    """Morris & Boulay (1999): relative shear viscosity and the normal
    stress differences over the shear stress, N1/Sigma12 = -(1 - l2)
    eta_n/eta_s, N2/Sigma12 = -(l2 - l3) eta_n/eta_s (eta_n:
    morris_boulay_normal, component 1)."""
    r = np.asarray(phi) / phi_m
    eta_n = morris_boulay_normal(phi, 1, phi_m, Kn)
    eta_s = 1 + 2.5 * phi / (1 - r) + Ks * r**2 / (1 - r) ** 2
    return eta_s, -(1 - l2) * eta_n / eta_s, -(l2 - l3) * eta_n / eta_s
