// Unit test of the Lees-Edwards row interpolation: rows of 4 faces along
// x (L_x = 1, centres 0.125 .. 0.875) at two z; a point shifted by s lies
// between the two faces around x + s (modulo 1), weighted linearly, so a
// linear function of x is interpolated exactly away from the wrap, and a
// row that is not whole is an error.  The offset is gammaDot L_y t
// modulo L_x.

#include "leesEdwardsRowMap.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- Two rows of 4 faces at z = 0.25 and 0.75, the second in reverse order
vectorField rows()
{
    vectorField Cf;
    for (const scalar z : {0.25, 0.75})
    {
        for (label i = 0; i < 4; ++i)
        {
            const scalar x = 0.125 + 0.25*(z > 0.5 ? 3 - i : i);
            Cf.append(vector(x, 0, z));
        }
    }
    return Cf;
}

} // End anonymous namespace


TEST(leesEdwardsRowMap, shiftedPointsInterpolateLinearly)
{
    const vectorField Cf(rows());
    scalarField x(Cf.component(vector::X));
    for (const scalar s : {0.0, 0.3, -0.3, 0.25, 1.55})
    {
        const fdm::leesEdwardsRowMap map(Cf, Cf, s, 1, "test");
        const scalarField at(map.interpolate<scalar>(x));
        forAll(Cf, f)
        {
            // Exact where x + s and its two faces do not straddle the wrap
            scalar p = Cf[f].x() + s;
            p -= std::floor(p);
            if (p >= 0.125 && p <= 0.875)
            {
                EXPECT_NEAR(at[f], p, 1e-14) << "s " << s << " face " << f;
            }
        }
    }
}


TEST(leesEdwardsRowMap, wrapsPeriodicallyWithinTheRow)
{
    // 0.875 + 0.3 = 1.175, i.e. 0.175: 0.8 of the face at 0.125 and 0.2 of
    // the one at 0.375, of the same row (z = 0.75: faces 7 and 6)
    const vectorField Cf(rows());
    const fdm::leesEdwardsRowMap map(Cf, Cf, 0.3, 1, "test");
    scalarField values(Cf.size(), 0);
    values[7] = 1;
    EXPECT_NEAR(map.interpolate<scalar>(values)()[4], 0.8, 1e-14);
    values = 0;
    values[6] = 1;
    EXPECT_NEAR(map.interpolate<scalar>(values)()[4], 0.2, 1e-14);
    // Nothing from the other row
    values = 0;
    values[0] = values[1] = values[2] = values[3] = 1;
    EXPECT_NEAR(map.interpolate<scalar>(values)()[4], 0, 1e-14);
}


TEST(leesEdwardsRowMap, partialRowIsAnError)
{
    // Three faces of a row of spacing 0.25 do not span L_x = 1 (a split
    // along x)
    const vectorField Cf({vector(0.125, 0, 0), vector(0.375, 0, 0),
        vector(0.625, 0, 0)});
    const std::string msg = unitTest::errorOf
    (
        [&]() { fdm::leesEdwardsRowMap(Cf, Cf, 0.1, 1, "Patch p"); }
    );
    EXPECT_NE(msg.find("Patch p"), std::string::npos) << msg;
    EXPECT_NE(msg.find("not along x"), std::string::npos) << msg;
}


TEST(leesEdwardsRowMap, offsetIsTheShearDisplacementModuloLx)
{
    const boundBox box(point(0, 0, 0), point(2, 3, 1));
    EXPECT_NEAR(fdm::leesEdwardsOffset(1, box, 0.5), 1.5, 1e-14);
    EXPECT_NEAR(fdm::leesEdwardsOffset(1, box, 1), 1, 1e-14);
    EXPECT_NEAR(fdm::leesEdwardsOffset(0.5, box, 3), 0.5, 1e-14);
    EXPECT_NEAR(fdm::leesEdwardsOffset(-1, box, 0.5), 0.5, 1e-14);
}
