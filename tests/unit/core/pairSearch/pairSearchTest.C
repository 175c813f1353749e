// Unit tests for Foam::fdm::findNearPairs (cell-linked list) and
// Foam::fdm::smallestSurfaceGap

#include "pairSearch.H"
#include "boolList.H"
#include "UIndirectList.H"
#include "ListOps.H"

#include <gtest/gtest.h>
#include <random>
#include <set>

using namespace Foam;

namespace
{

// Reference: all pairs by brute force with the minimum-image convention
std::set<std::pair<label, label>> bruteForcePairs(const fdm::periodicBox& box,
    const List<point>& x, const List<scalar>& a, const scalar cutoff)
{
    std::set<std::pair<label, label>> pairs;
    forAll(x, i)
    {
        for (label j = i + 1; j < x.size(); ++j)
        {
            const vector d = box.minimumImage(x[j] - x[i]);
            if (mag(d) < a[i] + a[j] + cutoff)
            {
                pairs.insert({i, j});
            }
        }
    }
    return pairs;
}

//- n spheres of radius 1 or 1.4 placed at random in the box (overlaps
//  allowed: the search does not care)
void randomSpheres(const fdm::periodicBox& box, const label n,
    const unsigned seed, List<point>& x, List<scalar>& a)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<scalar> u01(0, 1);
    x.setSize(n);
    a.setSize(n);
    forAll(x, i)
    {
        for (direction d = 0; d < 3; ++d)
        {
            x[i][d] = box.min()[d] + box.span()[d]*u01(gen);
        }
        a[i] = u01(gen) < 0.5 ? 1.0 : 1.4;
    }
}

void compareWithBruteForce(const fdm::periodicBox& box, const label n,
    const unsigned seed)
{
    List<point> x;
    List<scalar> a;
    randomSpheres(box, n, seed, x, a);

    DynamicList<labelPair> pairs;
    fdm::findNearPairs(box, x, a, 0.3, pairs);

    const auto ref = bruteForcePairs(box, x, a, 0.3);
    ASSERT_EQ(label(ref.size()), pairs.size());
    for (const labelPair& p : pairs)
    {
        EXPECT_LT(p.first(), p.second());
        EXPECT_EQ(ref.count({p.first(), p.second()}), 1u);
    }
}

// Smallest gap below cutoff from a neighbour list of twice the reach
scalar smallestGap
(
    const fdm::periodicBox& box,
    const List<point>& x,
    const List<scalar>& a,
    const scalar cutoff
)
{
    DynamicList<labelPair> near;
    fdm::findNearPairs(box, x, a, 2*cutoff, near);
    return fdm::smallestSurfaceGap(box, x, a, cutoff, near);
}

} // namespace


TEST(pairSearch, selectionFromALargerSearchIsTheSmallerSearch)
{
    // One search at the largest reach serves every interaction: selecting
    // gives the pairs, in order, that a search at the smaller cutoff gives
    const fdm::periodicBox box(point(0, -10, 0), point(20, 10, 20),
        FixedList<bool, 3>({true, false, true}));
    List<point> x;
    List<scalar> a;
    randomSpheres(box, 600, 7, x, a);
    DynamicList<labelPair> wide, narrow, selected;
    fdm::findNearPairs(box, x, a, 2, wide);
    for (const scalar cutoff : {0.0, 5e-3, 0.3, 2.0})
    {
        fdm::findNearPairs(box, x, a, cutoff, narrow);
        fdm::selectNearPairs(box, x, a, cutoff, wide, selected);
        ASSERT_EQ(selected.size(), narrow.size()) << cutoff;
        forAll(narrow, k)
        {
            EXPECT_EQ(selected[k], narrow[k]);
        }
    }
    EXPECT_GT(narrow.size(), 0);
    EXPECT_LT(narrow.size(), wide.size() + 1);
}


TEST(pairSearch, searchFromSomeParticlesGivesTheirPairsOfTheWholeSearch)
{
    // A rank searching from the particles it owns (every third one, and
    // the last) finds, in order, the pairs of the whole search with one of
    // them, across the periodic faces too; from all it is the whole search
    const fdm::periodicBox box(point(0, -10, 0), point(20, 10, 20),
        FixedList<bool, 3>({true, false, true}));
    const label n = 500;
    List<point> x;
    List<scalar> a;
    randomSpheres(box, n, 11, x, a);
    DynamicList<label> owned;
    for (label i = 0; i < n; i += 3)
    {
        owned.append(i);
    }
    owned.append(n - 1);
    boolList isOwned(n, false);
    UIndirectList<bool>(isOwned, owned) = true;

    DynamicList<labelPair> whole, fromOwned, fromAll;
    fdm::findNearPairs(box, x, a, 0.3, whole);
    fdm::findNearPairs(box, x, a, 0.3, owned, fromOwned);
    fdm::findNearPairs(box, x, a, 0.3, identity(n), fromAll);
    DynamicList<labelPair> expected;
    for (const labelPair& pq : whole)
    {
        if (isOwned[pq.first()] || isOwned[pq.second()])
        {
            expected.append(pq);
        }
    }
    ASSERT_GT(expected.size(), 0);
    ASSERT_LT(expected.size(), whole.size());
    ASSERT_EQ(fromOwned.size(), expected.size());
    forAll(expected, k)
    {
        EXPECT_EQ(fromOwned[k], expected[k]);
    }
    ASSERT_EQ(fromAll.size(), whole.size());
    forAll(whole, k)
    {
        EXPECT_EQ(fromAll[k], whole[k]);
    }
}


TEST(pairSearch, matchesBruteForceInAPeriodicChannel)
{
    const fdm::periodicBox box(point(0, -10, 0), point(20, 10, 20),
        FixedList<bool, 3>({true, false, true}));
    compareWithBruteForce(box, 800, 1);
}


TEST(pairSearch, matchesBruteForceWhenTheBoxHoldsFewerThanThreeBins)
{
    // 7 wide with bins of 3.1: two bins per direction, so the periodic
    // neighbour search wraps onto the same bin twice
    const fdm::periodicBox box(point(0, 0, 0), point(7, 7, 7),
        FixedList<bool, 3>({true, true, true}));
    compareWithBruteForce(box, 40, 2);
}


TEST(pairSearch, matchesBruteForceAcrossLeesEdwardsFaces)
{
    // Sheared periodic cell: the rows across the y faces are shifted images;
    // offsets of whole, fractional and nearly whole bins, and both signs of
    // the crossing, must all find every pair the minimum image finds
    for (const scalar offset : {0.0, 1.3, 4.9, 7.2, 11.95, 19.0})
    {
        fdm::periodicBox box(point(0, 0, 0), point(20, 15, 12),
            FixedList<bool, 3>({true, true, true}));
        box.setShearOffset(offset);
        compareWithBruteForce(box, 400, 3);
    }
}


TEST(pairSearch, smallestSurfaceGapAcrossAPeriodicFaceAndToAWall)
{
    // Channel: walls at y = -10 and 10, periodic in x and z (span 20)
    const fdm::periodicBox box(point(0, -10, 0), point(20, 10, 20),
        FixedList<bool, 3>({true, false, true}));
    // Pair through the x face: centres 0.5 and 19.2 are 1.3 apart,
    // gap 1.3 - 1 - 0.25 = 0.05; the second sphere 0.2 from the top wall
    List<point> x({point(0.5, 0, 5), point(19.2, 0, 5), point(10, 8.8, 10)});
    List<scalar> a({1, 0.25, 1});
    EXPECT_NEAR(smallestGap(box, x, a, 1), 0.05, 1e-12);

    x[2].y() = 8.96;
    EXPECT_NEAR(smallestGap(box, x, a, 1), 0.04, 1e-12);

    // Overlap is negative; nothing within the cut-off gives the cut-off
    x[1].x() = 19.6;
    EXPECT_NEAR(smallestGap(box, x, a, 1), -0.35, 1e-12);
    const List<point> far({point(5, 0, 5), point(15, 0, 15)});
    const List<scalar> unit({1, 1});
    EXPECT_EQ(smallestGap(box, far, unit, 0.5), 0.5);
}
