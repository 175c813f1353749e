// Unit test of fdm::setLeesEdwardsShear: the particle box takes the offset
// and shear velocity of the U field's leesEdwards patch at the mesh's time
// (unit box, shear rate 1: offset t modulo 1, velocity 1), and stays
// unsheared without one.

#include "leesEdwardsShear.H"
#include "shearedBox.H"
#include <gtest/gtest.h>

using namespace Foam;


TEST(leesEdwardsShear, boxTakesThePatchOffsetAndVelocity)
{
    shearedBox b("leesEdwardsShear", 4, 2.3);
    fdm::periodicBox box(point::zero, point::one,
        FixedList<bool, 3>({true, true, true}));
    EXPECT_FALSE(fdm::setLeesEdwardsShear(*b.mesh, box));
    EXPECT_EQ(box.shearOffset(), 0);

    const tmp<volVectorField> U(b.field<vector>("U"));
    EXPECT_TRUE(fdm::setLeesEdwardsShear(*b.mesh, box));
    EXPECT_NEAR(box.shearOffset(), 0.3, 1e-12);
    EXPECT_NEAR(box.shearVelocity(), 1.0, 1e-12);

    // A particle above the box comes back shifted and slower by the shear
    const point x(0.5, 1.2, 0.5);
    EXPECT_NEAR(box.wrap(x).x(), 0.2, 1e-12);
    EXPECT_NEAR(box.wrapVelocity(x, vector(1.2, 0, 0)).x(), 0.2, 1e-12);
}
