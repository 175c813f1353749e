// Unit test of contactLink: the force on i split along the branch into a
// normal and a tangential part that add up to it again.

#include "contactNetwork.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(contactNetwork, splitsAlongTheBranch)
{
    // Branch of length 2.1 along (1 1 0)/sqrt 2; force with a known
    // compressive normal part -3 and tangential part (0 0 0.5)
    const vector n = vector(1, 1, 0)/std::sqrt(2.0);
    const vector F = -3*n + vector(0, 0, 0.5);
    const fdm::contactLink c = fdm::contactLink::split(4, 7, 2.1*n, F);

    EXPECT_EQ(c.i, 4);
    EXPECT_EQ(c.j, 7);
    EXPECT_NEAR(c.normalForce, -3, 1e-14);
    EXPECT_NEAR(mag(c.tangentialForce - vector(0, 0, 0.5)), 0, 1e-14);
    EXPECT_NEAR(c.tangentialForce & n, 0, 1e-14);
    EXPECT_NEAR(mag(c.force() - F), 0, 1e-14);
}


TEST(contactNetwork, wallLinkKeepsItsIndex)
{
    // Wall 2 of a particle: j = -1 - 2, branch to the contact point
    const fdm::contactLink c =
        fdm::contactLink::split(0, -3, vector(0, -1.001, 0), vector(0, 5, 0));
    EXPECT_EQ(c.j, -3);
    EXPECT_NEAR(c.normalForce, -5, 1e-14);
    EXPECT_NEAR(mag(c.tangentialForce), 0, 1e-14);
}
