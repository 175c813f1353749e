// Unit test of the DEM restart state in a case: the state written at a
// time is read back into a fresh system to the last bit; at time 0 without
// a state the particle list stands; later without one the run stops.

#include "demState.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- Three spheres in a sheared periodic cube, after some steps when moved
fdm::lubricatedDEM threeSpheres(const label steps)
{
    fdm::lubricatedDEM dem
    (
        fdm::periodicBox(point::zero, point(16, 16, 16),
            FixedList<bool, 3>({true, true, true})),
        1.0,
        fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.4, 4)
    );
    dem.addParticle(point(2, 3, 4), 1, 1);
    dem.addParticle(point(4.05, 3.2, 4), 1, 1);
    dem.addParticle(point(6, 5, 2), 1.2, 1);
    for (label i = 0; i < steps; ++i)
    {
        dem.step(1e-3);
    }
    return dem;
}

} // End anonymous namespace


TEST(demState, stateWrittenAtATimeIsReadBackToTheLastBit)
{
    unitTest::scratchCase sc
    (
        "demState", "startFrom startTime; startTime 0.5;"
    );
    const fdm::lubricatedDEM moved = threeSpheres(200);
    fdm::writeDEMState(moved, sc.runTime());
    ASSERT_TRUE(isFile(sc.path()/"0.5/particleState"));

    fdm::lubricatedDEM restarted = threeSpheres(0);
    fdm::readDEMState(restarted, sc.runTime());
    forAll(moved.positions(), i)
    {
        EXPECT_EQ(restarted.positions()[i], moved.positions()[i]) << i;
        EXPECT_EQ(restarted.velocities()[i], moved.velocities()[i]) << i;
        EXPECT_EQ(restarted.spins()[i], moved.spins()[i]) << i;
    }
    EXPECT_NE(moved.positions()[1], threeSpheres(0).positions()[1]);
}


TEST(demState, withoutAStateTimeZeroKeepsTheListLaterStops)
{
    unitTest::scratchCase start("demStateStart");
    fdm::lubricatedDEM dem = threeSpheres(0);
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
