// Unit tests for Foam::fdm::rigidBodyMoments (pseudo-mass of eq 2.53)

#include "rigidBodyMoments.H"
#include "indicatorFunctions.H"
#include "constants.H"
#include "point.H"
#include "DynamicList.H"

#include <gtest/gtest.h>
#include <random>

using namespace Foam;

namespace
{

// Moments of a sphere of radius a centred at x0 on a cubic lattice of
// spacing h, weighted by J_u
fdm::rigidBodyMoments latticeSphere(const scalar a, const point& x0,
    const scalar h, List<vector>& offsets, List<scalar>& weights)
{
    const fdm::indicatorFunctions J(5, 0.3, h);
    fdm::rigidBodyMoments m;
    const label n = label(a/h) + 3;
    DynamicList<vector> r;
    DynamicList<scalar> w;
    for (label i = -n; i <= n; ++i)
    for (label j = -n; j <= n; ++j)
    for (label k = -n; k <= n; ++k)
    {
        const vector d = h*vector(i, j, k) - x0;
        const scalar Ju = J.Ju(mag(d), a);
        if (Ju > 0)
        {
            m.add(Ju, d, h*h*h);
            r.append(d);
            w.append(Ju*h*h*h);
        }
    }
    offsets.transfer(r);
    weights.transfer(w);
    return m;
}

} // namespace


TEST(rigidBodyMoments, approachTheContinuousSphereOnFineLattices)
{
    // J_u is 1/2 at r = a and antisymmetric about it up to the truncation,
    // so its volume tends to 4/3 pi a^3 and the inertia to (2/5) V a^2.
    const scalar a = 1;
    List<vector> r;
    List<scalar> w;
    const fdm::rigidBodyMoments m =
        latticeSphere(a, point(0.013, -0.007, 0.021), a/40, r, w);

    const scalar V = 4.0/3.0*constant::mathematical::pi*a*a*a;
    EXPECT_NEAR(m.volume/V, 1, 2e-3);
    EXPECT_NEAR(m.inertia.xx()/(0.4*V*a*a), 1, 5e-3);
    EXPECT_NEAR(m.inertia.xy()/(0.4*V*a*a), 0, 1e-3);
    EXPECT_NEAR(mag(m.firstMoment)/(V*a), 0, 1e-3);
}


TEST(rigidBodyMoments, blockIsSymmetricAndEqualsTheRigidMotionIntegrals)
{
    // Reference: the J_u-weighted integral of u = U + Omega x r evaluated
    // cell by cell must equal the block applied to (U, Omega).
    List<vector> r;
    List<scalar> w;
    const fdm::rigidBodyMoments m =
        latticeSphere(1.0, point(0.07, 0.11, -0.05), 0.2, r, w);

    for (direction i = 0; i < 6; ++i)
    {
        for (direction j = 0; j < 6; ++j)
        {
            EXPECT_NEAR(m.entry(i, j), m.entry(j, i), 1e-14);
        }
    }

    const vector U(0.3, -1.2, 0.7), Omega(-0.4, 0.9, 1.3);
    vector f(Zero), t(Zero);
    forAll(r, c)
    {
        const vector u = U + (Omega ^ r[c]);
        f += w[c]*u;
        t += w[c]*(r[c] ^ u);
    }
    EXPECT_LT(mag(m.force(U, Omega) - f), 1e-13*mag(f));
    EXPECT_LT(mag(m.torque(U, Omega) - t), 1e-13*mag(t));

    // Positive definite: (U,Omega).M.(U,Omega) = sum J_u V |u|^2 > 0
    const scalar quad = (U & m.force(U, Omega)) + (Omega & m.torque(U, Omega));
    scalar ref = 0;
    forAll(r, c)
    {
        ref += w[c]*magSqr(U + (Omega ^ r[c]));
    }
    EXPECT_NEAR(quad, ref, 1e-12*ref);
    EXPECT_GT(quad, 0);
}
