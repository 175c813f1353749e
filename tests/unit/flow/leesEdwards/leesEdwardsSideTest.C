// Unit test of the shared side of a Lees-Edwards patch on the unit box of
// shearedBox (8^3 cells, sides yMin and yMax), gammaDot = 2 at t = 0.3:
// the upper side is yMax; the offset is gammaDot L_y t modulo L_x = 0.6;
// the velocity jump is +gammaDot L_y along x from the upper side, minus it
// from the lower one, zero for a field that does not jump and for a
// scalar; the row map is made once per time index and anew in a copy.

#include "shearedBox.H"
#include "leesEdwardsSide.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(leesEdwardsSide, sidesOffsetAndJump)
{
    shearedBox box("leesEdwardsSide", 8, 0.3);
    const fvPatch& lower = box.mesh->boundary()["yMin"];
    const fvPatch& upper = box.mesh->boundary()["yMax"];
    EXPECT_FALSE(fdm::leesEdwardsSide::upper(lower));
    EXPECT_TRUE(fdm::leesEdwardsSide::upper(upper));

    const fdm::leesEdwardsSide velocity(2, true), other(2, false);
    EXPECT_NEAR(velocity.offset(upper), 0.6, 1e-14);
    EXPECT_EQ(velocity.jump<vector>(upper), vector(2, 0, 0));
    EXPECT_EQ(velocity.jump<vector>(lower), vector(-2, 0, 0));
    EXPECT_EQ(velocity.jump<scalar>(upper), 0);
    EXPECT_EQ(other.jump<vector>(upper), vector::zero);
}


TEST(leesEdwardsSide, mapKeptForItsTimeIndex)
{
    shearedBox box("leesEdwardsSideMap", 8, 0.3);
    const fvPatch& upper = box.mesh->boundary()["yMax"];
    const fvPatch& lower = box.mesh->boundary()["yMin"];
    const fdm::leesEdwardsSide side(1, true);
    const fdm::leesEdwardsRowMap* first = &side.map(upper, lower.Cf(), "p");
    EXPECT_EQ(&side.map(upper, lower.Cf(), "p"), first);
    EXPECT_EQ(first->size(), upper.size());

    // The row of the lower side's x values at the upper faces moved back
    // by the offset 0.3 (2.4 cells): x - 0.3 modulo 1, away from the wrap
    const scalarField x(lower.Cf().component(vector::X));
    const scalarField at(first->interpolate<scalar>(x));
    forAll(at, f)
    {
        const scalar p = upper.Cf()[f].x() - 0.3;
        if (p > 0.0625 && p < 0.9375)
        {
            EXPECT_NEAR(at[f], p, 1e-12) << f;
        }
    }

    const fdm::leesEdwardsSide copy(side);
    EXPECT_NE(&copy.map(upper, lower.Cf(), "p"), first);
    box.sc.runTime().setTime(0.4, 2);
    EXPECT_NEAR(side.offset(upper), 0.4, 1e-14);
}
