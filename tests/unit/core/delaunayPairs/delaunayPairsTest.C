// Unit tests for Foam::fdm::findDelaunayPairs (regular triangulation of a
// periodic sphere packing, CGAL), against references that do not use CGAL:
// the mean degree of the Poisson-Delaunay graph, the radical points of
// neighbouring spheres, and the invariance under periodic translation; a
// cell with walls also against the periodic cell its mirror images make

#include "delaunayPairs.H"
#include "mathematicalConstants.H"
#include "unitTestHelpers.H"

#include <gtest/gtest.h>
#include <random>
#include <set>
#include <string>

using namespace Foam;

namespace
{

typedef std::set<std::pair<label, label>> pairSet;

pairSet toSet(const UList<labelPair>& pairs)
{
    pairSet s;
    for (const labelPair& p : pairs)
    {
        s.insert({p.first(), p.second()});
    }
    return s;
}


fdm::periodicBox cube(const scalar L)
{
    return fdm::periodicBox(point::zero, point(L, L, L), {true, true, true});
}


//- A cell periodic in x and z with walls along y
fdm::periodicBox slab(const scalar L, const scalar H)
{
    return fdm::periodicBox(point::zero, point(L, H, L), {true, false, true});
}


//- Non-overlapping spheres of radii 1 and 1.4 (equal numbers) placed at
//  random in the periodic box, rejecting overlaps (random sequential
//  addition: volume fractions up to about 0.3)
void randomPacking
(
    const fdm::periodicBox& box,
    const label n,
    const unsigned seed,
    List<point>& x,
    List<scalar>& a
)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<scalar> u01(0, 1);
    x.setSize(0);
    a.setSize(0);
    while (x.size() < n)
    {
        const point p
        (
            box.min() + cmptMultiply(box.span(), vector(u01(gen), u01(gen), u01(gen)))
        );
        const scalar r = (x.size() % 2) ? 1.4 : 1.0;
        bool free = true;
        forAll(x, k)
        {
            free = free && mag(box.minimumImage(p - x[k])) > r + a[k];
        }
        if (free)
        {
            x.append(p);
            a.append(r);
        }
    }
}


//- Pairs that must be neighbours: the point c of the segment i-j where
//  the powers |c - x|^2 - r^2 of i and j are equal lies in the power cells
//  of i and j alone (every other sphere's power at c is larger), so the
//  cells share a face there
pairSet radicalPointPairs
(
    const fdm::periodicBox& box,
    const List<point>& x,
    const List<scalar>& a
)
{
    pairSet must;
    forAll(x, i)
    {
        for (label j = i + 1; j < x.size(); ++j)
        {
            const vector dij = box.minimumImage(x[j] - x[i]);
            const scalar d = mag(dij);
            const scalar t = (sqr(d) + sqr(a[i]) - sqr(a[j]))/(2*d);
            const point c = x[i] + t/d*dij;
            const scalar power = sqr(t) - sqr(a[i]);
            bool alone = true;
            forAll(x, k)
            {
                if (k != i && k != j)
                {
                    const scalar pk =
                        magSqr(box.minimumImage(c - x[k])) - sqr(a[k]);
                    alone = alone && pk > power + 1e-9;
                }
            }
            if (alone)
            {
                must.insert({i, j});
            }
        }
    }
    return must;
}


//- The pairs of a random packing (randomPacking) of n spheres in box
pairSet packedPairs
(
    const fdm::periodicBox& box,
    const label n,
    const unsigned seed,
    List<point>& x,
    List<scalar>& a
)
{
    randomPacking(box, n, seed, x, a);
    DynamicList<labelPair> pairs;
    fdm::findDelaunayPairs(box, x, a, pairs);
    return toSet(pairs);
}


//- Random packing of n spheres in box: its pairs include every pair of
//  radicalPointPairs, and none is longer than 8 (the neighbours of a
//  dense-ish packing are a few radii apart)
void expectRadicalPairsAndShortEdges
(
    const fdm::periodicBox& box,
    const label n,
    const unsigned seed
)
{
    List<point> x;
    List<scalar> a;
    const pairSet found(packedPairs(box, n, seed, x, a));
    const pairSet must(radicalPointPairs(box, x, a));
    ASSERT_GT(must.size(), x.size());
    for (const auto& p : must)
    {
        EXPECT_TRUE(found.count(p)) << "pair " << p.first << " " << p.second;
    }
    for (const auto& p : found)
    {
        EXPECT_LT(mag(box.minimumImage(x[p.second] - x[p.first])), 8);
    }
}

} // namespace


// Meijering (1953): the mean number of Delaunay neighbours of a point of a
// Poisson process in 3D is 2 + 48 pi^2/35 = 15.535
TEST(delaunayPairs, PoissonMeanDegreeIsMeijerings)
{
    const label n = 4000;
    const fdm::periodicBox box(cube(10));
    std::mt19937 gen(7);
    std::uniform_real_distribution<scalar> u01(0, 10);
    List<point> x(n);
    for (point& p : x)
    {
        p = point(u01(gen), u01(gen), u01(gen));
    }
    const List<scalar> a(n, 0.0);
    DynamicList<labelPair> pairs;
    fdm::findDelaunayPairs(box, x, a, pairs);

    const scalar meanDegree = 2.0*pairs.size()/n;
    const scalar meijering =
        2 + 48*sqr(constant::mathematical::pi)/35;
    // Three standard errors of the mean degree over 4000 points (degree
    // standard deviation about 3.4); measured 15.56.  Images cut too close
    // to the faces give 15.65 (and PeriodicTranslationKeepsThePairs fails)
    EXPECT_NEAR(meanDegree, meijering, 0.15);
}


TEST(delaunayPairs, RadicalPointNeighboursAreFound)
{
    for (const scalar shearOffset : {0.0, 3.7})
    {
        SCOPED_TRACE("shear offset " + std::to_string(shearOffset));
        fdm::periodicBox box(cube(16));
        box.setShearOffset(shearOffset);
        expectRadicalPairsAndShortEdges(box, 150, 3);   // volume fraction 0.29
    }
}


TEST(delaunayPairs, TouchingSpheresAreNeighbours)
{
    const fdm::periodicBox box(cube(16));
    List<point> x;
    List<scalar> a;
    randomPacking(box, 120, 5, x, a);
    // Move sphere 1 against sphere 0, along a free direction when possible
    x[1] = box.wrap(x[0] + vector(a[0] + a[1], 0, 0));
    DynamicList<labelPair> pairs;
    fdm::findDelaunayPairs(box, x, a, pairs);
    EXPECT_TRUE(toSet(pairs).count({0, 1}));
}


TEST(delaunayPairs, PeriodicTranslationKeepsThePairs)
{
    for (const scalar shearOffset : {0.0, 5.2})
    {
        fdm::periodicBox box(cube(18));
        box.setShearOffset(shearOffset);
        List<point> x;
        List<scalar> a;
        randomPacking(box, 200, 11, x, a);  // volume fraction 0.27
        DynamicList<labelPair> pairs;
        fdm::findDelaunayPairs(box, x, a, pairs);

        // The same packing seen from another origin (images wrapped in)
        List<point> shifted(x.size());
        forAll(x, i)
        {
            shifted[i] = box.wrap(x[i] + vector(4.3, 7.9, 2.2));
        }
        DynamicList<labelPair> shiftedPairs;
        const fdm::delaunayStatistics stats =
            fdm::findDelaunayPairs(box, shifted, a, shiftedPairs);

        EXPECT_EQ(toSet(pairs), toSet(shiftedPairs));
        EXPECT_EQ(stats.nHidden, 0);
        EXPECT_GT(stats.nPoints, x.size());
    }
}


// Without the mirror images the convex hull's edges would join spheres
// along the walls across the whole cell
TEST(delaunayPairs, WalledRadicalPointNeighboursAreFound)
{
    expectRadicalPairsAndShortEdges(slab(16, 14), 130, 17); // fraction 0.29
}


// Reference by another path: the spheres and their mirror images in the
// upper wall's plane fill a cell periodic in y with twice the walls'
// distance (the two reflections compose to that translation), whose
// periodic triangulation has the walled cell's pairs between the spheres
TEST(delaunayPairs, WallsAreTheMirroredCellsPairs)
{
    List<point> x;
    List<scalar> a;
    const pairSet pairs(packedPairs(slab(16, 14), 130, 23, x, a));

    scalar lo = GREAT;
    scalar hi = -GREAT;
    forAll(x, i)
    {
        lo = min(lo, x[i].y() - a[i]);
        hi = max(hi, x[i].y() + a[i]);
    }
    const label n = x.size();
    List<point> doubled(2*n);
    List<scalar> doubledRadii(2*n);
    forAll(x, i)
    {
        doubled[i] = x[i];
        doubled[n + i] = point(x[i].x(), 2*hi - x[i].y(), x[i].z());
        doubledRadii[i] = doubledRadii[n + i] = a[i];
    }
    const fdm::periodicBox periodic
    (
        point(0, lo, 0), point(16, lo + 2*(hi - lo), 16), {true, true, true}
    );
    DynamicList<labelPair> periodicPairs;
    fdm::findDelaunayPairs(periodic, doubled, doubledRadii, periodicPairs);

    pairSet reference;
    for (const labelPair& p : periodicPairs)
    {
        if (p.first() < n && p.second() < n)
        {
            reference.insert({p.first(), p.second()});
        }
    }
    EXPECT_EQ(pairs, reference);
}


TEST(delaunayPairs, WalledCellReflectedKeepsThePairs)
{
    const fdm::periodicBox box(slab(16, 14));
    List<point> x;
    List<scalar> a;
    const pairSet pairs(packedPairs(box, 130, 29, x, a));

    // Upside down and shifted along the periodic x and z
    List<point> moved(x.size());
    forAll(x, i)
    {
        moved[i] = box.wrap(point(x[i].x() + 5.1, 14 - x[i].y(), x[i].z() + 9.3));
    }
    DynamicList<labelPair> movedPairs;
    fdm::findDelaunayPairs(box, moved, a, movedPairs);
    EXPECT_EQ(pairs, toSet(movedPairs));
}
