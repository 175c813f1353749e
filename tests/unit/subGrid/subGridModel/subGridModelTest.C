// Unit test of the sub-grid model selection: none without a subGrid block,
// a misspelt model named with the nearest valid one, and none refusing
// keywords it does not take.

#include "subGridModel.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const subGridModel::settings aOver5{0.2, 5, 0.3, 1e-5};

std::string selectionError(unitTest::scratchCase& sc, const char* props)
{
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(2, 2, 2), 0.2, wordList(6, "cyclic")
    );
    return unitTest::errorOf([&]
    {
        autoPtr<subGridModel> m = subGridModel::New
        (
            unitTest::parse(props), *mesh, aOver5, scalarField(2, 1.0)
        );
        EXPECT_EQ(m->type(), "none");
        EXPECT_EQ(m->nPairs(), 0);
        EXPECT_EQ(m->nWallGaps(), 0);
    });
}

} // End anonymous namespace


TEST(subGridModel, withoutABlockTheModelIsNone)
{
    unitTest::scratchCase sc("subGridModelNone");
    EXPECT_EQ(selectionError(sc, ""), "");
    EXPECT_EQ(selectionError(sc, "subGrid { model none; }"), "");
}


TEST(subGridModel, misspeltModelOrExtraKeywordStops)
{
    unitTest::scratchCase sc("subGridModelBad");
    const std::string model =
        selectionError(sc, "subGrid { model frameInvarient; }");
    EXPECT_NE(model.find("frameInvarient"), std::string::npos) << model;
    EXPECT_NE(model.find("frameInvariant"), std::string::npos) << model;

    const std::string extra =
        selectionError(sc, "subGrid { model none; walls true; }");
    EXPECT_NE(extra.find("walls"), std::string::npos) << extra;
}
