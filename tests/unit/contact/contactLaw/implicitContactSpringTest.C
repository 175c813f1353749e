// Unit tests for Foam::fdm::implicitContactSpring: a contact's normal and
// tangential stiffness taken implicitly (k_t dt B^T B + k_n' dt C^T C in the
// particle system)

#include "implicitContactSpring.H"
#include "particleVelocitySystem.H"
#include "contactLoads.H"
#include "pairFrameShift.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

// Pair of radii 1 and 1.4 touching along n at gap 0.002
struct pairSetup
{
    vector n = normalised(vector(0.3, 1, -0.4));
    scalar ai = 1, aj = 1.4, r = 2.402;
    vector xi = vector(0.5, -0.2, 0.1);
    vector xj = xi + r*n;
    scalar li = ai*r/(ai + aj), lj = aj*r/(ai + aj);
    fdm::implicitContactSpring spring{0, 1, n, li, lj, 11.0, 7.0};
};

} // namespace


TEST(implicitContactSpring, rigidMotionHasNoSlipAndNoApproach)
{
    const pairSetup s;
    const vector V(0.3, -1, 2), W(-0.7, 0.2, 1.1), origin(3, 1, -2);
    const List<vector> U({V + (W ^ (s.xi - origin)), V + (W ^ (s.xj - origin))});
    const List<vector> Omega({W, W});
    EXPECT_NEAR(mag(s.spring.slip(U, Omega)), 0, 1e-14);
    EXPECT_NEAR(s.spring.approach(U), 0, 1e-14);
    EXPECT_NEAR(mag(s.spring.force(U, Omega).force), 0, 1e-12);
}


TEST(implicitContactSpring, matrixIsTheLoadsOfTheImplicitForce)
{
    const pairSetup s;
    const List<vector> U({vector(0.1, 0.2, -0.3), vector(-0.4, 0.05, 0.2)});
    const List<vector> Omega({vector(0.3, -0.1, 0.7), vector(0.2, 0.6, -0.5)});

    fdm::particleVelocitySystem system(2);
    s.spring.addTo(system, 1);
    List<vector> RF(2), RT(2);
    system.multiply(U, Omega, RF, RT);

    // R u is minus the loads of -k dt U_s applied through eqs 2.55, 2.64
    fdm::particleLoads loads(2);
    const List<vector>& F = loads.force;
    const List<vector>& T = loads.torque;
    const fdm::contactForce c = s.spring.force(U, Omega);
    EXPECT_NEAR(c.tangential & s.n, 0, 1e-15);
    EXPECT_NEAR(c.force & s.n, -11.0*s.spring.approach(U), 1e-14);
    fdm::addContactLoads(c, s.n, s.li, s.lj, 0, 1, loads);
    for (label p = 0; p < 2; ++p)
    {
        EXPECT_NEAR(mag(RF[p] + F[p]), 0, 1e-13) << p;
        EXPECT_NEAR(mag(RT[p] + T[p]), 0, 1e-13) << p;
    }

    // Dissipation u . R u = k_t dt |U_s|^2 + k_n' dt w^2 >= 0
    scalar power = 0;
    for (label p = 0; p < 2; ++p)
    {
        power += (U[p] & RF[p]) + (Omega[p] & RT[p]);
    }
    EXPECT_NEAR
    (
        power,
        7.0*magSqr(s.spring.slip(U, Omega)) + 11.0*sqr(s.spring.approach(U)),
        1e-13
    );
}


TEST(implicitContactSpring, rollingOnAMovingWallDoesNotSlip)
{
    // Wall below (n = -y from the centre), moving at Uw along x
    const vector n(0, -1, 0), Uw(2, 0, 0);
    const fdm::implicitContactSpring wall(0, -1, n, 1.0, 0, 3.0, 5.0, Uw);
    // Rolling: contact point velocity U + a Omega x n equals Uw
    const List<vector> U({vector(3, 0.2, 0)});
    const List<vector> Omega({vector(0, 0, -1)});
    EXPECT_NEAR(mag(wall.slip(U, Omega)), 0, 1e-15);
    const List<vector> slide({vector(3.5, 0, 0)});
    EXPECT_NEAR(wall.slip(slide, Omega).x(), 0.5, 1e-15);
    // Moving onto the wall (-y) is an approach
    EXPECT_NEAR(wall.approach(U), -0.2, 1e-15);

    // The system holds K and the wall part on the right: at the wall's
    // own velocity (no slip, no approach) the implicit force vanishes
    const List<vector> withWall({Uw});
    const List<vector> still({Zero});
    EXPECT_NEAR(mag(wall.force(withWall, still).force), 0, 1e-15);
}


TEST(implicitContactSpring, imageVelocityShiftsThePartnersFrame)
{
    const pairSetup s;
    const vector v(0.8, 0, 0);
    const fdm::implicitContactSpring image{0, 1, s.n, s.li, s.lj, 11.0, 7.0, v};
    const scalar error = unitTest::pairFrameShiftError
    (
        [&](fdm::particleVelocitySystem& sys) { image.addTo(sys, 1); },
        [&](fdm::particleVelocitySystem& sys) { s.spring.addTo(sys, 1); },
        v
    );
    EXPECT_LT(error, 1e-12);
}
