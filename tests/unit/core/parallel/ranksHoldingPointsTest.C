// Unit test of fdm::ranksHoldingPoints on one rank: a point inside the
// cells (a 4 x 3 x 2 block of cubes of side 0.5, corners and faces
// included) is held by rank 0, a point outside by none (-1).

#include "ranksHoldingPoints.H"
#include "pointBins.H"

#include <gtest/gtest.h>

using namespace Foam;

TEST(ranksHoldingPoints, pointsInTheCellsBelongToThisRank)
{
    const scalar delta = 0.5;
    pointField centres;
    for (label k = 0; k < 2; ++k)
    for (label j = 0; j < 3; ++j)
    for (label i = 0; i < 4; ++i)
    {
        centres.append(delta*point(i + 0.5, j + 0.5, k + 0.5));
    }
    const fdm::pointBins bins(centres, 2*delta);

    const pointField points
    ({
        point(0.1, 0.2, 0.3),       // inside
        point(0, 0, 0),             // a corner of the block
        point(2, 1.5, 1),           // the opposite corner
        point(0.5, 0.75, 0.25),     // on a face between two cells
        point(2.01, 1, 0.5),        // just outside in x
        point(1, -0.01, 0.5),       // just outside in y
        point(1, 1, 3)              // far away
    });
    const labelList rank
    (
        fdm::ranksHoldingPoints(points, centres, bins, delta)
    );
    EXPECT_EQ(rank, labelList({0, 0, 0, 0, -1, -1, -1}));
}
