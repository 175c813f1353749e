// Unit tests for Foam::fdm::pointBins

#include "pointBins.H"

#include <gtest/gtest.h>
#include <algorithm>
#include <random>

using namespace Foam;

TEST(pointBins, findInSphereMatchesBruteForce)
{
    std::mt19937 gen(3);
    std::uniform_real_distribution<scalar> u(-2, 5);
    pointField pts(5000);
    for (point& p : pts)
    {
        p = point(u(gen), u(gen), 0.5*u(gen));
    }
    const fdm::pointBins bins(pts, 0.7);

    for (label q = 0; q < 50; ++q)
    {
        const point x(u(gen), u(gen), u(gen));
        const scalar R = 0.2 + 0.02*q;

        DynamicList<label> found;
        bins.findInSphere(x, R, found);
        std::sort(found.begin(), found.end());

        DynamicList<label> ref;
        forAll(pts, i)
        {
            if (mag(pts[i] - x) <= R)
            {
                ref.append(i);
            }
        }
        ASSERT_EQ(found.size(), ref.size()) << "query " << q;
        forAll(ref, i)
        {
            EXPECT_EQ(found[i], ref[i]);
        }
    }
}


TEST(pointBins, sphereOutsideThePointsFindsNothing)
{
    const pointField pts({point(0, 0, 0), point(1, 1, 1)});
    const fdm::pointBins bins(pts, 0.5);
    DynamicList<label> found;
    bins.findInSphere(point(3, 3, 3), 1, found);
    EXPECT_EQ(found.size(), 0);
    EXPECT_FALSE(bins.mayOverlap(point(3, 3, 3), 1));
}
