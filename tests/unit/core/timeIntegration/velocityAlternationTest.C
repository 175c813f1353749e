// Unit tests for the watch on alternating particle velocities
// (velocityAlternation.H): the zig-zag of velocities that alternate in
// sign is their amplitude times the step, that of velocities linear in
// time is zero, and the warning comes once, after stepsInARow steps
// in a row above the limit

#include "velocityAlternation.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

// Two particles: a smooth drift (linear in time) plus, with amplitude a,
// a part that alternates in sign from step to step
List<vector> velocities(const label k, const scalar a)
{
    const scalar sign = k % 2 ? -1 : 1;
    List<vector> U(2);
    U[0] = vector(1 + 0.1*k, 0, 0) + sign*a*vector(0, 1, 0);
    U[1] = vector(-2, 0.05*k, 0) + sign*a*vector(0, 0, -1);
    return U;
}

} // End anonymous namespace


TEST(velocityAlternation, zigzagOfAlternatingAndSmoothVelocities)
{
    const scalar dt = 4e-3;
    for (const scalar a : {0.0, 0.7})
    {
        fdm::velocityAlternation watch;
        scalar zigzag = 0;
        // Nothing to compare until a third velocity is known
        watch.check(velocities(1, a), velocities(0, a), dt, 1, {}, false, zigzag);
        EXPECT_EQ(zigzag, -1);
        watch.check(velocities(2, a), velocities(1, a), dt, 1, {}, false, zigzag);
        // |U - 2 Uold + Uolder|/4 = a for the alternating part; zero for
        // the linear drift
        EXPECT_NEAR(zigzag, a*dt, 1e-15);
    }
}


TEST(velocityAlternation, onlyTheParticlesMovedHereCount)
{
    fdm::velocityAlternation watch;
    scalar zigzag = 0;
    List<vector> U(velocities(1, 0.7)), Uold(velocities(0, 0.7));
    const boolList moved({true, false});
    watch.check(U, Uold, 1, 1, moved, false, zigzag);
    // The second particle, not moved here, alternates ten times as much
    List<vector> U2(velocities(2, 0.7));
    U2[1] *= 10;
    watch.check(U2, U, 1, 1, moved, false, zigzag);
    EXPECT_NEAR(zigzag, 0.7, 1e-14);
}


TEST(velocityAlternation, warnsOnceAfterStepsInARow)
{
    const scalar dt = 4e-3;
    const scalar hr = 5e-3;
    const scalar limit = fdm::velocityAlternation::roughnessFraction*hr;
    // Alternating at 0.05 (zig-zag 0.04 h_r) up to step 14, at 0.7 (0.56
    // h_r) from 15; the limit is 0.1 h_r
    List<List<vector>> U(40);
    forAll(U, k)
    {
        U[k] = velocities(k, k < 15 ? 0.05 : 0.7);
    }
    fdm::velocityAlternation watch;
    scalar zigzag = 0;
    label firstWarning = -1, warnings = 0;
    for (label k = 1; k < U.size(); ++k)
    {
        if (watch.check(U[k], U[k - 1], dt, limit, {}, false, zigzag))
        {
            ++warnings;
            firstWarning = k;
        }
    }
    EXPECT_EQ(warnings, 1);
    // Step 15 mixes the two (zig-zag 0.21 dt = 0.17 h_r) and is above, as
    // are those after it
    EXPECT_EQ(firstWarning, 15 + fdm::velocityAlternation::stepsInARow - 1);
    EXPECT_NEAR(zigzag, 0.7*dt, 1e-15);
}
