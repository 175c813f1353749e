// Unit test of checkTimeControls and lastStepOfRun on the Time of a scratch
// case: deltaT must be > 0, endTime not before the start; the last step is
// the one within half a step of endTime.  (An overflowing deltaT, 1e400,
// never reaches the check: OpenFOAM's dictionary reader refuses it.)

#include "checkTimeControls.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

std::string errorFor(const std::string& controls)
{
    unitTest::scratchCase sc
    (
        "checkTimeControls", "startFrom startTime; " + controls
    );
    return unitTest::errorOf([&]{ fdm::checkTimeControls(sc.runTime()); });
}

} // End anonymous namespace


TEST(checkTimeControls, acceptsAForwardRun)
{
    EXPECT_EQ(errorFor("startTime 0; endTime 1; deltaT 0.1;"), "");
    EXPECT_EQ(errorFor("startTime 1; endTime 1; deltaT 0.1;"), "");
}


TEST(checkTimeControls, refusesAStepThatIsNotPositiveAndFinite)
{
    for (const char* dt : {"0", "-0.1"})
    {
        const std::string msg = errorFor
        (
            std::string("startTime 0; endTime 1; deltaT ") + dt + ";"
        );
        EXPECT_NE(msg.find("deltaT"), std::string::npos) << dt << ": " << msg;
        EXPECT_NE(msg.find("finite numbers > 0"), std::string::npos) << msg;
    }
}


TEST(checkTimeControls, refusesAnEndBeforeTheStart)
{
    const std::string msg = errorFor("startTime 2; endTime 1; deltaT 0.1;");
    EXPECT_NE(msg.find("endTime 1"), std::string::npos) << msg;
    EXPECT_NE(msg.find(">= the start time"), std::string::npos) << msg;
}


TEST(checkTimeControls, lastStepIsWithinHalfAStepOfTheEnd)
{
    unitTest::scratchCase sc
    (
        "lastStep", "startTime 0; endTime 0.3; deltaT 0.1;"
    );
    Time& runTime = sc.runTime();
    label steps = 0;
    while (!fdm::lastStepOfRun(runTime))
    {
        ++runTime;
        ++steps;
    }
    // 0.1 + 0.1 + 0.1 accumulates to 0.30000000000000004 or 0.2999...:
    // the half-step margin makes the third step the last either way
    EXPECT_EQ(steps, 3);
    EXPECT_NEAR(runTime.value(), 0.3, 1e-12);
}
