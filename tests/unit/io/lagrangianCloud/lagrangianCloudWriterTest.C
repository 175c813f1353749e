// Unit test of the lagrangian cloud writer on a box mesh: OpenFOAM's own
// cloud reader gets the positions back, and each field holds the values
// of the particles in the mesh in input order; a particle outside the mesh
// is left out of positions and fields alike.  The cells found by the walk
// from one position to the next are those of OpenFOAM's octree search.

#include "lagrangianCloudWriter.H"
#include "unitTestCase.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(lagrangianCloudWriter, openFoamReadsThePositionsAndFieldsBack)
{
    unitTest::scratchCase sc("lagrangianCloudWriter");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(4, 4, 4), 0.25, unitTest::channelSides()
    );
    const List<point> x
    ({
        point(0.1, 0.2, 0.3), point(2, 0.5, 0.5), point(0.9, 0.9, 0.05)
    });
    const scalarList d({1.0, 2.0, 3.0});
    {
        const lagrangianCloudWriter cloud(*mesh, "particles", x);
        cloud.write("d", d);
        cloud.write
        (
            "U", List<vector>({vector(1, 0, 0), Zero, vector(0, 0, 3)})
        );
    }

    const passiveParticleCloud read(*mesh, "particles");
    ASSERT_EQ(read.size(), 2);
    const List<point> expected({x[0], x[2]});
    label i = 0;
    for (const passiveParticle& p : read)
    {
        EXPECT_LT(mag(p.position() - expected[i]), 1e-12) << i;
        ++i;
    }

    const fileName dir = sc.path()/"0/lagrangian/particles";
    IOField<scalar> dRead
    (
        IOobject("d", "0", cloud::prefix/"particles", *mesh,
            IOobject::MUST_READ)
    );
    EXPECT_EQ(dRead, scalarList({1.0, 3.0}));
    EXPECT_TRUE(isFile(dir/"U"));
}


TEST(lagrangianCloudWriter, eachParticleInTheCellThatTheOctreeFinds)
{
    unitTest::scratchCase sc("lagrangianCloudWriterWalk");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(10, 8, 6), 0.1, unitTest::channelSides()
    );
    // Scattered positions (a fixed pseudo-random sequence), far apart in
    // turn, so that each walk crosses many cells
    List<point> x(40);
    forAll(x, i)
    {
        x[i] = point
        (
            0.999*std::fmod(0.37*i + 0.11, 1.0),
            0.799*std::fmod(0.61*i + 0.05, 1.0),
            0.599*std::fmod(0.83*i + 0.02, 1.0)
        );
    }
    const lagrangianCloudWriter cloud(*mesh, "particles", x);

    const passiveParticleCloud read(*mesh, "particles");
    ASSERT_EQ(read.size(), x.size());
    label i = 0;
    for (const passiveParticle& p : read)
    {
        EXPECT_EQ(p.cell(), mesh->findCell(x[i])) << i;
        ++i;
    }
}
