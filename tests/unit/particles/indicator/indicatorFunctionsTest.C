// Unit tests for Foam::fdm::indicatorFunctions (thesis 1, eqs 2.51-2.52)

#include "indicatorFunctions.H"

#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

TEST(indicatorFunctions, supportIsRadiusPlusCDelta)
{
    const fdm::indicatorFunctions J(5, 0.3, 0.2);
    EXPECT_DOUBLE_EQ(J.supportRadius(1.0), 1.06);
    EXPECT_TRUE(J.inSupport(1.06, 1.0));
    EXPECT_FALSE(J.inSupport(1.0600001, 1.0));
}


TEST(indicatorFunctions, JuIsHalfAtTheSurfaceAndTruncatedAtTheSupport)
{
    const scalar b = 5, c = 0.3, delta = 0.2, a = 1.4;
    const fdm::indicatorFunctions J(b, c, delta);

    EXPECT_DOUBLE_EQ(J.Ju(a, a), 0.5);
    // Inside the tanh profile tends to 1: at r = a - Delta, (1 + tanh 5)/2
    EXPECT_NEAR(J.Ju(a - delta, a), 0.5*(1 + std::tanh(b)), 1e-15);
    // Last value before the cut: (1 - tanh(b c))/2 = 0.0474...
    EXPECT_NEAR(J.Ju(a + c*delta, a), 0.5*(1 - std::tanh(b*c)), 1e-15);
    EXPECT_NEAR(J.Ju(a + c*delta, a), 0.04742587317756678, 1e-15);
    EXPECT_EQ(J.Ju(a + c*delta + 1e-12, a), 0);
}


TEST(indicatorFunctions, JlambdaIsSharpAtTheSupport)
{
    const fdm::indicatorFunctions J(5, 0.3, 0.2);
    EXPECT_EQ(J.Jlambda(0, 1), 1);
    EXPECT_EQ(J.Jlambda(1.06, 1), 1);
    EXPECT_EQ(J.Jlambda(1.0601, 1), 0);
}
