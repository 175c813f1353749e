// Unit test of the check before createTime: a number beyond the range of a
// double in a dictionary OpenFOAM reads next stops naming the file, the
// keyword and what is allowed, with floating-point traps on (where
// OpenFOAM's reader alone would trap), in the start dictionaries and in
// the fields; whole dictionaries pass, absent ones are skipped.

#include "readableDictionaries.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(readableDictionaries, hugeNumberStopsNamingFileAndKeywordWithTrapsOn)
{
    unitTest::scratchCase sc("readableDictionaries");
    sc.writeFile("constant/transportProperties", "nu 1; rho 1e400;");
    const std::string msg = unitTest::errorWithTrapsOn([&]
    {
        fdm::checkDictionariesReadable(sc.path());
    });
    EXPECT_NE(msg.find("constant/transportProperties"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("keyword 'rho'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("finite numbers"), std::string::npos) << msg;
}


TEST(readableDictionaries, wholeOrAbsentDictionariesPass)
{
    unitTest::scratchCase sc("readableDictionariesWhole");
    sc.writeFile
    (
        "constant/flowProperties", "meanPressureGradient (1e300 0 0);"
    );
    EXPECT_EQ
    (
        unitTest::errorOf([&]{ fdm::checkDictionariesReadable(sc.path()); }),
        ""
    );
    EXPECT_EQ(fdm::dictionariesReadAtStart().size(), 6);
}


TEST(readableDictionaries, fieldsOfTheStartTimeAreCheckedTheSameWay)
{
    unitTest::scratchCase sc("readableDictionariesFields");
    sc.writeFile("0/U", "internalField uniform (1e400 0 0);");
    sc.writeFile("0/p", "internalField uniform 0;");
    const std::string msg = unitTest::errorOf([&]
    {
        fdm::checkDictionariesReadable(sc.path()/"0", {"p", "U", "lambda"});
    });
    EXPECT_NE(msg.find("0/U"), std::string::npos) << msg;
    EXPECT_NE(msg.find("keyword 'internalField'"), std::string::npos) << msg;
}
