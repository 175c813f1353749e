// Unit test of the DEM restart state in a case: the state written at a
// time is read back into a fresh system to the last bit; at time 0 without
// a state the particle list stands; later without one the run stops.

#include "demState.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "demTestSystem.H"
#include <gtest/gtest.h>

using namespace Foam;



TEST(demState, stateWrittenAtATimeIsReadBackToTheLastBit)
{
    unitTest::scratchCase sc
    (
        "demState", "startFrom startTime; startTime 0.5;"
    );
    const fdm::lubricatedDEM moved = unitTest::threeSpheres(200);
    fdm::writeDEMState(moved, sc.runTime());
    ASSERT_TRUE(isFile(sc.path()/"0.5/particleState"));

    fdm::lubricatedDEM restarted = unitTest::threeSpheres(0);
    fdm::readDEMState(restarted, sc.runTime());
    forAll(moved.positions(), i)
    {
        EXPECT_EQ(restarted.positions()[i], moved.positions()[i]) << i;
        EXPECT_EQ(restarted.velocities()[i], moved.velocities()[i]) << i;
        EXPECT_EQ(restarted.spins()[i], moved.spins()[i]) << i;
    }
    EXPECT_NE(moved.positions()[1], unitTest::threeSpheres(0).positions()[1]);
}


TEST(demState, withoutAStateTimeZeroKeepsTheListLaterStops)
{
    unitTest::scratchCase start("demStateStart");
    fdm::lubricatedDEM dem = unitTest::threeSpheres(0);
    fdm::readDEMState(dem, start.runTime());
    EXPECT_EQ(dem.positions()[1], point(4.05, 3.2, 4));

    unitTest::scratchCase later
    (
        "demStateLater", "startFrom startTime; startTime 2;"
    );
    const std::string msg = unitTest::errorOf([&]
    {
        fdm::readDEMState(dem, later.runTime());
    });
    EXPECT_NE(msg.find("is missing"), std::string::npos) << msg;
}
