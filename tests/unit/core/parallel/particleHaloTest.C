// Unit tests of fdm::particleHalo (issue 38) on one rank, as rank 0 of the
// 2 x 1 x 1 split of the box [0, 4] x [0, 2] x [0, 2] laid out by hand:
// which particles rank 0 holds once the owners are set (its own, and the
// others within reach of its box, periodic images included), and after a
// move (its own only: nothing is received in serial).  The exchanges
// between ranks are tested by the distributed case tests (processorCrossing,
// adhesivePair, poiseuilleSuspension, subGridSqueeze).

#include "particleHalo.H"

#include "twoRankBoxes.H"

#include <gtest/gtest.h>

using namespace Foam;

const List<boundBox> halves(unitTest::twoRankBoxes());


TEST(particleHalo, replicatedHoldsEveryParticle)
{
    const fdm::particleHalo halo;
    EXPECT_FALSE(halo.distributed());
    EXPECT_TRUE(halo.holds(7));
    EXPECT_TRUE(halo.owns(7));
}


TEST(particleHalo, holdsItsOwnAndThoseWithinReach)
{
    // Rank 0's particle, rank 1's 0.3 from rank 0's box, rank 1's 1.5 away
    fdm::particleHalo halo(halves, scalarField(3, 0.5));
    EXPECT_TRUE(halo.distributed());
    const pointField x({point(1, 1, 1), point(2.3, 1, 1), point(3.5, 1, 1)});
    halo.setOwners(labelList({0, 1, 1}), x, List<vector>({vector::zero}));
    EXPECT_TRUE(halo.holds(0));
    EXPECT_TRUE(halo.owns(0));
    EXPECT_TRUE(halo.holds(1));
    EXPECT_FALSE(halo.owns(1));
    EXPECT_FALSE(halo.holds(2));
}


TEST(particleHalo, holdsAcrossThePeriodicFace)
{
    // Periodic in x: rank 1's particle at x = 3.8 is 0.2 from rank 0's box
    // through the cyclic face
    fdm::particleHalo halo(halves, scalarField(2, 0.5));
    const pointField x({point(1, 1, 1), point(3.8, 1, 1)});
    const List<vector> images
    ({vector::zero, vector(4, 0, 0), vector(-4, 0, 0)});
    halo.setOwners(labelList({0, 1}), x, images);
    EXPECT_TRUE(halo.holds(1));
    halo.setOwners(labelList({0, 1}), x, List<vector>({vector::zero}));
    EXPECT_FALSE(halo.holds(1));
}


TEST(particleHalo, aMoveKeepsOwnParticlesAndWhatIsReceived)
{
    fdm::particleHalo halo(halves, scalarField(2, 0.5));
    fdm::particleState s;
    s.position = pointField({point(1, 1, 1), point(2.3, 1, 1)});
    s.radius = scalarField(2, 0.1);
    s.resizeVelocities();
    const List<vector> none({vector::zero});
    halo.setOwners(labelList({0, 1}), s.position, none);
    EXPECT_TRUE(halo.holds(1));
    // Rank 1 sends nothing here: particle 1 is no longer current on rank 0
    halo.sendMoved(s, none);
    EXPECT_TRUE(halo.holds(0));
    EXPECT_FALSE(halo.holds(1));
}
