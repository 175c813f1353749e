// Unit tests of readBounded: values inside [lo, hi) are returned, a missing
// keyword or a value outside stops with the dictionary, the keyword and the
// allowed range in the message; axisIndex names of the three axes.

#include "readBounded.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

using unitTest::parse;
using unitTest::errorOf;

} // namespace


TEST(readBounded, returnsValuesInsideTheRange)
{
    const dictionary d(parse("b 5; c 0.3; zero 0;"));
    EXPECT_EQ(fdm::readBounded(d, "b", 1, 10, "width"), 5);
    EXPECT_EQ(fdm::readBounded(d, "c", VSMALL, GREAT, "support"), 0.3);
    // lo is included, hi is not
    EXPECT_EQ(fdm::readBounded(d, "zero", 0, 1, "a count"), 0);
    EXPECT_EQ(fdm::readBoundedOrDefault(d, "missing", 7, 1, 10, "x"), 7);
    EXPECT_EQ(fdm::readBoundedOrDefault(d, "b", 7, 1, 10, "x"), 5);
}


TEST(readBounded, stopsOutsideTheRangeNamingIt)
{
    const dictionary d(parse("b 10; c 0; d -1;"));
    const std::string atHi =
        errorOf([&]{ fdm::readBounded(d, "b", 1, 10, "indicator width"); });
    EXPECT_NE(atHi.find("b 10"), std::string::npos) << atHi;
    EXPECT_NE(atHi.find("b >= 1 < 10"), std::string::npos) << atHi;
    EXPECT_NE(atHi.find("indicator width"), std::string::npos) << atHi;

    const std::string positive =
        errorOf([&]{ fdm::readBounded(d, "c", VSMALL, GREAT, "radius"); });
    EXPECT_NE(positive.find("allowed values are 0 < c"), std::string::npos)
        << positive;
    EXPECT_EQ(positive.find("GREAT"), std::string::npos);

    EXPECT_NE
    (
        errorOf
        (
            [&]{ fdm::readBoundedOrDefault(d, "d", 1, 0, GREAT, "count"); }
        ),
        ""
    );
}


TEST(readBounded, stopsOnAMissingKeyword)
{
    const dictionary d(parse("b 5;"));
    const std::string msg =
        errorOf([&]{ fdm::readBounded(d, "c", 0, 1, "support width"); });
    EXPECT_NE(msg.find("Missing keyword c"), std::string::npos) << msg;
    EXPECT_NE(msg.find("support width"), std::string::npos) << msg;
}


TEST(axisIndex, namesTheThreeAxes)
{
    EXPECT_EQ(fdm::axisIndex("x"), 0);
    EXPECT_EQ(fdm::axisIndex("y"), 1);
    EXPECT_EQ(fdm::axisIndex("z"), 2);
    EXPECT_EQ(fdm::axisIndex("Y"), -1);
    EXPECT_EQ(fdm::axisIndex("xy"), -1);
}


// ************************************************************************* //
