// Unit tests for Foam::fdm::sumToOwners, keepOwned and sumPairsToOwners
// (issue 38) on one rank: the owner keeps its sums (its entries), the
// records of particles (or pairs) another rank owns are zeroed, and an
// empty owner list leaves every record (sumOverRanks); the ranks together
// are tested by the distributed case tests (processorCrossing,
// subGridSqueeze, adhesivePair, poiseuilleSuspension) and ranksAgreement)

#include "sumToOwners.H"
#include "rigidBodyMoments.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

struct touchesAll
{
    bool touches(const label) const { return true; }
};

List<fdm::rigidBodyMoments> threeMoments()
{
    List<fdm::rigidBodyMoments> m(3);
    forAll(m, p)
    {
        m[p].add(1 + p, vector(0.1*p, -0.2, 0.3), 1);
    }
    return m;
}

} // namespace


TEST(sumToOwners, keepsOwnSumsAndZeroesOthers)
{
    List<fdm::rigidBodyMoments> m(threeMoments());
    const List<fdm::rigidBodyMoments> before(m);
    fdm::sumToOwners(m, labelList({0, 1, 0}), touchesAll());
    for (const label p : {0, 2})
    {
        for (direction r = 0; r < 6; ++r)
        {
            for (direction c = 0; c < 6; ++c)
            {
                EXPECT_EQ(m[p].entry(r, c), before[p].entry(r, c));
            }
        }
    }
    scalar other = 0;
    m[1].forEachScalar([&](scalar& s) { other += mag(s); });
    EXPECT_EQ(other, 0);
    EXPECT_NE(before[1].entry(0, 0), 0);
}


TEST(sumToOwners, withoutOwnersEveryRankHoldsEverySum)
{
    List<fdm::rigidBodyMoments> m(threeMoments());
    const List<fdm::rigidBodyMoments> before(m);
    fdm::sumToOwners(m, labelList(), touchesAll());
    forAll(m, p)
    {
        EXPECT_EQ(m[p].entry(1, 1), before[p].entry(1, 1)) << p;
        EXPECT_EQ(m[p].entry(3, 4), before[p].entry(3, 4)) << p;
    }
}


TEST(keepOwned, keepsOwnEntriesAndZeroesOthers)
{
    List<vector> f({vector(1, 2, 3), vector(4, 5, 6), vector(7, 8, 9)});
    fdm::keepOwned(f, labelList({0, 1, 0}));
    EXPECT_EQ(f[0], vector(1, 2, 3));
    EXPECT_EQ(f[1], vector::zero);
    EXPECT_EQ(f[2], vector(7, 8, 9));
}


TEST(sumPairsToOwners, keepsPairsWithAnOwnParticleAndZeroesOthers)
{
    // Particles 0 and 2 are this rank's, 1 and 3 another's: the pairs
    // (0, 1) and (1, 2) keep their records, (1, 3) is zeroed
    const List<labelPair> pairs({labelPair(0, 1), labelPair(1, 2),
        labelPair(1, 3)});
    List<fdm::rigidBodyMoments> m(threeMoments());
    const List<fdm::rigidBodyMoments> before(m);
    fdm::sumPairsToOwners(pairs, m, labelList({0, 1, 0, 1}), touchesAll());
    EXPECT_EQ(m[0].entry(2, 2), before[0].entry(2, 2));
    EXPECT_EQ(m[1].entry(0, 0), before[1].entry(0, 0));
    scalar other = 0;
    m[2].forEachScalar([&](scalar& s) { other += mag(s); });
    EXPECT_EQ(other, 0);
    EXPECT_NE(before[2].entry(0, 0), 0);
}
