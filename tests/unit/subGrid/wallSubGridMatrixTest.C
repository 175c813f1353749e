// Unit tests for Foam::fdm::wallSubGridMatrix (thesis 1, eqs 3.17-3.21,
// Appendix A forms with d = wall normal pointing into the wall)

#include "wallSubGridMatrix.H"
#include "particleVelocitySystem.H"
#include "rigidBodyMoments.H"
#include "mathematicalConstants.H"
#include "point.H"
#include "tensor.H"

#include "randomGeometry.H"

#include <gtest/gtest.h>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

typedef fdm::wallSubGridMatrix wallMatrix;

std::mt19937 rng(1912);

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

fdm::wallBaseFunctions arbitraryBase()
{
    fdm::wallBaseFunctions b;
    b.XA = uniform(1, 20);
    b.YA = uniform(-5, 5);
    b.YB = uniform(-5, 5);
    b.XC = uniform(-5, 5);
    b.YC = uniform(-5, 5);
    b.XG = uniform(-5, 5);
    b.XP = uniform(-5, 5);
    return b;
}

//- Singular parts of the wall lubrication forms (thesis B.2) for radius a
fdm::wallBaseFunctions nearWallBase(const scalar eps, const scalar a)
{
    const scalar L = std::log(1/eps);
    fdm::wallBaseFunctions b;
    b.XA = 6*pi*a*(1/eps + 0.2*L + eps*L/21);
    b.YA = 6*pi*a*((8.0/15)*L + (64.0/375)*eps*L);
    b.YB = 4*pi*a*a*(-(3.0/15)*L - (43.0/125)*eps*L);
    b.XC = 0;   // seed notes section 12 item 25: no SG needed for X^C
    b.YC = 8*pi*a*a*a*((2.0/5)*L + (66.0/125)*eps*L);
    b.XG = 4*pi*a*a*(1.5/eps - 1.2*L);
    b.XP = 4*pi*a*a*(1.5/eps - 1.2*L);
    return b;
}

scalar maxEntry(const wallMatrix& R)
{
    scalar m = 0;
    for (label i = 0; i < 6; ++i)
    {
        for (label j = 0; j < 6; ++j)
        {
            m = max(m, mag(R(i, j)));
        }
    }
    const wallMatrix::resistanceFunctions& f = R.functions();
    return max(m, max(max(mag(f.XG), mag(f.YG)), max(mag(f.YH), mag(f.XP))));
}

} // namespace


TEST(wallSubGridMatrix, motionWithTheWallGivesNoCorrection)
{
    for (label trial = 0; trial < 10; ++trial)
    {
        const wallMatrix R(arbitraryBase(), 1.3, 0.01, randomUnit());
        const vector Uw = randomVector();
        vector F, T;
        R.forceTorque(Uw, Zero, Uw, F, T);
        EXPECT_EQ(mag(F) + mag(T), 0);
        EXPECT_EQ(mag(R.stresslet(Uw, Zero, Uw)), 0);
        EXPECT_EQ(R.dipoleTrace(Uw, Uw), 0);

        // Only the velocity relative to the wall counts
        const vector U = randomVector();
        const vector W = randomVector();
        vector F0, T0;
        R.forceTorque(U - Uw, W, Zero, F0, T0);
        R.forceTorque(U, W, Uw, F, T);
        EXPECT_LT(mag(F - F0) + mag(T - T0), 1e-13*maxEntry(R));
    }
}


TEST(wallSubGridMatrix, symmetricAndPositiveSemiDefiniteNearTheWall)
{
    for (const scalar eps : {1e-4, 1e-3, 1e-2, 0.1})
    {
        const scalar a = 1.4;
        const wallMatrix R(nearWallBase(eps, a), a, eps, randomUnit());
        Eigen::MatrixXd M(6, 6);
        for (label i = 0; i < 6; ++i)
        {
            for (label j = 0; j < 6; ++j)
            {
                M(i, j) = R(i, j);
                EXPECT_EQ(R(i, j), R(j, i));
            }
        }
        const Eigen::VectorXd ev =
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues();
        EXPECT_GE(ev.minCoeff(), -1e-12*ev.cwiseAbs().maxCoeff())
            << ev.transpose();
    }

    // Symmetric for arbitrary functions too (B~ = -B reading of 3.21)
    const wallMatrix R(arbitraryBase(), 1, 0.05, randomUnit());
    for (label i = 0; i < 6; ++i)
    {
        for (label j = 0; j < 6; ++j)
        {
            EXPECT_EQ(R(i, j), R(j, i));
        }
    }
}


TEST(wallSubGridMatrix, ambientShearGivesNoCorrection)
{
    // Eq 3.19: fixed particle, fixed wall, simple shear parallel to the wall
    // (second part of 3.17): F = -R.(-u_inf(x_p), -Omega_inf) + G~:E, T alike
    // with H~, must vanish.  Wall through the origin, d into the wall.
    for (label trial = 0; trial < 10; ++trial)
    {
        const scalar a = uniform(0.5, 2);
        const scalar eps = uniform(1e-4, 0.3);
        const vector d = randomUnit();
        vector t = randomUnit();
        t = t - (t & d)*d;
        t /= mag(t);
        const scalar gammaDot = uniform(0.5, 2);

        // u_inf = -gammaDot (x.d) t: grad u = -gammaDot t d
        const tensor gradU = -gammaDot*(t*d);
        const symmTensor E = symm(gradU);
        const vector Omega = 0.5*vector
        (
            gradU.zy() - gradU.yz(),
            gradU.xz() - gradU.zx(),
            gradU.yx() - gradU.xy()
        );
        const point xp = -(1 + eps)*a*d;
        const vector uInf = (Omega ^ xp) + (E & xp);
        ASSERT_LT(mag(uInf - (-gammaDot*(xp & d)*t)), 1e-13);

        const wallMatrix R(arbitraryBase(), a, eps, d);
        vector F, T;
        R.forceTorque(-uInf, -Omega, Zero, F, T);
        F += R.strainForce(E);
        T += R.strainTorque(E);
        const scalar ref = maxEntry(R)*gammaDot*(1 + a);
        EXPECT_LT(mag(F), 1e-12*ref);
        EXPECT_LT(mag(T), 1e-12*ref);

        // With a wrong lever arm in (3.19) the ambient part does not vanish
        const wallMatrix Rwrong(arbitraryBase(), a, eps + 0.5, d);
        Rwrong.forceTorque(-uInf, -Omega, Zero, F, T);
        F += Rwrong.strainForce(E);
        T += Rwrong.strainTorque(E);
        EXPECT_GT(mag(F) + mag(T), 1e-6*ref);
    }
}


TEST(wallSubGridMatrix, analyticEntriesForWallBelow)
{
    // Wall below the particle: d = -e_z; h = (1 + eps) a
    fdm::wallBaseFunctions b;
    b.XA = 9.0; b.YA = 2.5; b.YB = -0.8; b.XC = 0.3; b.YC = 1.7;
    b.XG = 4.1; b.XP = 3.6;
    const scalar a = 1.2, eps = 0.02, h = (1 + eps)*a;
    const wallMatrix R(b, a, eps, vector(0, 0, -1));
    const vector ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
    const scalar tol = 1e-13;
    const scalar YG = h*b.YA + 0.5*b.YB;
    const scalar YH = -h*b.YB - 0.5*b.YC;
    EXPECT_NEAR(R.functions().YG, YG, tol);
    EXPECT_NEAR(R.functions().YH, YH, tol);
    vector F, T;

    // Normal approach U = d: F = -X^A U_n d, no torque
    R.forceTorque(-ez, Zero, Zero, F, T);
    EXPECT_LT(mag(F - b.XA*ez), tol);
    EXPECT_LT(mag(T), tol);
    EXPECT_NEAR(R.stresslet(-ez, Zero, Zero).zz(), -b.XG*2.0/3, tol);
    EXPECT_NEAR(R.stresslet(-ez, Zero, Zero).xx(), b.XG/3, tol);
    EXPECT_NEAR(R.dipoleTrace(-ez, Zero), -b.XP, tol);
    // Moving away from a moving wall: relative velocity counts
    R.forceTorque(Zero, Zero, -ez, F, T);
    EXPECT_LT(mag(F + b.XA*ez), tol);

    // Sliding U = e_x: F = -Y^A e_x, T = -Y^B U x d = -Y^B e_y
    R.forceTorque(ex, Zero, Zero, F, T);
    EXPECT_LT(mag(F + b.YA*ex), tol);
    EXPECT_LT(mag(T + b.YB*ey), tol);
    EXPECT_NEAR(R.stresslet(ex, Zero, Zero).xz(), YG, tol);
    EXPECT_NEAR(R.dipoleTrace(ex, Zero), 0, tol);

    // Rolling W = e_y: F = -Y~^B W x d = Y^B (-e_x), T = -Y^C e_y
    R.forceTorque(Zero, ey, Zero, F, T);
    EXPECT_LT(mag(F + b.YB*ex), tol);
    EXPECT_LT(mag(T + b.YC*ey), tol);
    // S = -Y^H (d (W x d) + (W x d) d), W x d = -e_x, d = -e_z
    EXPECT_NEAR(R.stresslet(Zero, ey, Zero).xz(), -YH, tol);

    // Spin about the normal: T = -X^C W
    R.forceTorque(Zero, ez, Zero, F, T);
    EXPECT_LT(mag(F), tol);
    EXPECT_LT(mag(T + b.XC*ez), tol);
    EXPECT_LT(mag(R.stresslet(Zero, ez, Zero)), tol);
}


TEST(wallSubGridMatrix, addsIntoParticleSystemWithWallVelocity)
{
    // [M + R] u = M u_ref + R (Uw, 0): a particle with the pseudo-mass
    // force of a motion with the wall and the wall term on the right-hand
    // side moves with the wall
    const wallMatrix R(nearWallBase(1e-3, 1), 1, 1e-3, randomUnit());
    const vector Uw(0.3, -0.2, 0.1);

    fdm::particleVelocitySystem sys(2);
    fdm::rigidBodyMoments m;
    m.add(1.0, vector(0.3, 0.1, -0.2), 1);
    m.add(0.7, vector(-0.4, 0.2, 0.1), 1);
    m.add(0.9, vector(0.1, -0.3, 0.4), 1);
    m.add(0.8, vector(-0.1, 0.2, -0.4), 1);
    sys.addMass(0, m, 10);
    sys.addMass(1, m, 10);
    R.addTo(sys, 1, Uw, 2.0);
    sys.addRhs(1, 10*m.force(Uw, Zero), 10*m.torque(Uw, Zero));

    List<vector> U(2, Zero), W(2, Zero);
    const auto info = sys.solve(1e-13, 200, U, W);
    EXPECT_TRUE(info.converged);
    EXPECT_LT(mag(U[1] - Uw), 1e-9);
    EXPECT_LT(mag(W[1]), 1e-9);
    EXPECT_LT(mag(U[0]) + mag(W[0]), 1e-12);

    // The matrix part alone reproduces -scale*forceTorque
    fdm::particleVelocitySystem sys2(2);
    R.addTo(sys2, 0, Zero, 2.0);
    const List<vector> Ut({vector(1, -2, 0.5), Zero});
    const List<vector> Wt({vector(0.2, 0.4, -1), Zero});
    List<vector> f, t;
    sys2.multiply(Ut, Wt, f, t);
    vector F, T;
    R.forceTorque(Ut[0], Wt[0], Zero, F, T);
    EXPECT_LT(mag(f[0] + 2*F) + mag(t[0] + 2*T), 1e-12*maxEntry(R));
}
