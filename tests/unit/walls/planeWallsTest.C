// Unit test of planeWalls on a box mesh with walls at y = 0 and y = 1.5:
// normals out of the fluid, distances, the area-averaged wall velocity and
// the Couette shear rate against values worked out by hand; a wall patch
// that is not a plane stops, or is left out and counted.

#include "planeWalls.H"
#include "volFields.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- U with the given values on the two y walls (x component varying along
//  x on the upper one, so that only the area average gives its mean)
tmp<volVectorField> wallVelocity(const fvMesh& mesh)
{
    tmp<volVectorField> tU =
        unitTest::zeroField<vector>(mesh, "U", dimVelocity);
    auto& Ub = tU.ref().boundaryFieldRef();
    Ub[mesh.boundaryMesh().findPatchID("yMin")] == vector(-1, 0, 0);
    fvPatchVectorField& top = Ub[mesh.boundaryMesh().findPatchID("yMax")];
    const vectorField& Cf = top.patch().Cf();
    forAll(top, facei)
    {
        // 1 and 3 alternating along x: area average 2
        top[facei] = vector(Cf[facei].x() < 0.5 ? 1 : 3, 0, 0);
    }
    return tU;
}

} // End anonymous namespace


TEST(planeWalls, couetteWallsNormalsDistancesAndShearRate)
{
    unitTest::scratchCase sc("planeWalls");
    autoPtr<fvMesh> mesh =
        unitTest::boxMesh
        (
            sc.runTime(), labelVector(4, 6, 4), 0.25, unitTest::channelSides()
        );
    tmp<volVectorField> U = wallVelocity(*mesh);

    const planeWalls walls(*mesh, "test");
    ASSERT_EQ(walls.size(), 2);
    const planeWalls::wall& bottom = walls.walls()[0];
    const planeWalls::wall& top = walls.walls()[1];
    EXPECT_EQ(bottom.name, "yMin");
    EXPECT_EQ(top.name, "yMax");
    EXPECT_LT(mag(bottom.normal - vector(0, -1, 0)), 1e-12);
    EXPECT_LT(mag(top.normal - vector(0, 1, 0)), 1e-12);

    const point x(0.3, 0.4, 0.2);
    EXPECT_NEAR(bottom.distance(x), 0.4, 1e-12);
    EXPECT_NEAR(top.distance(x), 1.1, 1e-12);

    EXPECT_LT(mag(walls.velocity(bottom) - vector(-1, 0, 0)), 1e-12);
    EXPECT_LT(mag(walls.velocity(top) - vector(2, 0, 0)), 1e-12);
    // |(2 0 0) - (-1 0 0)| over the gap 1.5
    EXPECT_NEAR(walls.shearRate(), 2.0, 1e-12);
}


TEST(planeWalls, noShearRateWithoutExactlyTwoWalls)
{
    unitTest::scratchCase sc("planeWallsBox");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(2, 2, 2), 0.5, wordList(6, "wall")
    );
    tmp<volVectorField> U = wallVelocity(*mesh);

    const planeWalls walls(*mesh, "test");
    EXPECT_EQ(walls.size(), 6);
    EXPECT_EQ(walls.shearRate(), 0);
}


TEST(planeWalls, aBentWallStopsOrIsCounted)
{
    unitTest::scratchCase sc("planeWallsBent");
    // The x = 0 and y = 0 sides make one wall patch
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(2, 2, 2), 0.5, wordList(6, "wall"),
        wordList({"corner", "xMax", "corner", "yMax", "zMin", "zMax"})
    );

    const std::string msg = unitTest::errorOf
    (
        [&]{ planeWalls(*mesh, "sub-grid wall lubrication"); }
    );
    EXPECT_NE(msg.find("corner is not a plane"), std::string::npos) << msg;
    EXPECT_NE(msg.find("sub-grid wall lubrication"), std::string::npos);

    const planeWalls planes(*mesh, "contacts", false);
    EXPECT_EQ(planes.size(), 4);
    for (const planeWalls::wall& w : planes.walls())
    {
        EXPECT_NE(w.name, "corner");
    }
    EXPECT_EQ(planes.shearRate(), 0);
}
