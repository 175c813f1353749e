"""Reference values for a FREE (force- and torque-free) rigid sphere in simple
shear u = gdot*y*e_x above ONE plane wall y = 0 (unbounded fluid, Stokes flow).

Sphere radius a, centre height d = a(1 + eps), viscosity eta.

free_sphere_velocity(eps) -> (U_x/(gdot a), Omega_z/gdot)
sangani_stresslet(eps)    -> S_xy / ((10/3) pi eta a^3 gdot)

Construction (this module; no published table of the free-sphere velocities
was available to us, see "Sources / precision" below)
-------------------------------------------------------------------------------
Force and torque balance on the sphere (a = gdot = eta = 1, u = U_x,
w = Omega_z; in unbounded shear u = d, w = -1/2):

    F_x = -6 pi A u - 8 pi B w + 6 pi d f_s = 0
    T_z = -8 pi B u - 8 pi C w - 4 pi t_s   = 0

  A(eps) = Y^A/(6 pi eta a)      (translation parallel to the wall, drag)
  B(eps) = Y^B/(-8 pi eta a^2)   (translation-rotation coupling, > 0)
  C(eps) = Y^C/(8 pi eta a^3)    (rotation about an axis parallel to the wall)
  f_s    = F_x/(6 pi eta a d gdot) on the FIXED sphere in the shear flow
  t_s    = -T_z/(4 pi eta a^3 gdot) on the FIXED sphere in the shear flow

Sources / precision
-------------------
[CF]  M. Chaoui & F. Feuillebois, Q. J. Mech. Appl. Math. 56 (2003) 381-410.
      * small-gap expansions (their eq. 5.4-5.6, Tables 11 and 13):
        A = sum_j phi_j eps^j ln eps + f_j eps^j, etc.  These are the
        coefficients already in src/python/fdmResistance/wall.py (thesis
        1 eq B.1).  Used for eps <= EPS_SWITCH.
      * Pade approximants in a/d (their eq. 5.1, Tables 9, 10, 12; numbers
        as transcribed in the optical tweezers toolbox, ott.drag.PadeSphere):
        used for eps > EPS_SWITCH.
      Checked here against each other (overlap 0.1 <= eps <= 0.6) and against
      bipolar-coordinate values (see CHECK_BIPOLAR): agreement ~1e-4.
[GCB] A. J. Goldman, R. G. Cox & H. Brenner, Chem. Eng. Sci. 22 (1967)
      653-660 ("... II Couette flow"), exact bipolar-coordinate solution.
      Fixed-sphere shear force / torque f_s, t_s tabulated at
      h/a = cosh(alpha), alpha = 3, 2, 1.5, 1, 0.5, 0.3, 0.1, 0.08 and the
      contact limit (f_s = 1.7005, t_s = 0.9440, O'Neill 1968), 4-5 digits
      (table values as transcribed in public code, see GCB_TABLE).
      Between the nodes f_s, t_s are interpolated by a natural cubic spline in
      alpha = arccosh(1 + eps).  Interpolation uncertainty estimated by a second,
      independent interpolant (spline in a/d, with the unbounded limit
      f_s = t_s = 1 at a/d = 0 as extra node): see __main__.
      For eps > EPS_FAR (alpha > 1) the quantities kU = (1 - U/(gdot d))/s^3 and
      kOm = (1 + 2 Omega/gdot)/s^3 (s = a/d), evaluated exactly at the GCB nodes,
      are splined in s with the far-field value 5/16 at s = 0 (GCB method of
      reflections; the nodes give k = 0.29-0.35, consistent with 5/16).
      GCB's lubrication asymptote U/(gdot d) ~ 0.7431/(0.6376 - 0.2 ln eps) and
      far field U/(gdot d) ~ 1 - (5/16)(a/d)^3 are used as checks only.

Reliable range: 1e-3 <= eps <= ~9 (alpha <= 3); beyond, far field.  At the GCB nodes the result is
as good as the 4-5 digit table (<~1e-4 rel.); between nodes the two
interpolants differ by <~1e-3 (see printed table) -- quote 0.2 % as the
uncertainty of U and Omega for 0.001 <= eps <= 5.
"""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "FDM_PROJECT_DIR", os.path.join(os.path.dirname(os.path.abspath(
        __file__)), "..", "..")), "src", "python"))
from fdmResistance.wall import CF  # noqa: E402

PI = math.pi

# ---------------------------------------------------------------- [CF] small eps
# The small-gap coefficient table of Chaoui & Feuillebois (Tables 11, 13),
# shared with the sub-grid theory tables
_CF_SMALL = CF

# ---------------------------------------------------------------- [CF] Pade in a/d
# columns: numerator, denominator coefficients of (a/d)^k, k = 0..len-1
_PADE_A = np.array([  # Table 9: f_xx^t = A
    (1.0000000000000000, 1.0000000000000000), (0.4908044826583015, -0.0716955173416986),
    (-5.9089832134410898, -6.1850607349363846), (-3.5131616290239789, -0.0643585714633657),
    (15.8084387577986870, 17.6701614844569620), (11.3026454259591860, 1.5230014975500095),
    (-25.4204600037753040, -31.0142617248087940), (-22.1471886954821320, -4.9543202018606971),
    (27.7560683302883220, 37.7762831912656620), (29.9526704556636040, 8.6523092950119675),
    (-22.5314407803093640, -34.4875979228363790), (-29.8531751466299120, -9.7299979046697445),
    (15.1220023457727230, 25.1038379563044960), (22.7366718877015930, 7.4296786502390768),
    (-9.3218018365645854, -15.2740433268190130), (-13.5313752142074220, -3.8514631848696728),
    (5.3051235132574242, 7.9065568461965441), (6.4704436057717105, 1.3310163345710742),
    (-2.4665892743626681, -3.4254372671567435), (-2.6437641575552702, -0.3653047198870711),
    (0.7771314187961326, 1.2135904493519249), (1.0105989058549130, 0.1773693978765500),
    (-0.0982971888072048, -0.3562252726334449), (-0.3696484621597229, -0.1215738645617847),
    (-0.0388403557770505, 0.0924829508022898), (0.1178052153278498, 0.0570985338450345),
    (0.0239731345108428, -0.0223176692443156), (-0.0296092414452849, -0.0163260360921365),
    (-0.0051932812835911, 0.0049336345493305), (0.0051959782885691, 0.0024740275532692),
    (0.0004467306955688, -0.0007151856250505), (-0.0005090795488796, -0.0001540322172991),
    (-0.0002283634635380, -0.0000432110135947), (0.0001112835192454, 0.0001218740679878),
    (0.0001947778117732, 0.0000315676817145), (-0.0000777784823648, -0.0000901590239588),
    (-0.0000608432770399, 0.0000136958535388), (0.0000204062418828, 0.0000157506941068),
    (0.0000083269893273, -0.0000020983554747)])
_PADE_B = np.array([  # Table 10: c_yx^t = B
    (0.0, 1.0000000000000000), (0.0, 0.7530928302472617), (0.0, -5.6876478972560180),
    (0.0, -4.6001625314679311), (0.0937500000000000, 14.7688208805162220),
    (0.0354462028356808, 12.9110364270167750), (-0.5794683008061320, -23.2985876342930280),
    (-0.1591806968088001, -22.2529692918405930), (1.6842716605855981, 25.2949343649485390),
    (0.2590332240370517, 26.5642830424431010), (-3.0399314551829391, -20.7275046216581170),
    (-0.0645486159987336, -23.5088999441590650), (3.7757798299644287, 14.1983612865681630),
    (-0.4424917088086144, 16.1120087317810350), (-3.3696060827666314, -8.9979341047037718),
    (0.8677197790058497, -8.7887426960210036), (2.1860298844040456, 5.4292449518028008),
    (-0.8761868169616034, 3.8751690379208039), (-1.0192554133470433, -2.9222312270789970),
    (0.5698017880599795, -1.3986551339586100), (0.3294504504024299, 1.2921105899769376),
    (-0.2542214172218537, 0.4215695555772232), (-0.0689937284425019, -0.4481976016305430),
    (0.0806987107131334, -0.1083283065391708), (0.0097549766071051, 0.1241851919484450),
    (-0.0201417209825254, 0.0237060050706818), (-0.0030113344253303, -0.0323930735345231),
    (0.0057346579076300, -0.0041438522586214), (0.0016237250709576, 0.0102787025544772),
    (-0.0024134043883321, 0.0000794121908992), (-0.0002857520641057, -0.0034959095257686),
    (0.0009078237305454, 0.0004233705581285), (-0.0001481233143099, 0.0009223046179774),
    (-0.0002045995112581, -0.0002180191880766), (0.0001062038845836, -0.0001333546201417),
    (0.0000104657146092, 0.0000637844613933), (-0.0000268057642468, -0.0000096296739955),
    (0.0000075227992668, -0.0000116959858281), (-0.0000007108447371, -0.0000022007617119)])
_PADE_C = np.array([  # Table 12: c_yy^r = C
    (1.0000000000000000, 1.0000000000000000), (-7.5838964357215906, -7.5838964357215906),
    (-4.5207915154522071, -4.5207915154522071), (67.1126014324299830, 66.8001014324299830),
    (36.4257465110401740, 38.7957141472031710), (-227.5434101958574600, -226.1306628472786400),
    (-148.8868387007147800, -169.9181203983491500), (425.6988546482454000, 414.7601777953258900),
    (322.9424771530482900, 394.3029642171122800), (-511.7610421660615400, -469.1169610571635100),
    (-433.3830394473827700, -568.1911141292858900), (435.5861115275547500, 347.3528087832515900),
    (393.9363791481090400, 559.5050863555197800), (-289.7726603465931700, -177.4883257131791400),
    (-257.2538676239515800, -401.8573592578553100), (169.8215795297231200, 74.3740852975847130),
    (127.1823575386862300, 223.4938946349586800), (-94.8269310329440460, -37.7348164935060740),
    (-50.9124722094202300, -103.2373672310176600), (48.3584924238158750, 22.7665029241817970),
    (18.1172702688163230, 42.6727488787292800), (-20.2524941264342860, -10.3674675169848310),
    (-6.1301321875823511, -16.2280741114435580), (6.4841086908589745, 2.4385277545819979),
    (1.8629524433630982, 5.2925499604112982), (-1.6546410482740759, 0.0727424296455357),
    (-0.4418054918716946, -1.2955329800216224), (0.4474639134552081, -0.1458737659618503),
    (0.0855305535945268, 0.2286349421460986), (-0.1492902692086656, -0.0234720672648906),
    (-0.0198209692030472, -0.0497699599389199), (0.0387758704005577, 0.0277057758052075),
    (-0.0004298844398339, 0.0127677985914393), (-0.0066929563118655, -0.0062955861393704),
    (0.0026047337056495, -0.0007922566399001), (0.0008666597716715, 0.0007258586021021),
    (-0.0005406029268510, 0.0000013255383408), (-0.0000112860358089, 0.0000755918974562)])

EPS_SWITCH = 0.3   # CF small-gap expansion below, CF Pade above

# bipolar-coordinate values (h/a, A, (4/3)B, (4/3)C) from the public table
# haloless/StupidCFD StokesianDynBox/WallBody/WallSphereResTab.csv (O'Neill /
# Dean & O'Neill series); used only as an independent check.
CHECK_BIPOLAR = [(1.01, 3.422533, 0.36868987, 2.9877302),
                 (1.1, 2.264303, 0.11835113, 1.9398016),
                 (1.5, 1.5957066, 0.022098616, 1.4806607),
                 (1.7, 1.4854156, 0.012967281, 1.4284548)]

# [GCB] Table: h/a, f_s, t_s (fixed sphere in shear); h/a = cosh(alpha)
GCB_TABLE = np.array([
    (1.0, 1.7005, 0.94399),
    (1.003202, 1.6982, 0.94427),   # alpha = 0.08
    (1.005004, 1.6969, 0.94442),   # alpha = 0.1
    (1.0453, 1.6682, 0.94769),     # alpha = 0.3
    (1.1276, 1.6160, 0.95374),     # alpha = 0.5
    (1.5431, 1.4391, 0.97419),     # alpha = 1
    (2.3524, 1.2780, 0.99010),     # alpha = 1.5
    (3.7622, 1.1671, 0.99711),     # alpha = 2
    (10.0677, 1.0587, 0.99981)])   # alpha = 3


def _pade(tab, s):
    k = np.arange(tab.shape[0])
    p = s ** k
    return float(np.dot(tab[:, 0], p) / np.dot(tab[:, 1], p))


def resistance(eps):
    """(A, B, C) = (Y^A/(6 pi a), Y^B/(-8 pi a^2), Y^C/(8 pi a^3)), [CF]."""
    eps = float(eps)
    if eps <= EPS_SWITCH:
        le = math.log(eps)
        c = _CF_SMALL
        A = sum(c["phi_t"][j] * eps**j * le + c["f_t"][j] * eps**j for j in range(6))
        B = sum(c["gam_t"][j] * eps**j * le + c["c_t"][j] * eps**j for j in range(6))
        C = sum(c["gam_r"][j] * eps**j * le + c["c_r"][j] * eps**j for j in range(6))
        return A, B, C
    s = 1.0 / (1.0 + eps)
    return _pade(_PADE_A, s), _pade(_PADE_B, s), _pade(_PADE_C, s)


def _natural_spline(x, y):
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    n = len(x)
    h = np.diff(x)
    M = np.zeros((n, n))
    r = np.zeros(n)
    M[0, 0] = M[-1, -1] = 1.0
    for i in range(1, n - 1):
        M[i, i - 1] = h[i - 1]
        M[i, i] = 2 * (h[i - 1] + h[i])
        M[i, i + 1] = h[i]
        r[i] = 6 * ((y[i + 1] - y[i]) / h[i] - (y[i] - y[i - 1]) / h[i - 1])
    m = np.linalg.solve(M, r)

    def f(xq):
        i = int(np.clip(np.searchsorted(x, xq) - 1, 0, n - 2))
        t0, t1 = x[i + 1] - xq, xq - x[i]
        return (m[i] * t0**3 + m[i + 1] * t1**3) / (6 * h[i]) \
            + (y[i] / h[i] - m[i] * h[i] / 6) * t0 + (y[i + 1] / h[i] - m[i + 1] * h[i] / 6) * t1
    return f


_ALPHA = np.arccosh(GCB_TABLE[:, 0])
_FS_A = _natural_spline(_ALPHA, GCB_TABLE[:, 1])
_TS_A = _natural_spline(_ALPHA, GCB_TABLE[:, 2])
_S = np.concatenate([[0.0], 1.0 / GCB_TABLE[::-1, 0]])
_FS_S = _natural_spline(_S, np.concatenate([[1.0], GCB_TABLE[::-1, 1]]))
_TS_S = _natural_spline(_S, np.concatenate([[1.0], GCB_TABLE[::-1, 2]]))


def shear_force_torque(eps, interpolant="alpha"):
    """Fixed-sphere shear force/torque (f_s, t_s) [GCB], interpolated.

    interpolant "alpha": natural cubic spline in alpha = arccosh(1+eps) (default);
    "s": natural cubic spline in a/d including the unbounded limit (check only).
    """
    if interpolant == "alpha":
        al = math.acosh(1.0 + eps)
        return _FS_A(al), _TS_A(al)
    s = 1.0 / (1.0 + eps)
    return _FS_S(s), _TS_S(s)


def _node_k():
    """kU = (1 - U/(gdot d))/s^3, kOm = (1 + 2 Omega/gdot)/s^3 at the GCB nodes
    (s = a/d), from the exact balance; k -> 5/16 as s -> 0 [GCB far field]."""
    rows = [(0.0, 5 / 16, 5 / 16)]
    for ha, f, t in GCB_TABLE[:0:-1]:
        if ha < 1.1:
            continue
        u, w = free_sphere_velocity(ha - 1, fs_ts=(f, t))
        s = 1 / ha
        rows.append((s, (1 - u * s) / s**3, (1 + 2 * w) / s**3))
    rows = np.array(rows)
    return _natural_spline(rows[:, 0], rows[:, 1]), _natural_spline(rows[:, 0], rows[:, 2])


EPS_FAR = 0.5431   # alpha = 1: beyond it interpolate kU, kOm in a/d


def free_sphere_velocity(eps, interpolant="alpha", fs_ts=None):
    """Free sphere in wall shear: (U_x/(gdot a), Omega_z/gdot).

    Force/torque-free balance with [CF] resistances A, B, C and [GCB]
    fixed-sphere shear force/torque f_s, t_s (see module docstring).
    Unbounded limit: (d/a, -1/2).  Estimated uncertainty 0.2 % for
    1e-3 <= eps <= 5 (dominated by the interpolation of the 4-5 digit GCB table).
    """
    if fs_ts is None and interpolant == "alpha" and eps > EPS_FAR:
        s = 1.0 / (1.0 + eps)
        return (1 + eps) * (1 - _KU(s) * s**3), -0.5 * (1 - _KOM(s) * s**3)
    A, B, C = resistance(eps)
    f, t = fs_ts if fs_ts is not None else shear_force_torque(eps, interpolant)
    d = 1.0 + eps
    M = np.array([[6 * A, 8 * B], [8 * B, 8 * C]])
    u, w = np.linalg.solve(M, np.array([6 * d * f, -4 * t]))
    return float(u), float(w)


_KU, _KOM = _node_k()


def sangani_stresslet(eps):
    """Sangani et al. (2011) fit (thesis 1, eq. 4.9).

    S_xy/((10/3) pi eta a^3 gdot), Y = 1 + eps:
      1/[1 - 15/(16Y^3) + 1/Y^5 - 0.65/Y^7]                         0 < 1/Y <= 0.85
      (0.847 L - 0.41 + 1.44 eps L - 0.3 eps)/(0.2 L + 0.6376), L = ln(1/eps)   1/Y > 0.85
    Precision not stated in the thesis (fit to Lamb-multipole results).
    """
    Y = 1.0 + eps
    if 1.0 / Y <= 0.85:
        return 1.0 / (1 - 15 / (16 * Y**3) + 1 / Y**5 - 0.65 / Y**7)
    L = math.log(1.0 / eps)
    return (0.847 * L - 0.41 + 1.44 * eps * L - 0.3 * eps) / (0.2 * L + 0.6376)


def _checks():
    print("== check 1: [CF] small-gap expansion vs [CF] Pade (A, B, C)")
    for eps in (0.1, 0.2, 0.3, 0.45, 0.6):
        le = math.log(eps)
        c = _CF_SMALL
        sm = [sum(c[p][j] * eps**j * le + c[q][j] * eps**j for j in range(6))
              for p, q in (("phi_t", "f_t"), ("gam_t", "c_t"), ("gam_r", "c_r"))]
        s = 1 / (1 + eps)
        pa = [_pade(T, s) for T in (_PADE_A, _PADE_B, _PADE_C)]
        print("  eps=%5.2f small: %.6f %.6f %.6f  pade: %.6f %.6f %.6f" % (eps, *sm, *pa))
    print("== check 2: resistance() vs bipolar table (StupidCFD WallSphereResTab.csv)")
    for ha, a, b43, c43 in CHECK_BIPOLAR:
        A, B, C = resistance(ha - 1)
        print("  h/a=%5.3f  A %.6f/%.6f  B %.6f/%.6f  C %.6f/%.6f" %
              (ha, A, a, B, 0.75 * b43, C, 0.75 * c43))
    print("== check 3: lubrication limit vs GCB asymptote U/(gdot d) ~ 0.7431/(0.6376-0.2 ln eps)")
    print("   leading coefficient from the balance: 0.2*(2 f_s + t_s/3) at contact = %.5f (GCB 0.7431)"
          % (0.2 * (2 * 1.7005 + 0.9440 / 3)))
    # denominator constant from the GCB (1967 part I) resistance constants
    a0, b0, c0 = 0.9588, -0.1895, 0.3817
    D2 = 48 * (8 / 15) * (2 / 5) - 64 * 0.01
    D1 = 48 * ((8 / 15) * c0 + (2 / 5) * a0) - 128 * 0.1 * b0
    print("   denominator constant 0.2*D1/D2 with GCB-I constants = %.4f (GCB 0.6376)" % (0.2 * D1 / D2))
    for eps in (1e-4, 1e-3, 1e-2):
        u, w = free_sphere_velocity(eps)
        print("   eps=%g  U/(gdot d)=%.4f   GCB asymptote %.4f" %
              (eps, u / (1 + eps), 0.7431 / (0.6376 - 0.2 * math.log(eps))))
    print("   (GCB asymptote keeps only the leading-log numerator: O(1/ln eps) relative error)")
    print("== check 4: far field U/(gdot d) vs 1-(5/16)(a/d)^3; Omega/gdot vs -(1/2)(1-(5/16)(a/d)^3)")
    for eps in (2.0, 5.0, 9.0):
        u, w = free_sphere_velocity(eps)
        s = 1 / (1 + eps)
        print("   eps=%g  U/(gdot d)=%.5f (%.5f)  Omega=%.5f (%.5f)  k_Omega=(1+2 Omega)/s^3=%.3f"
              % (eps, u * s, 1 - 5 / 16 * s**3, w, -0.5 * (1 - 5 / 16 * s**3), (1 + 2 * w) / s**3))
    print("== check 5: interpolation uncertainty of f_s, t_s (spline in alpha vs spline in a/d)")
    for eps in (0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.8, 1, 2, 3, 5):
        f1, t1 = shear_force_torque(eps, "alpha")
        f2, t2 = shear_force_torque(eps, "s")
        u1, w1 = free_sphere_velocity(eps, "alpha")
        u2, w2 = free_sphere_velocity(eps, "s")
        print("   eps=%5.2f f_s %.4f/%.4f t_s %.5f/%.5f  dU/U=%.1e dOm/Om=%.1e"
              % (eps, f1, f2, t1, t2, abs(u1 / u2 - 1), abs(w1 / w2 - 1)))


if __name__ == "__main__":
    print("eps      U/(gdot a)  U/(gdot d)  Omega/gdot  S_xy/((10/3)pi eta a^3 gdot) [Sangani]")
    for eps in (0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2):
        u, w = free_sphere_velocity(eps)
        print("%-7g  %.5f     %.5f     %.5f     %.4f" % (eps, u, u / (1 + eps), w, sangani_stresslet(eps)))
    _checks()
