// Unit test of the restart guard: with startFrom latestTime, newest times
// with an empty field or without the particle state are renamed to
// <time>.incomplete (kept, numbered when the name is taken) until the
// newest is whole; time 0 is never set aside; other start settings touch
// nothing.

#include "incompleteWrites.H"
#include "unitTestCase.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- The guard as a solver started in the case calls it.  The argList is
//  never destroyed: its destructor ends OpenFOAM's file handler, which
//  the tests after this one still need.
void guard(const fileName& casePath)
{
    static std::string caseArg;
    caseArg = casePath;
    static char name[] = "test", option[] = "-case";
    static char* argv[] = {name, option, nullptr, nullptr};
    argv[2] = &caseArg[0];
    char** av = argv;
    int argc = 3;
    const argList* args = new argList(argc, av, false, false, false);
    fdm::setAsideIncompleteWrites(*args);
}

//- A time directory with U and p (an empty p when damaged) and, when
//  given, the particle state
void writeTime
(
    const unitTest::scratchCase& sc,
    const word& t,
    const bool pWritten,
    const bool state
)
{
    sc.writeFile(t/"U", "internalField uniform (0 0 0);");
    mkDir(sc.path()/t);
    OFstream(sc.path()/t/"p")() << (pWritten ? "internalField 0;" : "");
    if (state)
    {
        sc.writeFile(t/"particleState", "");
    }
}

} // End anonymous namespace


TEST(incompleteWrites, newestIncompleteTimesAreSetAside)
{
    unitTest::scratchCase sc("incompleteWrites", "startFrom latestTime;");
    sc.writeFile("constant/particleProperties", "");
    writeTime(sc, "0", false, false);      // never set aside
    writeTime(sc, "1", true, true);        // whole
    writeTime(sc, "2", true, false);       // killed before the state
    writeTime(sc, "3", false, true);       // killed while writing p
    mkDir(sc.path()/"2.incomplete");       // an earlier one, kept
    guard(sc.path());

    EXPECT_TRUE(isDir(sc.path()/"0"));
    EXPECT_TRUE(isDir(sc.path()/"1"));
    EXPECT_FALSE(isDir(sc.path()/"2"));
    EXPECT_FALSE(isDir(sc.path()/"3"));
    EXPECT_TRUE(isDir(sc.path()/"2.incomplete"));
    EXPECT_TRUE(isFile(sc.path()/"2.incomplete1/U"));
    EXPECT_TRUE(isFile(sc.path()/"3.incomplete/particleState"));
}


TEST(incompleteWrites, withoutParticlesOrLatestTimeFieldsDecide)
{
    unitTest::scratchCase fluid
    (
        "incompleteWritesFluid", "startFrom latestTime;"
    );
    writeTime(fluid, "1", true, false);    // whole without particles
    guard(fluid.path());
    EXPECT_TRUE(isDir(fluid.path()/"1"));

    unitTest::scratchCase fixed
    (
        "incompleteWritesStart", "startFrom startTime;"
    );
    fixed.writeFile("constant/particleProperties", "");
    writeTime(fixed, "1", false, false);
    guard(fixed.path());
    EXPECT_TRUE(isDir(fixed.path()/"1"));
}
