// Unit test of the frame-invariant sub-grid model with the shipped a/5
// tables: a close pair's loads are unchanged by any rigid-body motion added
// to both particles (the property the model is named for, thesis 1 section
// 3.3), equal and opposite, and resist the approach; a far pair is not
// corrected; a particle near a wall feels nothing when it moves with the
// wall and is pushed back when it approaches it; tables for another mesh
// spacing are refused.

#include "frameInvariantSubGrid.H"
#include "pairSearch.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>
#include <random>

using namespace Foam;

namespace
{

const subGridModel::settings aOver5{0.2, 5, 0.3, 1e-5};

//- A channel mesh of a/5 cells (y from 0 to 4 a), U on it with the lower
//  wall moving at (1 0 0)
struct channelCase
{
    unitTest::scratchCase sc;
    autoPtr<fvMesh> mesh;
    tmp<volVectorField> U;

    explicit channelCase(const word& name)
    :
        sc(name)
    {
        mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(2, 20, 2), 0.2, unitTest::channelSides()
        );
        U = unitTest::zeroField<vector>(*mesh, "U", dimVelocity, "fixedValue");
        U.ref().boundaryFieldRef()[mesh->boundaryMesh().findPatchID("yMin")]
            == vector(1, 0, 0);
    }

    autoPtr<subGridModel> model(const std::string& block, label n) const
    {
        return subGridModel::New
        (
            unitTest::parse(("subGrid {" + block + "}").c_str()),
            *mesh, aOver5, scalarField(n, 1.0)
        );
    }
};

//- Loads of the model for velocities U, Omega
fdm::particleLoads loadsOf
(
    const subGridModel& m,
    const List<vector>& U,
    const List<vector>& Omega
)
{
    fdm::particleLoads loads(U.size());
    List<scalar> trace(U.size(), 0.0);
    m.addSolvedLoads(U, Omega, fdm::fluidProperties{1, 1}, loads, trace);
    return loads;
}

void update
(
    subGridModel& m,
    const pointField& x,
    const fdm::periodicBox& box
)
{
    const scalarField radii(x.size(), 1.0);
    DynamicList<labelPair> near;
    fdm::findNearPairs(box, x, radii, m.pairReach(), near);
    const fdm::positionStep euler(fdm::positionStep::euler(1e-3));
    const List<vector> Uold(x.size(), Zero);
    m.update({x, radii, box, near, euler, Uold, 0, labelList()});
}

const fdm::periodicBox periodic10
(
    point::zero, point(10, 10, 10), FixedList<bool, 3>({true, true, true})
);

} // End anonymous namespace


TEST(frameInvariantSubGrid, pairLoadsAreFrameInvariantEqualAndOpposite)
{
    channelCase cc("frameInvariantPair");
    autoPtr<subGridModel> m = cc.model("model frameInvariant; walls false;", 2);
    // Across the periodic boundary: the pair meets through the image
    const pointField x({point(0.3, 5, 5), point(9.3, 5.5, 5.2)});
    update(*m, x, periodic10);
    ASSERT_EQ(m->nPairs(), 1);

    std::mt19937 gen(3);
    std::uniform_real_distribution<scalar> u(-1, 1);
    auto random = [&]{ return vector(u(gen), u(gen), u(gen)); };
    const List<vector> U({random(), random()});
    const List<vector> W({random(), random()});
    const fdm::particleLoads base = loadsOf(*m, U, W);
    EXPECT_GT(mag(base.force[0]), 1);

    // Equal and opposite
    EXPECT_LT(mag(base.force[0] + base.force[1]), 1e-10*mag(base.force[0]));

    // A rigid-body motion V + Omega0 x (x - x0) added to both
    const vector V = random(), Omega0 = random();
    const vector r = periodic10.minimumImage(x[1] - x[0]);
    const List<vector> Ur({U[0] + V, U[1] + V + (Omega0 ^ r)});
    const List<vector> Wr({W[0] + Omega0, W[1] + Omega0});
    const fdm::particleLoads moved = loadsOf(*m, Ur, Wr);
    const scalar scale = mag(base.force[0]);
    for (label p = 0; p < 2; ++p)
    {
        EXPECT_LT(mag(moved.force[p] - base.force[p]), 1e-10*scale) << p;
        EXPECT_LT(mag(moved.torque[p] - base.torque[p]), 1e-10*scale) << p;
        EXPECT_LT(mag(moved.stresslet[p] - base.stresslet[p]), 1e-10*scale)
            << p;
    }

    // Approach along the line of centres is resisted
    const vector n = r/mag(r);
    const fdm::particleLoads squeeze =
        loadsOf(*m, List<vector>({n, -n}), List<vector>(2, Zero));
    EXPECT_LT(squeeze.force[0] & n, 0);
}


TEST(frameInvariantSubGrid, farPairsAndTheNoneModelCorrectNothing)
{
    channelCase cc("frameInvariantFar");
    autoPtr<subGridModel> m = cc.model("model frameInvariant; walls false;", 2);
    update(*m, pointField({point(2, 5, 5), point(4.5, 5, 5)}), periodic10);
    EXPECT_EQ(m->nPairs(), 0);

    autoPtr<subGridModel> none = cc.model("", 2);
    EXPECT_EQ(none->type(), "none");
    update(*none, pointField({point(2, 5, 5), point(4.01, 5, 5)}), periodic10);
    const fdm::particleLoads loads =
        loadsOf(*none, List<vector>({vector(1, 0, 0), Zero}), List<vector>(2));
    EXPECT_EQ(loads.force[0], vector::zero);
}


TEST(frameInvariantSubGrid, wallGapMovesWithTheWallAndResistsApproach)
{
    channelCase cc("frameInvariantWall");
    autoPtr<subGridModel> m = cc.model("model frameInvariant;", 1);
    const fdm::periodicBox channel
    (
        point::zero, point(10, 4, 10), FixedList<bool, 3>({true, false, true})
    );
    update(*m, pointField(1, point(3, 1.05, 3)), channel);
    ASSERT_EQ(m->nWallGaps(), 1);

    // Translating with the lower wall at (1 0 0), not rotating
    const fdm::particleLoads with =
        loadsOf(*m, List<vector>(1, vector(1, 0, 0)), List<vector>(1, Zero));
    EXPECT_LT(mag(with.force[0]), 1e-12);
    EXPECT_LT(mag(with.torque[0]), 1e-12);

    const fdm::particleLoads towards =
        loadsOf(*m, List<vector>(1, vector(0, -1, 0)), List<vector>(1, Zero));
    EXPECT_GT(towards.force[0].y(), 1);
}


TEST(frameInvariantSubGrid, tablesOfAnotherSpacingAreRefused)
{
    channelCase cc("frameInvariantSpacing");
    const std::string msg = unitTest::errorOf([&]
    {
        subGridModel::New
        (
            unitTest::parse("subGrid { model frameInvariant; }"), *cc.mesh,
            subGridModel::settings{0.25, 5, 0.3, 1e-5}, scalarField(1, 1.0)
        );
    });
    EXPECT_NE(msg.find("Delta/a = 0.2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Delta/a = 0.25"), std::string::npos) << msg;
}
