// Unit tests for the lambda residuals that end a solve (thesis eq 2.54)

#include "lambdaTolerances.H"

#include <gtest/gtest.h>

using namespace Foam;


TEST(lambdaTolerances, firstSolveThenRecordedOrBetween)
{
    const fdm::lambdaTolerances t{1e-3, 1e-4, 1e-2};

    // The first solve of a run, whether it writes or not
    EXPECT_EQ(t.of(false, true), 1e-4);
    EXPECT_EQ(t.of(false, false), 1e-4);
    // Later: a step that writes, a step that does not
    EXPECT_EQ(t.of(true, true), 1e-3);
    EXPECT_EQ(t.of(true, false), 1e-2);
}


TEST(lambdaTolerances, onlyStepsAboveTheRecordedToleranceAreLoose)
{
    const fdm::lambdaTolerances t{1e-3, 1e-4, 1e-2};
    EXPECT_FALSE(t.loose(false, false));
    EXPECT_FALSE(t.loose(true, true));
    EXPECT_TRUE(t.loose(true, false));

    // Without a looser tolerance between records no step is loose
    const fdm::lambdaTolerances same{1e-3, 1e-4, 1e-3};
    EXPECT_FALSE(same.loose(true, false));

    // A first solve looser than the recorded steps is loose too
    const fdm::lambdaTolerances looseStart{1e-3, 1e-2, 1e-3};
    EXPECT_TRUE(looseStart.loose(false, true));
}


// ************************************************************************* //
