// Unit tests for Foam::fdm::pairHistory: the per-pair states carried from
// step to step, against std::map (the container the FDM contacts used
// before) on random pair lists

#include "pairHistory.H"
#include "scalarList.H"
#include "SubList.H"

#include <gtest/gtest.h>
#include <map>
#include <random>

using namespace Foam;

namespace
{

typedef std::map<std::pair<label, label>, scalar> referenceMap;

// Random distinct pairs: particle pairs (i < j) and wall pairs (i, -1 - w)
referenceMap randomPairs(std::mt19937& gen, const label n)
{
    std::uniform_int_distribution<label> particle(0, 30), wall(0, 1);
    std::uniform_real_distribution<scalar> value(-1, 1);
    referenceMap pairs;
    while (label(pairs.size()) < n)
    {
        const label i = particle(gen);
        const label j = gen() % 4 ? particle(gen) : -1 - wall(gen);
        if (j != i && (j < 0 || j > i))
        {
            pairs[{i, j}] = value(gen);
        }
    }
    return pairs;
}

} // namespace


TEST(PairHistory, AppendedPairsSortLikeTheMap)
{
    std::mt19937 gen(7);
    const referenceMap reference = randomPairs(gen, 60);

    // Appended in reverse order, looked up after the sort
    fdm::pairHistory<scalar> history;
    for (auto it = reference.rbegin(); it != reference.rend(); ++it)
    {
        history.append(labelPair(it->first.first, it->first.second),
            it->second);
    }
    EXPECT_TRUE(history.sort());

    ASSERT_EQ(history.size(), label(reference.size()));
    label k = 0;
    for (const auto& e : reference)
    {
        EXPECT_EQ(history.pair(k), labelPair(e.first.first, e.first.second));
        EXPECT_EQ(history[k], e.second);
        EXPECT_EQ(history.find(history.pair(k)), k);
        ++k;
    }
    EXPECT_EQ(history.find(labelPair(31, 32)), -1);
    EXPECT_EQ(history.get(labelPair(31, 32), 5.0), 5.0);
}


TEST(PairHistory, WallPairsSortBeforeParticlePairs)
{
    fdm::pairHistory<scalar> history;
    history.append(labelPair(3, 4), 1);
    history.append(labelPair(3, -1), 2);
    history.append(labelPair(3, -2), 3);
    history.append(labelPair(2, 9), 4);
    EXPECT_TRUE(history.sort());
    EXPECT_EQ(history.pair(0), labelPair(2, 9));
    EXPECT_EQ(history.pair(1), labelPair(3, -2));
    EXPECT_EQ(history.pair(2), labelPair(3, -1));
    EXPECT_EQ(history.pair(3), labelPair(3, 4));
}


TEST(PairHistory, CarryKeepsStayingPairsAndStartsNewOnes)
{
    std::mt19937 gen(11);
    const referenceMap before = randomPairs(gen, 80);
    const referenceMap after = randomPairs(gen, 80);

    fdm::pairHistory<scalar> history;
    for (const auto& e : before)
    {
        history.append(labelPair(e.first.first, e.first.second), e.second);
    }
    history.sort();

    List<labelPair> next;
    for (const auto& e : after)
    {
        next.append(labelPair(e.first.first, e.first.second));
    }
    const scalar fresh = 99;
    history.carry(next, fresh);

    ASSERT_EQ(history.size(), next.size());
    label kept = 0;
    forAll(next, k)
    {
        const auto old = before.find({next[k].first(), next[k].second()});
        EXPECT_EQ(history.pair(k), next[k]);
        EXPECT_EQ(history[k], old == before.end() ? fresh : old->second);
        kept += old != before.end();
    }
    // Both branches were exercised
    EXPECT_GT(kept, 0);
    EXPECT_LT(kept, next.size());
}


TEST(PairHistory, RepeatedPairIsReported)
{
    fdm::pairHistory<scalar> history;
    const List<labelPair> pairs({labelPair(1, 2), labelPair(0, 5),
        labelPair(1, 2)});
    EXPECT_FALSE(history.reset(pairs, scalarList({1, 2, 3})));
    // The first state of the repeated pair is kept
    ASSERT_EQ(history.size(), 2);
    EXPECT_EQ(history.pair(0), labelPair(0, 5));
    EXPECT_EQ(history[1], 1);

    const SubList<labelPair> distinct(pairs, 2);
    EXPECT_TRUE(history.reset(distinct, scalarList({1, 2})));
}
