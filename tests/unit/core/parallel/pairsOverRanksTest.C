// Unit tests for Foam::fdm::shareWithOwners and gatherOnMaster (issue 38)
// on one rank: nothing to share (the history keeps its pairs and states),
// the gather returns the rank's own list; the ranks together are tested by
// the case test adhesivePair (a bonded frictional doublet tumbling across
// a processor boundary)

#include "pairsOverRanks.H"
#include "vector.H"

#include <gtest/gtest.h>

using namespace Foam;

TEST(shareWithOwners, oneRankKeepsItsHistory)
{
    fdm::pairHistory<vector> h;
    h.append(labelPair(1, 2), vector(1, 0, 0));
    h.append(labelPair(0, -1), vector(0, 2, 0));
    h.sort();
    fdm::shareWithOwners(h, labelList({0, 0, 0}));
    ASSERT_EQ(h.size(), 2);
    EXPECT_EQ(h.pair(0), labelPair(0, -1));
    EXPECT_EQ(h[h.find(labelPair(1, 2))], vector(1, 0, 0));
}


TEST(gatherOnMaster, oneRankGetsItsOwnList)
{
    const List<labelPair> mine({labelPair(3, 4), labelPair(0, 1)});
    const List<labelPair> all(fdm::gatherOnMaster(mine));
    ASSERT_EQ(all.size(), 2);
    EXPECT_EQ(all[0], labelPair(3, 4));
    EXPECT_EQ(all[1], labelPair(0, 1));
}
