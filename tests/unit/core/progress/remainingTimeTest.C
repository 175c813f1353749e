// Unit tests of fdm::remainingTime: the time left of a run at its recent
// cost per unit of simulated time

#include "remainingTime.H"

#include <gtest/gtest.h>

using namespace Foam;


TEST(remainingTime, steadyCostGivesTheTimeLeft)
{
    // 2 s per step of 0.004: 500 s per unit time, 10 - 1 units left
    fdm::remainingTime left(0, 0, 0, 200);
    for (label n = 1; n <= 250; ++n)
    {
        left.update(2.0*n, 2.0*n, 0.004*n);
    }
    EXPECT_NEAR(left.cost(), 500, 1e-9);
    EXPECT_NEAR(left.seconds(10), 9*500, 1e-6);
    EXPECT_EQ(left.seconds(0.5), 0);
}


TEST(remainingTime, recentCostReplacesAnEarlySlowSpell)
{
    // 100 steps at 6 s then 1000 at 1.5 s: the mean since the start is
    // 1.91 s per step, the estimate within 1 % of 1.5 after ten memories
    // of 100 steps
    fdm::remainingTime left(0, 0, 0, 100);
    scalar clock = 0;
    label n = 0;
    for (; n < 100; ++n)
    {
        clock += 6;
        left.update(clock, clock, n + 1);
    }
    EXPECT_NEAR(left.cost(), 6, 1e-12);
    for (; n < 1100; ++n)
    {
        clock += 1.5;
        left.update(clock, clock, n + 1);
    }
    EXPECT_GT(clock/n, 1.9);
    EXPECT_NEAR(left.cost(), 1.5, 0.015);
    EXPECT_NEAR(left.seconds(n + 100), 150, 1.5);
}


TEST(remainingTime, intervalWithoutProgressIsNotAveraged)
{
    // A repeated update (a second progress line at the same time) neither
    // divides by zero nor changes the cost; the wall time it took counts
    // in the next interval
    fdm::remainingTime left(10, 10, 1, 5);
    left.update(12, 12, 2);
    left.update(13, 13, 2);
    EXPECT_EQ(left.cost(), 2);
    left.update(15, 15, 3);
    EXPECT_EQ(left.cost(), 2.5);
}


TEST(remainingTime, aPauseIsNotACost)
{
    // 2 s per step, then one step during which the process was stopped
    // for 420 s (it ran 2 s of it): counted at its 2 s.  A step that ran
    // for half its wall time (a shared core) counts in full
    fdm::remainingTime left(0, 0, 0, 200);
    left.update(2, 2, 1);
    left.update(424, 4, 2);
    EXPECT_EQ(left.cost(), 2);
    left.update(432, 8, 3);
    EXPECT_NEAR(left.cost(), (2 + 2 + 8)/3.0, 1e-12);
}


// ************************************************************************* //
