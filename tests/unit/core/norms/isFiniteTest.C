// Unit test of isFinite: NaN or infinity in any component is caught, and
// large finite components are finite (no overflow of a component sum).

#include "isFinite.H"
#include "vector.H"
#include "symmTensor.H"
#include <gtest/gtest.h>
#include <limits>

using namespace Foam;

TEST(isFinite, anyNonFiniteComponent)
{
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    const scalar inf = std::numeric_limits<scalar>::infinity();
    EXPECT_TRUE(fdm::isFinite(scalar(1)));
    EXPECT_FALSE(fdm::isFinite(nan));
    EXPECT_TRUE(fdm::isFinite(vector(1, 2, 3)));
    EXPECT_FALSE(fdm::isFinite(vector(1, nan, 3)));
    EXPECT_FALSE(fdm::isFinite(vector(1, 2, -inf)));
    EXPECT_FALSE(fdm::isFinite(symmTensor(0, 0, 0, 0, 0, inf)));
    // Each component finite although their sum overflows
    EXPECT_TRUE(fdm::isFinite(vector(1e308, 1e308, 1e308)));
}
