// Unit tests of fdm::ranksWithinReach (issue 38): which other ranks need a
// particle as a ghost, against boxes laid out by hand: a 2 x 1 x 1 split
// of the box [0, 4] x [0, 2] x [0, 2], with and without periodicity in x,
// and with a Lees-Edwards shift.

#include "ranksWithinReach.H"

#include "twoRankBoxes.H"

#include <gtest/gtest.h>

using namespace Foam;

const List<boundBox> halves(unitTest::twoRankBoxes());


TEST(ranksWithinReach, distanceToABox)
{
    const boundBox b(point(0, 0, 0), point(1, 2, 3));
    EXPECT_EQ(fdm::squaredDistanceToBox(point(0.5, 1, 1), b), 0);
    EXPECT_NEAR(fdm::squaredDistanceToBox(point(1.5, 1, 1), b), 0.25, 1e-15);
    // Beyond a corner: the distance to the corner
    EXPECT_NEAR(fdm::squaredDistanceToBox(point(-1, -1, 4), b), 3, 1e-15);
}


TEST(ranksWithinReach, theNeighbourWithinTheHalo)
{
    // Rank 0's particles: 0.4 from rank 1's box (reach 0.5, then 0.3),
    // and one in the middle of rank 0's box
    const pointField x({point(1.6, 1, 1), point(1.6, 1, 1), point(1, 1, 1)});
    const scalarField reach({0.5, 0.3, 0.5});
    const List<vector> none({vector::zero});
    const List<labelList> r
    (
        fdm::ranksWithinReach(x, reach, halves, none, 0)
    );
    // Rank 0's own box holds all three: it is never listed
    EXPECT_EQ(r[0], labelList({1}));
    EXPECT_EQ(r[1], labelList());
    EXPECT_EQ(r[2], labelList());
    // Seen from rank 1, the owner's box is listed
    EXPECT_EQ(fdm::ranksWithinReach(x, reach, halves, none, 1)[2],
              labelList({0}));
}


TEST(ranksWithinReach, acrossTheCyclicPatch)
{
    // Periodic in x with span 4: rank 1's particle at x = 3.8 reaches rank
    // 0's box through its image at -0.2; without the image it does not
    const pointField x({point(3.8, 1, 1)});
    const scalarField reach(1, 0.5);
    const List<vector> periodicX({vector::zero, vector(-4, 0, 0),
                                  vector(4, 0, 0)});
    EXPECT_EQ(fdm::ranksWithinReach(x, reach, halves, periodicX, 1)[0],
              labelList({0}));
    EXPECT_EQ
    (
        fdm::ranksWithinReach(x, reach, halves, List<vector>({vector::zero}), 1)[0],
        labelList()
    );
}


TEST(ranksWithinReach, acrossShearedFaces)
{
    // Boxes split along y, Lees-Edwards across y (span 2) with an offset
    // of 1.5 along x: the image above y = 2 sits 1.5 further along x.
    // Rank 0's particle at (3.8, 0.1) has its image at (5.3, 2.1), 0.1
    // from rank 1's box, which starts at x = 5; the unsheared image
    // (3.8, 2.1) is 1.2 from it
    const List<boundBox> layers
    ({
        boundBox(point(0, 0, 0), point(4, 1, 2)),
        boundBox(point(5, 1, 0), point(8, 2, 2))
    });
    const pointField x({point(3.8, 0.1, 1)});
    const scalarField reach(1, 0.5);
    const List<vector> sheared({vector::zero, vector(1.5, 2, 0),
                                vector(-1.5, -2, 0)});
    const List<vector> unsheared({vector::zero, vector(0, 2, 0),
                                  vector(0, -2, 0)});
    EXPECT_EQ(fdm::ranksWithinReach(x, reach, layers, sheared, 0)[0],
              labelList({1}));
    EXPECT_EQ(fdm::ranksWithinReach(x, reach, layers, unsheared, 0)[0],
              labelList());
}
