// Unit test of the DEM run's watch: a stable system passes; an unstable
// leapfrog step and a particle out of an open direction stop naming what
// to change; the total stress is the sum of the four parts.

#include "demMonitor.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "demTestSystem.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(demMonitor, stableSystemPassesUnstableStepStops)
{
    unitTest::scratchCase sc("demMonitor");
    fdm::demMonitor monitor;
    const fdm::lubricatedDEM stable = unitTest::threeSpheres(50);
    EXPECT_EQ(unitTest::errorOf([&]{ monitor.check(stable, sc.runTime()); }),
        "");

    symmTensor sum(Zero);
    for (label p = 0; p < fdm::lubricatedInteraction::nStressParts; ++p)
    {
        sum += stable.stress(p);
    }
    EXPECT_EQ(fdm::totalStress(stable), sum);

    // One step well above the critical one, sqrt(m/k) = 0.02: stability
    // number >= 1 (a second step would diverge)
    const fdm::lubricatedDEM unstable = unitTest::threeSpheres(1, 0.1);
    ASSERT_GE(unstable.stabilityNumber(), 1);
    const std::string msg =
        unitTest::errorOf([&]{ monitor.check(unstable, sc.runTime()); });
    EXPECT_NE(msg.find("Lower deltaT"), std::string::npos) << msg;
}


TEST(demMonitor, particleOutOfAnOpenDirectionStops)
{
    unitTest::scratchCase sc("demMonitorOpen");
    fdm::lubricatedDEM dem = unitTest::threeSpheres(0, 1e-3, true);
    dem.addParticle(point(8, 17, 8), 1, 1);
    const std::string msg = unitTest::errorOf([&]
    {
        fdm::demMonitor().check(dem, sc.runTime());
    });
    EXPECT_NE(msg.find("left the cell through its open direction y"),
        std::string::npos) << msg;
}
