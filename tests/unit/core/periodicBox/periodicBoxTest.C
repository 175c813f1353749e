// Unit tests for Foam::fdm::periodicBox (src/fdmParticles/core/periodicBox)

#include "periodicBox.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const fdm::periodicBox box
(
    point(-1, 0, 2),
    point(3, 10, 4),
    FixedList<bool, 3>({true, false, true})
);

} // namespace


TEST(periodicBox, wrapLeavesInsidePointsUnchanged)
{
    const point p(0.5, 3.0, 3.5);
    const point w = box.wrap(p);
    EXPECT_DOUBLE_EQ(w.x(), p.x());
    EXPECT_DOUBLE_EQ(w.y(), p.y());
    EXPECT_DOUBLE_EQ(w.z(), p.z());
}


TEST(periodicBox, periodicFlagsAsGiven)
{
    EXPECT_TRUE(box.periodic()[0]);
    EXPECT_FALSE(box.periodic()[1]);
    EXPECT_TRUE(box.periodic()[2]);
    for (direction d = 0; d < 3; ++d)
    {
        EXPECT_EQ(box.periodic()[d], box.periodic(d));
    }
}


TEST(periodicBox, wrapMapsThroughPeriodicFacesOnly)
{
    // x = 3.5 is 0.5 past the upper face (span 4); x = -1.25 lies 0.25 below
    // the lower face; y is not periodic and must stay outside.
    const point w1 = box.wrap(point(3.5, 12.0, 1.0));
    EXPECT_NEAR(w1.x(), -0.5, 1e-15);
    EXPECT_DOUBLE_EQ(w1.y(), 12.0);
    EXPECT_NEAR(w1.z(), 3.0, 1e-15);

    const point w2 = box.wrap(point(-1.25, -2.0, 4.0));
    EXPECT_NEAR(w2.x(), 2.75, 1e-15);
    EXPECT_DOUBLE_EQ(w2.y(), -2.0);
    EXPECT_NEAR(w2.z(), 2.0, 1e-15);   // upper face maps to lower face
}


TEST(periodicBox, wrapHandlesSeveralPeriods)
{
    const point w = box.wrap(point(-1 + 4*7 + 0.3, 5, 2 - 2*3 + 0.1));
    EXPECT_NEAR(w.x(), -0.7, 1e-12);
    EXPECT_NEAR(w.z(), 2.1, 1e-12);
}


TEST(periodicBox, wrapResultAlwaysInsideHalfOpenBox)
{
    // Points just below the lower face: floor() rounding must not return
    // the excluded upper bound
    for (const scalar eps : {1e-17, 1e-16, 1e-15, 1e-12})
    {
        const point w = box.wrap(point(-1 - eps, 0, 2 - eps));
        EXPECT_GE(w.x(), -1.0);
        EXPECT_LT(w.x(), 3.0);
        EXPECT_GE(w.z(), 2.0);
        EXPECT_LT(w.z(), 4.0);
    }
}


TEST(periodicBox, minimumImageIsShortestSeparation)
{
    // Separation 3.5 along x (span 4) is -0.5 through the periodic face;
    // along y (not periodic) it stays 9.
    const vector m = box.minimumImage(vector(3.5, 9.0, -1.5));
    EXPECT_NEAR(m.x(), -0.5, 1e-15);
    EXPECT_DOUBLE_EQ(m.y(), 9.0);
    EXPECT_NEAR(m.z(), 0.5, 1e-15);

    for (const scalar dx : {-7.9, -2.1, -0.3, 0.0, 1.9, 6.2})
    {
        const scalar mx = box.minimumImage(vector(dx, 0, 0)).x();
        EXPECT_LE(std::abs(mx), 2.0 + 1e-14);
        // Same point modulo the period
        const scalar k = (dx - mx)/4.0;
        EXPECT_NEAR(k, std::round(k), 1e-12);
    }
}


TEST(periodicBox, rejectsDegenerateBox)
{
    FatalError.throwExceptions();
    EXPECT_THROW
    (
        fdm::periodicBox
        (
            point(0, 0, 0), point(1, 0, 1), FixedList<bool, 3>(true)
        ),
        Foam::error
    );
    FatalError.dontThrowExceptions();
}


TEST(periodicBox, leesEdwardsImagesShiftAlongX)
{
    fdm::periodicBox box(point(0, 0, 0), point(10, 8, 6),
        FixedList<bool, 3>({true, true, true}));
    box.setShearOffset(23.0);          // stored modulo L_x
    EXPECT_NEAR(box.shearOffset(), 3.0, 1e-12);

    // One period up in y: the image is shifted by +3 in x, so wrapping
    // takes 3 off x (and the periodic x wrap follows)
    const point w = box.wrap(point(1, 9, 2));
    EXPECT_NEAR(w.x(), 8.0, 1e-12);
    EXPECT_NEAR(w.y(), 1.0, 1e-12);
    EXPECT_EQ(box.periodsAlongY(point(1, 9, 2)), 1);
    EXPECT_EQ(box.periodsAlongY(point(1, -0.5, 2)), -1);

    // A particle near the top sees the image of one near the bottom
    // displaced by (offset, L_y, 0): the separation is short
    const point top(5, 7.5, 1);
    const point bottom(2.2, 0.4, 1);
    const vector d = box.minimumImage(bottom - top);
    EXPECT_NEAR(d.x(), 0.2, 1e-12);
    EXPECT_NEAR(d.y(), 0.9, 1e-12);
    EXPECT_NEAR(d.z(), 0.0, 1e-12);

    // Wrapped positions give the same separations as unwrapped ones
    const point p(3.3, 17.1, 2.0);
    const point q(4.1, 1.2, 5.5);
    const vector d1 = box.minimumImage(q - p);
    const vector d2 = box.minimumImage(box.wrap(q) - box.wrap(p));
    EXPECT_NEAR(mag(d1 - d2), 0.0, 1e-12);
}


TEST(periodicBox, leesEdwardsVelocitiesFollowTheAffineShear)
{
    // u_x = gammaDot y continued through the sheared faces: a point's
    // velocity after the wrap, and the relative velocity of the image a
    // pair sees, are those of that flow
    const scalar gammaDot = 0.7, Ly = 8;
    fdm::periodicBox box(point(0, 0, 0), point(10, Ly, 6),
        FixedList<bool, 3>({true, true, true}));
    box.setShearOffset(gammaDot*Ly*3.3);
    box.setShearVelocity(gammaDot*Ly);
    auto affine = [&](const point& x) { return vector(gammaDot*x.y(), 0, 0); };

    for (const point& x : {point(1, 9, 2), point(4, -0.5, 1), point(2, 17, 3),
        point(5, 3, 3)})
    {
        const vector U = affine(x) + vector(0.1, -0.2, 0.3);
        const vector wrapped = box.wrapVelocity(x, U);
        EXPECT_LT(mag(wrapped - U - (affine(box.wrap(x)) - affine(x))), 1e-12)
            << x.x() << ' ' << x.y();
    }

    // A near the top, B near the bottom: B's image above A moves at
    // B's velocity + gammaDot L_y; A's image below B at A's - gammaDot L_y
    const point A(5, 7.5, 1), B(2.2, 0.4, 1);
    EXPECT_LT(mag(box.imageVelocity(B - A) - vector(gammaDot*Ly, 0, 0)), 1e-12);
    EXPECT_LT(mag(box.imageVelocity(A - B) + vector(gammaDot*Ly, 0, 0)), 1e-12);
    EXPECT_EQ(box.imageVelocity(point(5, 5, 1) - A), vector::zero);
}


TEST(periodicBox, leesEdwardsNeedsXAndYPeriodic)
{
    fdm::periodicBox box(point(0, 0, 0), point(1, 1, 1),
        FixedList<bool, 3>({true, false, true}));
    FatalError.throwExceptions();
    EXPECT_ANY_THROW(box.setShearOffset(0.5));
    EXPECT_ANY_THROW(box.setShearVelocity(0.5));
}
