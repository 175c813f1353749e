// Unit tests of lubricatedDEMFoam's input checks: every keyword of
// particleProperties and its blocks is one the solver reads, and the cell's
// open directions.

#include "demSetup.H"
#include "unitTestHelpers.H"

#include <gtest/gtest.h>

using namespace Foam;
using unitTest::parse;
using unitTest::errorOf;


TEST(demSetup, acceptsTheDocumentedKeywords)
{
    const dictionary props
    (
        parse
        (
            "particlesFile \"list\"; density 1;"
            " cell { min (0 0 0); max (1 1 1); shearRate 1; open (y); }"
            " drag { viscosity 1; isolatedViscosity 0; isolatedBelow 3; }"
            " output { interval 10; track (0); vtkInterval 0; }"
        )
    );
    EXPECT_EQ(errorOf([&]{ fdm::checkDEMKeywords(props); }), "");
}


TEST(demSetup, stopsOnAMisspeltKeywordInABlock)
{
    const dictionary props
    (
        parse("density 1; drag { viscosty 1; }")
    );
    const std::string msg = errorOf([&]{ fdm::checkDEMKeywords(props); });
    EXPECT_NE(msg.find("viscosty"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'viscosity'"), std::string::npos) << msg;

    EXPECT_NE
    (
        errorOf([&]{ fdm::checkDEMKeywords(parse("densty 1;")); }),
        ""
    );
}


TEST(demSetup, openDirectionsAreNotPeriodic)
{
    const FixedList<bool, 3> all(fdm::readPeriodicity(parse("min (0 0 0);")));
    EXPECT_TRUE(all[0] && all[1] && all[2]);

    const FixedList<bool, 3> y(fdm::readPeriodicity(parse("open (y);")));
    EXPECT_TRUE(y[0]);
    EXPECT_FALSE(y[1]);
    EXPECT_TRUE(y[2]);

    EXPECT_NE
    (
        errorOf([&]{ fdm::readPeriodicity(parse("open (w);")); })
       .find("is not one of x, y, z"),
        std::string::npos
    );
}


// ************************************************************************* //
