// Unit test of the gravity fdmSuspensionFoam reads: a vector as before, or
// the gravity{} block with the Shields number of the heavy spheres (free,
// denser than the fluid) sheared between the two walls of a channel mesh,
// by hand; spheres of two densities cannot share one Shields number.

#include "cloudGravity.H"
#include "volFields.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "mathematicalConstants.H"
#include <gtest/gtest.h>

using namespace Foam;
using Foam::constant::mathematical::pi;
using unitTest::parse;

namespace
{

//- Groups: neutral (fluid density), heavy (2000) free, held (3000, fixed)
List<particleGroup> groups(const scalar heavy2 = 2000)
{
    return List<particleGroup>
    ({
        particleGroup("neutral", parse(""), 1000),
        particleGroup("heavy", parse("density 2000;"), 1000),
        particleGroup("held", parse("density 3000; translation fixed;"), 1000),
        particleGroup
        (
            "heavy2",
            parse(("density " + std::to_string(heavy2) + ";").c_str()),
            1000
        )
    });
}

//- Spheres of radii 1, 1, 1.4, 2 and 1 in the groups 0, 1, 1, 2, 3
fdm::particleState spheres()
{
    fdm::particleState s;
    s.group = labelList({0, 1, 1, 2, 3});
    s.radius = scalarField({1, 1, 1.4, 2, 1});
    return s;
}

} // End anonymous namespace


TEST(cloudGravity, heavySpheresScales)
{
    const fdm::settlingScales s = fdm::heavySphereScales
    (
        groups(), spheres(), 1000, 1e-3, 2, vector(8, 6, 4)
    );
    // the free spheres denser than the fluid: radii 1, 1.4 and 1
    EXPECT_EQ(s.densityDifference, 1000);
    EXPECT_NEAR(s.meanRadius, 3.4/3, 1e-15);
    EXPECT_NEAR(s.volume, 4.0/3.0*pi*(2 + pow3(1.4)), 1e-12);
    EXPECT_EQ(s.viscosity, 1e-3);
    EXPECT_EQ(s.shearRate, 2);

    EXPECT_NE
    (
        unitTest::errorOf
        (
            [&]
            {
                fdm::heavySphereScales
                (
                    groups(2500), spheres(), 1000, 1e-3, 2, vector(8, 6, 4)
                );
            }
        ).find("share one density"),
        std::string::npos
    );
}


TEST(cloudGravity, vectorOrShieldsNumberBetweenMovingWalls)
{
    unitTest::scratchCase sc("cloudGravity");
    // 1 x 1.5 x 1 channel, walls at y = 0 and 1.5 moving at -+0.75
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(4, 6, 4), 0.25, unitTest::channelSides()
    );
    tmp<volVectorField> U =
        unitTest::zeroField<vector>(*mesh, "U", dimVelocity);
    auto& Ub = U.ref().boundaryFieldRef();
    Ub[mesh->boundaryMesh().findPatchID("yMin")] == vector(-0.75, 0, 0);
    Ub[mesh->boundaryMesh().findPatchID("yMax")] == vector(0.75, 0, 0);

    const List<particleGroup> g(groups());
    const fdm::particleState s(spheres());
    EXPECT_EQ
    (
        fdm::readCloudGravity(parse(""), *mesh, g, s, 1000, 1e-3),
        vector::zero
    );
    EXPECT_EQ
    (
        fdm::readCloudGravity
        (
            parse("gravity (0 -9.81 0);"), *mesh, g, s, 1000, 1e-3
        ),
        vector(0, -9.81, 0)
    );
    // gammaDot 1: g = eta gammaDot/(drho a Sh) = 1e-3/(1000 (3.4/3) 0.5)
    const vector gs = fdm::readCloudGravity
    (
        parse("gravity { direction (0 -1 0); shieldsNumber 0.5; }"),
        *mesh, g, s, 1000, 1e-3
    );
    EXPECT_NEAR(gs.y(), -1e-3/(1000*3.4/3*0.5), 1e-18);
    EXPECT_EQ(gs.x(), 0);
}
