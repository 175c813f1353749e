// Unit test of the check before createTime: a number beyond the range of a
// double in a dictionary OpenFOAM reads next stops naming the file, the
// keyword and what is allowed, with floating-point traps on (where
// OpenFOAM's reader alone would trap), in the start dictionaries and in
// the fields; whole dictionaries pass, absent ones are skipped, and a
// field written in binary (writeFormat binary) is read in its format.

#include "readableDictionaries.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "volFields.H"
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


TEST(readableDictionaries, fieldWrittenInBinaryIsReadInItsFormat)
{
    unitTest::scratchCase sc
    (
        "readableDictionariesBinary", "writeFormat binary;"
    );
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(3, 2, 2), 0.5, unitTest::channelSides()
    );
    tmp<volVectorField> tU =
        unitTest::zeroField<vector>(*mesh, "U", dimVelocity);
    volVectorField& U = tU.ref();
    forAll(U, c)
    {
        // Bytes of every value, '(' and ')' among them
        U[c] = vector(0.1*c - 0.3, 1.0/(c + 1), -1e-300*c);
    }
    ASSERT_TRUE(U.write());
    const fileName dir = sc.path()/sc.runTime().timeName();
    ASSERT_TRUE(isFile(dir/"U"));
    EXPECT_EQ
    (
        unitTest::errorOf([&]
        {
            fdm::checkDictionariesReadable(dir, {"U"});
        }),
        ""
    );
}
