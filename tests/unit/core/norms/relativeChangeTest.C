// Unit tests for the relative change in the norm of thesis eq 2.54

#include "relativeChange.H"
#include "vectorField.H"

#include <gtest/gtest.h>

using namespace Foam;


TEST(relativeChange, sumOfMagnitudesNorm)
{
    // ||a|| = |(3,4,0)| + |(0,0,1)| = 6; ||a - b|| = |(0,0,0)| + |(0,0,2)|
    vectorField a(2);
    a[0] = vector(3, 4, 0);
    a[1] = vector(0, 0, 1);
    vectorField b(a);
    b[1] = vector(0, 0, -1);

    EXPECT_DOUBLE_EQ(fdm::relativeChange(a, b), 2.0/6.0);
}


TEST(relativeChange, unchangedFieldsGiveZero)
{
    const vectorField a(5, vector(1, -2, 3));
    EXPECT_EQ(fdm::relativeChange(a, a), 0);

    const vectorField zero(5, Zero);
    EXPECT_EQ(fdm::relativeChange(zero, zero), 0);
}


TEST(relativeChange, changeFromZeroIsLarge)
{
    const vectorField zero(3, Zero);
    const vectorField b(3, vector(1e-3, 0, 0));
    EXPECT_GT(fdm::relativeChange(zero, b), 1e100);
}


TEST(relativeChange, scalarFields)
{
    scalarField a(3, 2.0);
    scalarField b(3, 2.0);
    b[2] = 1.0;
    EXPECT_DOUBLE_EQ(fdm::relativeChange(a, b), 1.0/6.0);
}
