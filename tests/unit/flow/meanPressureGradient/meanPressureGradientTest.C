// Unit test of meanPressureGradient: read from constant/flowProperties with
// or without dimensions, set by the solver, zero skipped; a misspelt or
// missing keyword stops naming it.

#include "meanPressureGradient.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- The mean pressure gradient read from a flowProperties with body text
std::string readWith(const std::string& body, vector* value = nullptr)
{
    unitTest::scratchCase sc("meanPressureGradient");
    sc.writeFile("constant/flowProperties", body);
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(2, 2, 2), 0.5, unitTest::channelSides()
    );
    return unitTest::errorOf([&]
    {
        const meanPressureGradient g(*mesh);
        if (value)
        {
            *value = g.value().value();
        }
    });
}

} // End anonymous namespace


TEST(meanPressureGradient, readsTheVectorWithOrWithoutDimensions)
{
    vector v;
    EXPECT_EQ(readWith("meanPressureGradient (-8e-3 0 0);", &v), "");
    EXPECT_EQ(v, vector(-8e-3, 0, 0));
    EXPECT_EQ
    (
        readWith("meanPressureGradient [0 1 -2 0 0 0 0] (0 2 0);", &v), ""
    );
    EXPECT_EQ(v, vector(0, 2, 0));
}


TEST(meanPressureGradient, zeroIsSkippedAndTheSolverCanSetIt)
{
    unitTest::scratchCase sc("meanPressureGradientSet");
    sc.writeFile("constant/flowProperties", "meanPressureGradient (0 0 0);");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(2, 2, 2), 0.5, unitTest::channelSides()
    );
    meanPressureGradient g(*mesh);
    EXPECT_TRUE(g.isZero());
    g.set(vector(1e-3, 0, 0));
    EXPECT_FALSE(g.isZero());
    EXPECT_EQ(g.value().value(), vector(1e-3, 0, 0));
}


TEST(meanPressureGradient, wrongDimensionsMissingOrMisspeltKeywordsStop)
{
    const std::string dims =
        readWith("meanPressureGradient [1 -2 -2 0 0 0 0] (1 0 0);");
    EXPECT_NE(dims.find("imension"), std::string::npos) << dims;

    const std::string missing = readWith("");
    EXPECT_NE(missing.find("meanPressureGradient"), std::string::npos)
        << missing;

    const std::string misspelt = readWith
    (
        "meanPressureGradient (1 0 0); meanPresureGradient (1 0 0);"
    );
    EXPECT_NE(misspelt.find("meanPresureGradient"), std::string::npos)
        << misspelt;
}
