// Unit tests for Foam::fdm::pairSubGridMatrix (thesis 1, eqs 3.5, 3.10,
// 3.13-3.14, section 3.3.3 relations, Appendix A forms, Appendix D)

#include "pairSubGridMatrix.H"
#include "particleVelocitySystem.H"
#include "rigidBodyMoments.H"
#include "mathematicalConstants.H"
#include "point.H"
#include "tensor.H"

#include "randomGeometry.H"
#include "pairFrameShift.H"

#include <gtest/gtest.h>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

typedef fdm::pairSubGridMatrix pairMatrix;

std::mt19937 rng(20220401);

scalar uniform(const scalar lo, const scalar hi)
{
    return fdmTest::uniform(rng, lo, hi);
}

vector randomVector(const scalar s = 1)
{
    return fdmTest::randomVector(rng, s);
}

vector randomUnit()
{
    return fdmTest::randomUnit(rng);
}

symmTensor randomSymm()
{
    return symmTensor
    (
        uniform(-1, 1), uniform(-1, 1), uniform(-1, 1),
        uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)
    );
}

//- Arbitrary, all different, nonzero base functions
fdm::pairBaseFunctions arbitraryBase()
{
    fdm::pairBaseFunctions b;
    b.XA21 = uniform(-20, -1);
    b.YA21 = uniform(-5, 5);
    b.YB21 = uniform(-5, 5);
    b.XC21 = uniform(-5, 5);
    b.YC11 = uniform(-5, 5);
    b.XG11 = uniform(-5, 5);
    b.YG11 = uniform(-5, 5);
    b.YH21 = uniform(-5, 5);
    b.XP12 = uniform(-5, 5);
    b.XP21 = uniform(-5, 5);
    return b;
}

//- Near-contact values for a1 = a2 = 1 (lambda = 1): the singular terms of
//  the theory (thesis B.1), which the SG functions reduce to where the FDM
//  only captures the O(1) part.  X_21^C has no singular term besides
//  xi ln(1/xi); a small negative O(1) part (physical sign: the second
//  sphere is dragged along by a rotating first one) is added.
fdm::pairBaseFunctions nearContactBase(const scalar xi)
{
    const scalar L = std::log(1/xi);
    const scalar xiL = xi*L;
    fdm::pairBaseFunctions b;
    // 3 pi (a1 + a2) [-4 lambda^2/(1+lambda)^4 / xi - ...] at lambda = 1
    b.XA21 = 6*pi*(-0.25/xi - 0.225*L - (2.0*9/(42*16))*xiL);
    b.YA21 = 6*pi*(-L/6);
    b.XC21 = 8*pi*(0.125*xiL - 0.05);
    b.YC11 = 8*pi*(0.2*L + (47.0/250)*xiL);
    b.YB21 = 4*pi*(-0.25*L - 0.125*xiL);
    b.XG11 = 4*pi*(0.375/xi + 0.3375*L);
    b.YG11 = 4*pi*(0.125*L);
    b.YH21 = 8*pi*(0.1*L);
    b.XP12 = 4*pi*(-0.375/xi + 0.225*L);
    b.XP21 = 4*pi*(0.375/xi - 0.225*L);
    return b;
}

//- Largest magnitude of all 52 functions (reference for round-off)
scalar maxFunction(const pairMatrix& R)
{
    const pairMatrix::resistanceFunctions& f = R.functions();
    scalar m = 0;
    for (label a = 0; a < 2; ++a)
    {
        for (label b = 0; b < 2; ++b)
        {
            for
            (
                const scalar v
              : {f.XA[a][b], f.YA[a][b], f.YB[a][b], f.YBt[a][b],
                 f.XC[a][b], f.YC[a][b], f.XG[a][b], f.YG[a][b],
                 f.XGt[a][b], f.YGt[a][b], f.YH[a][b], f.YHt[a][b],
                 f.XP[a][b]}
            )
            {
                m = max(m, mag(v));
            }
        }
    }
    return m;
}

Eigen::MatrixXd toEigen(const pairMatrix& R)
{
    Eigen::MatrixXd M(12, 12);
    for (label i = 0; i < 12; ++i)
    {
        for (label j = 0; j < 12; ++j)
        {
            M(i, j) = R(i, j);
        }
    }
    return M;
}

//- Levi-Civita symbol
scalar eps3(const label i, const label j, const label k)
{
    return scalar((i - j)*(j - k)*(k - i))/2;
}

} // namespace


TEST(pairSubGridMatrix, rigidBodyMotionGivesNoCorrection)
{
    // Eq 3.13: U_a = U0 + W0 x x_a, Omega_a = W0 about any origin gives no
    // SG force, torque, stresslet or dipole trace
    for (label trial = 0; trial < 20; ++trial)
    {
        const fdm::pairBaseFunctions base = arbitraryBase();
        const scalar r = uniform(1.5, 3.5);
        const vector d = randomUnit();
        const point x1 = randomVector(5);
        const point x2 = x1 + r*d;
        const pairMatrix R(base, r, d);

        const vector U0 = randomVector();
        const vector W0 = randomVector();
        const vector U1 = U0 + (W0 ^ x1);
        const vector U2 = U0 + (W0 ^ x2);

        const scalar ref =
            maxFunction(R)*max(max(mag(U1), mag(U2)), mag(W0));
        ASSERT_GT(ref, 0);

        vector F1, T1, F2, T2;
        R.forceTorque(U1, W0, U2, W0, F1, T1, F2, T2);
        EXPECT_LT(mag(F1), 1e-12*ref);
        EXPECT_LT(mag(T1), 1e-12*ref);
        EXPECT_LT(mag(F2), 1e-12*ref);
        EXPECT_LT(mag(T2), 1e-12*ref);
        for (label a = 0; a < 2; ++a)
        {
            EXPECT_LT(mag(R.stresslet(a, U1, W0, U2, W0)), 1e-12*ref);
            EXPECT_LT(mag(R.dipoleTrace(a, U1, U2)), 1e-12*ref);
        }

        // ... while an internal mode (squeeze) is resisted
        R.forceTorque(d, Zero, -d, Zero, F1, T1, F2, T2);
        EXPECT_GT(mag(F1), 1e-3*mag(base.XA21));
    }
}


TEST(pairSubGridMatrix, pureStrainGivesNoForceOrTorque)
{
    // Appendix D.2: a pair at rest in pure strain E (full matrix 3.5 with
    // the G~, H~ columns): F_a = -sum_b [A_ab.(-E.x_b)] + sum_b G~_ab:E = 0
    // (T alike with B, H~), any origin.  Checks the G~, H~ lists of 3.3.3
    // against A, B.
    for (label trial = 0; trial < 20; ++trial)
    {
        const scalar r = uniform(1.5, 3.5);
        const vector d = randomUnit();
        const point x1 = randomVector(5);
        const point x2 = x1 + r*d;
        const pairMatrix R(arbitraryBase(), r, d);

        const symmTensor E = dev(randomSymm());
        const vector U1 = -(E & x1);
        const vector U2 = -(E & x2);

        vector F1, T1, F2, T2;
        R.forceTorque(U1, Zero, U2, Zero, F1, T1, F2, T2);
        F1 += R.strainForce(0, 0, E) + R.strainForce(0, 1, E);
        F2 += R.strainForce(1, 0, E) + R.strainForce(1, 1, E);
        T1 += R.strainTorque(0, 0, E) + R.strainTorque(0, 1, E);
        T2 += R.strainTorque(1, 0, E) + R.strainTorque(1, 1, E);

        const scalar ref =
            maxFunction(R)*mag(E)*(1 + max(mag(x1), mag(x2)));
        EXPECT_LT(mag(F1), 1e-12*ref);
        EXPECT_LT(mag(F2), 1e-12*ref);
        EXPECT_LT(mag(T1), 1e-12*ref);
        EXPECT_LT(mag(T2), 1e-12*ref);
    }
}


TEST(pairSubGridMatrix, lorentzReciprocity)
{
    // Force/torque block symmetric as assembled (B~_ab = B_ba^T with the
    // printed B~ list), and G~_ab,ijk = G_ba,jki, H~_ab,ijk = H_ba,jki:
    // U.(G~_ab:E) = E:(G_ba.U), W.(H~_ab:E) = E:(H_ba.W), with G~, H~ from
    // their own 3.3.3 lists
    for (label trial = 0; trial < 10; ++trial)
    {
        const pairMatrix R(arbitraryBase(), uniform(1.5, 3.5), randomUnit());
        const scalar ref = maxFunction(R);

        for (label i = 0; i < 12; ++i)
        {
            for (label j = 0; j < 12; ++j)
            {
                EXPECT_LE(mag(R(i, j) - R(j, i)), 1e-14*ref)
                    << "R(" << i << ", " << j << ")";
            }
        }

        const vector U = randomVector();
        const vector W = randomVector();
        const symmTensor E = randomSymm();
        for (label a = 0; a < 2; ++a)
        {
            for (label b = 0; b < 2; ++b)
            {
                EXPECT_NEAR
                (
                    U & R.strainForce(a, b, E),
                    E && R.G(b, a, U),
                    1e-12*ref
                );
                EXPECT_NEAR
                (
                    W & R.strainTorque(a, b, E),
                    E && R.H(b, a, W),
                    1e-12*ref
                );
            }
        }
    }
}


TEST(pairSubGridMatrix, stressletMatchesIndexFormOfAppendixA)
{
    // G_ijk U_k and H_ijk W_k in closed form against the index forms
    const vector d = randomUnit();
    const pairMatrix R(arbitraryBase(), 2.3, d);
    const pairMatrix::resistanceFunctions& f = R.functions();
    const vector U = randomVector();
    const vector W = randomVector();

    for (label a = 0; a < 2; ++a)
    {
        for (label b = 0; b < 2; ++b)
        {
            const symmTensor GU = R.G(a, b, U);
            const symmTensor HW = R.H(a, b, W);
            EXPECT_NEAR(tr(GU), 0, 1e-13);
            EXPECT_NEAR(tr(HW), 0, 1e-13);
            for (label i = 0; i < 3; ++i)
            {
                for (label j = 0; j < 3; ++j)
                {
                    scalar g = 0, h = 0;
                    for (label k = 0; k < 3; ++k)
                    {
                        const scalar dij = (i == j), dik = (i == k),
                            djk = (j == k);
                        g += U[k]*
                        (
                            f.XG[a][b]*(d[i]*d[j] - dij/3)*d[k]
                          + f.YG[a][b]
                           *(d[i]*djk + d[j]*dik - 2*d[i]*d[j]*d[k])
                        );
                        for (label m = 0; m < 3; ++m)
                        {
                            h += W[k]*f.YH[a][b]
                               *(d[i]*eps3(j, k, m) + d[j]*eps3(i, k, m))
                               *d[m];
                        }
                    }
                    EXPECT_NEAR(tensor(GU).component(3*i + j), g, 1e-12);
                    EXPECT_NEAR(tensor(HW).component(3*i + j), h, 1e-12);
                }
            }
        }
    }
}


TEST(pairSubGridMatrix, analyticEntriesForPairAlongX)
{
    // d = e_x, r = 2.5; every block of R and every stresslet function is
    // probed by one unit velocity
    fdm::pairBaseFunctions b;
    b.XA21 = -7.0;  b.YA21 = -1.3; b.YB21 = 0.7;  b.XC21 = -0.4;
    b.YC11 = 2.1;   b.XG11 = 3.3;  b.YG11 = 0.9;  b.YH21 = -0.6;
    b.XP12 = -2.7;  b.XP21 = 2.5;
    const scalar r = 2.5;
    const pairMatrix R(b, r, vector(1, 0, 0));
    const vector ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
    const scalar tol = 1e-13;
    vector F1, T1, F2, T2;

    // U_1 along d: F_1 = -X_11^A d = X_21^A d, F_2 = -X_21^A d, no torque
    R.forceTorque(ex, Zero, Zero, Zero, F1, T1, F2, T2);
    EXPECT_LT(mag(F1 - b.XA21*ex), tol);
    EXPECT_LT(mag(F2 + b.XA21*ex), tol);
    EXPECT_LT(mag(T1), tol);
    EXPECT_LT(mag(T2), tol);
    // S_1 = -X_11^G (dd - I/3), S_2 = -X_21^G (dd - I/3)
    {
        const symmTensor D(sqr(ex) - symmTensor::I/3);
        EXPECT_LT(mag(R.stresslet(0, ex, Zero, Zero, Zero) + b.XG11*D), tol);
        EXPECT_LT
        (
            mag
            (
                R.stresslet(1, ex, Zero, Zero, Zero)
              - (b.XG11 + r*b.XA21)*D
            ),
            tol
        );
        // s_1 = -X_11^P = X_12^P, s_2 = -X_21^P
        EXPECT_NEAR(R.dipoleTrace(0, ex, Zero), b.XP12, tol);
        EXPECT_NEAR(R.dipoleTrace(1, ex, Zero), -b.XP21, tol);
        // U_2 along d: s_1 = -X_12^P, s_2 = -X_22^P = X_21^P
        EXPECT_NEAR(R.dipoleTrace(0, Zero, ex), -b.XP12, tol);
        EXPECT_NEAR(R.dipoleTrace(1, Zero, ex), b.XP21, tol);
    }

    // U_1 = e_y: F = -Y^A U, T = -Y^B U x d = Y^B e_z (B_ij = Y^B eps_ijk d_k)
    R.forceTorque(ey, Zero, Zero, Zero, F1, T1, F2, T2);
    EXPECT_LT(mag(F1 - b.YA21*ey), tol);                 // -Y_11^A
    EXPECT_LT(mag(F2 + b.YA21*ey), tol);                 // -Y_21^A
    EXPECT_LT(mag(T1 - (-b.YB21 + r*b.YA21)*ez), tol);   // Y_11^B
    EXPECT_LT(mag(T2 - b.YB21*ez), tol);                 // Y_21^B
    // S_1 = -Y_11^G (e_x e_y + e_y e_x)
    EXPECT_NEAR(R.stresslet(0, ey, Zero, Zero, Zero).xy(), -b.YG11, tol);
    EXPECT_NEAR
    (
        R.stresslet(1, ey, Zero, Zero, Zero).xy(), b.YG11 + 0.5*r*b.YA21, tol
    );
    EXPECT_NEAR(R.dipoleTrace(0, ey, Zero), 0, tol);

    // U_2 = e_z: F_1 = -Y_12^A e_z, T_1 = -Y_12^B e_z x e_x = -Y_12^B e_y
    R.forceTorque(Zero, Zero, ez, Zero, F1, T1, F2, T2);
    EXPECT_LT(mag(F1 + b.YA21*ez), tol);
    EXPECT_LT(mag(F2 - b.YA21*ez), tol);
    EXPECT_LT(mag(T1 + (b.YB21 - r*b.YA21)*ey), tol);
    EXPECT_LT(mag(T2 - b.YB21*ey), tol);                 // -Y_22^B e_y

    // Omega_1 = e_y: F = -Y~^B Omega x d = Y~^B e_z, T = -Y^C Omega
    R.forceTorque(Zero, ey, Zero, Zero, F1, T1, F2, T2);
    EXPECT_LT(mag(F1 - (b.YB21 - r*b.YA21)*ez), tol);   // Y~_11^B
    EXPECT_LT(mag(F2 - (-b.YB21 + r*b.YA21)*ez), tol);  // Y~_21^B
    EXPECT_LT(mag(T1 + b.YC11*ey), tol);
    EXPECT_LT
    (
        mag(T2 - (b.YC11 - r*b.YB21 + r*r*b.YA21)*ey), tol   // -Y_21^C
    );
    // S_a = -Y_a1^H (d (W x d) + (W x d) d), W x d = -e_z
    EXPECT_NEAR
    (
        R.stresslet(0, Zero, ey, Zero, Zero).xz(),
        -b.YH21 - 0.5*r*r*b.YA21 + 0.5*r*b.YB21,
        tol
    );
    EXPECT_NEAR(R.stresslet(1, Zero, ey, Zero, Zero).xz(), b.YH21, tol);

    // Omega_2 = e_z: F_1 = -Y~_12^B e_z x e_x = Y_21^B e_y
    R.forceTorque(Zero, Zero, Zero, ez, F1, T1, F2, T2);
    EXPECT_LT(mag(F1 - b.YB21*ey), tol);
    EXPECT_LT(mag(F2 + b.YB21*ey), tol);                 // -Y~_22^B e_y
    EXPECT_LT
    (
        mag(T1 + (-b.YC11 + r*b.YB21 - r*r*b.YA21)*ez), tol  // -Y_12^C
    );
    EXPECT_LT
    (
        mag(T2 + (b.YC11 - 2*r*b.YB21 + r*r*b.YA21)*ez), tol // -Y_22^C
    );
    EXPECT_NEAR
    (
        R.stresslet(0, Zero, Zero, Zero, ez).xy(),
        // -Y_12^H (d (W x d) + ...), W x d = e_y
        -(b.YH21 + 0.5*r*r*b.YA21 + r*b.YG11 - 0.5*r*b.YB21),
        tol
    );

    // Omega_2 along d (twist): T_1 = -X_12^C d, T_2 = X_21^C d, no force
    R.forceTorque(Zero, Zero, Zero, ex, F1, T1, F2, T2);
    EXPECT_LT(mag(F1), tol);
    EXPECT_LT(mag(F2), tol);
    EXPECT_LT(mag(T1 + b.XC21*ex), tol);
    EXPECT_LT(mag(T2 - b.XC21*ex), tol);
    EXPECT_LT(mag(R.stresslet(0, Zero, Zero, Zero, ex)), tol);
}


TEST(pairSubGridMatrix, positiveSemiDefiniteNearContact)
{
    // Singular parts of the theory at xi = 1e-3 (lambda = 1): R has the six
    // rigid modes as null space and is positive on the six internal modes
    const scalar xi = 1e-3;
    for (label trial = 0; trial < 5; ++trial)
    {
        const pairMatrix R(nearContactBase(xi), 2 + xi, randomUnit());
        const Eigen::MatrixXd M = toEigen(R);
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(M);
        const Eigen::VectorXd ev = es.eigenvalues();
        const scalar maxEv = ev.cwiseAbs().maxCoeff();
        EXPECT_GE(ev.minCoeff(), -1e-12*maxEv);
        // 6 rigid modes (zero), 6 internal modes (positive)
        label nPositive = 0;
        for (label k = 0; k < 12; ++k)
        {
            if (ev(k) > 1e-10*maxEv)
            {
                ++nPositive;
            }
        }
        EXPECT_EQ(nPositive, 6) << ev.transpose();
    }
}


TEST(pairSubGridMatrix, addsIntoParticleSystem)
{
    // Three particles, pair (2, 0) added in reversed order: the system's
    // product equals the matrix's own force/torque, and with a positive
    // pseudo-mass the system is SPD and CG recovers a known solution
    const pairMatrix R(nearContactBase(1e-3), 2 + 1e-3, randomUnit());

    const List<vector> U({randomVector(), randomVector(), randomVector()});
    const List<vector> W({randomVector(), randomVector(), randomVector()});

    {
        fdm::particleVelocitySystem sys(3);
        R.addTo(sys, 2, 0, 1.5);
        List<vector> f, t;
        sys.multiply(U, W, f, t);
        vector F1, T1, F2, T2;
        R.forceTorque(U[2], W[2], U[0], W[0], F1, T1, F2, T2);
        const scalar ref = mag(R(0, 0))*3;
        EXPECT_LT(mag(f[2] + 1.5*F1), 1e-12*ref);
        EXPECT_LT(mag(t[2] + 1.5*T1), 1e-12*ref);
        EXPECT_LT(mag(f[0] + 1.5*F2), 1e-12*ref);
        EXPECT_LT(mag(t[0] + 1.5*T2), 1e-12*ref);
        EXPECT_EQ(mag(f[1]) + mag(t[1]), 0);
    }

    fdm::particleVelocitySystem sys(3);
    for (label i = 0; i < 3; ++i)
    {
        fdm::rigidBodyMoments m;
        m.add(1.0, vector(0.3, 0.1, -0.2), 1);
        m.add(0.7, vector(-0.4, 0.2, 0.1), 1);
        m.add(0.9, vector(0.1, -0.3, 0.4), 1);
        m.add(0.8, vector(-0.1, 0.2, -0.4), 1);
        sys.addMass(i, m, 10);
    }
    R.addTo(sys, 0, 1, 1.0);

    List<vector> f, t;
    sys.multiply(U, W, f, t);
    forAll(f, i)
    {
        sys.addRhs(i, f[i], t[i]);
    }
    List<vector> Us(3, Zero), Ws(3, Zero);
    const auto info = sys.solve(1e-13, 500, Us, Ws);
    EXPECT_TRUE(info.converged);
    forAll(U, i)
    {
        EXPECT_LT(mag(Us[i] - U[i]), 1e-8);
        EXPECT_LT(mag(Ws[i] - W[i]), 1e-8);
    }
}


TEST(pairSubGridMatrix, imageVelocityShiftsThePartnersFrame)
{
    const pairMatrix R(nearContactBase(1e-3), 2 + 1e-3, randomUnit());
    const vector v(0.8, 0, 0);
    const scalar error = unitTest::pairFrameShiftError
    (
        [&](fdm::particleVelocitySystem& sys) { R.addTo(sys, 0, 1, 1.5, v); },
        [&](fdm::particleVelocitySystem& sys) { R.addTo(sys, 0, 1, 1.5); },
        v
    );
    EXPECT_LT(error, 1e-10);
}


TEST(pairSubGridMatrix, rejectsDegenerateGeometry)
{
    FatalError.throwExceptions();
    EXPECT_THROW(pairMatrix(arbitraryBase(), 2, vector(Zero)), Foam::error);
    EXPECT_THROW(pairMatrix(arbitraryBase(), 0, vector(1, 0, 0)), Foam::error);
    fdm::particleVelocitySystem sys(2);
    const pairMatrix R(arbitraryBase(), 2, vector(1, 0, 0));
    EXPECT_THROW(R.addTo(sys, 1, 1, 1.0), Foam::error);
    FatalError.dontThrowExceptions();
}
