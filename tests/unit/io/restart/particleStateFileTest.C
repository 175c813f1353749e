// Unit test of the restart file shared by both solvers: entries come back
// to the last bit, no temporary file is left, a number out of range is an
// error naming the file even with floating-point traps on, and a restart
// at a time other than 0 without the file stops naming it.

#include "particleStateFile.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(particleStateFile, writtenEntriesReadBackToTheLastBit)
{
    unitTest::scratchCase sc("particleStateFile");
    Time& runTime = sc.runTime();
    const scalar x = 0.1 + 0.2;
    const vector v(1.0/3.0, -2.0/7.0, 1e-300);
    fdm::writeParticleStateFile
    (
        sc.path()/"0", "0", runTime,
        [&](Ostream& os)
        {
            os.writeEntry("x", x);
            os.writeEntry("v", v);
        }
    );
    EXPECT_FALSE(isFile(sc.path()/"0/particleState.tmp"));

    const dictionary d =
        fdm::readParticleStateFile(sc.path()/"0/particleState");
    EXPECT_EQ(d.get<scalar>("x"), x);
    EXPECT_EQ(d.get<vector>("v"), v);
}


TEST(particleStateFile, numberOutOfRangeIsAnErrorNamingTheFileWithTrapsOn)
{
    unitTest::scratchCase sc("particleStateFileRange");
    sc.writeFile("particleState", "x 1e400;");
    const std::string msg = unitTest::errorWithTrapsOn([&]
    {
        fdm::readParticleStateFile(sc.path()/"particleState");
    });
    EXPECT_NE(msg.find("file: " + sc.path()/"particleState"),
              std::string::npos) << msg;
}


TEST(particleStateFile, restartWithoutTheFileStopsNamingIt)
{
    unitTest::scratchCase fresh("particleStateFileFresh");
    const fileName file = fresh.path()/"0/particleState";
    EXPECT_FALSE
    (
        fdm::continuesFromParticleState(fresh.runTime(), file, "the list")
    );
    fresh.writeFile("0/particleState", "");
    EXPECT_TRUE
    (
        fdm::continuesFromParticleState(fresh.runTime(), file, "the list")
    );

    unitTest::scratchCase later
    (
        "particleStateFileLater", "startFrom startTime; startTime 0.5;"
    );
    const std::string msg = unitTest::errorOf([&]
    {
        fdm::continuesFromParticleState
        (
            later.runTime(), later.path()/"0.5/particleState", "the list"
        );
    });
    EXPECT_NE(msg.find("0.5/particleState\" is missing"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("the list"), std::string::npos) << msg;
}
