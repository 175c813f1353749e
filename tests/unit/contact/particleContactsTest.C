// Unit test of the cloud's rough contacts on a channel mesh: the normal
// force of a pair and of a wall gap against eq 2.57 evaluated here by hand
// (k_n given, a = 1), equal and opposite across a periodic boundary, none
// beyond the roughness; the accumulated slip survives the restart state.

#include "particleContacts.H"
#include "pairSearch.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const scalar hr = 5e-3, kn = 1e4, gapFloor = 1e-5;

//- Eq 2.57 with the floor gap gapFloor a (a = 1)
scalar elasticForce(const scalar gap)
{
    const scalar delta = hr - gap, d = gapFloor/hr;
    return kn*std::pow(delta, 1.5)*(1 - std::exp(10*(d - 1)))
        /(1 - std::exp(10*(d - gap/hr)));
}

struct contactCase
{
    unitTest::scratchCase sc;
    autoPtr<fvMesh> mesh;
    tmp<volVectorField> U;
    fdm::periodicBox box;

    explicit contactCase(const word& name)
    :
        sc(name),
        box(point::zero, point(10, 4, 10),
            FixedList<bool, 3>({true, false, true}))
    {
        mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(2, 20, 2), 0.2, unitTest::channelSides()
        );
        U = unitTest::zeroField<vector>(*mesh, "U", dimVelocity, "fixedValue");
    }

    autoPtr<contactModel> model(const label n, const char* props =
        "contact { model hertz; roughness 5e-3; friction 0.5; kn 1e4; }")
    const
    {
        return contactModel::New
        (
            unitTest::parse(props), *mesh, scalarField(n, 1.0), 1, gapFloor
        );
    }

    void update(contactModel& m, const pointField& x) const
    {
        const scalarField radii(x.size(), 1.0);
        DynamicList<labelPair> near;
        fdm::findNearPairs(box, x, radii, m.pairReach(), near);
        m.update(x, radii, box, near, 1e-3);
    }
};

} // End anonymous namespace


TEST(particleContacts, pairAndWallForcesAreEq257)
{
    contactCase cc("particleContacts");
    autoPtr<contactModel> m = cc.model(3);
    const scalar gap = 0.4*hr;
    // A pair across the periodic x boundary, a sphere above the lower wall
    const pointField x
    ({
        point(0.5, 2, 5), point(10.5 - 2 - gap, 2, 5), point(5, 1 + gap, 5)
    });
    cc.update(*m, x);
    ASSERT_EQ(m->nContacts(), 2);

    const fdm::particleLoads& loads = m->loads();
    const scalar F = elasticForce(gap);
    // Sphere 0 is pushed along +x (its partner lies below it through the
    // boundary), sphere 1 along -x, sphere 2 up from the wall
    EXPECT_NEAR(loads.force[0].x(), F, 1e-10*F);
    EXPECT_LT(mag(loads.force[0] + loads.force[1]), 1e-12*F);
    EXPECT_NEAR(loads.force[2].y(), F, 1e-10*F);
    EXPECT_NEAR(mag(loads.force[2]), F, 1e-10*F);
    for (label p = 0; p < 3; ++p)
    {
        EXPECT_LT(mag(loads.torque[p]), 1e-12*F) << p;
    }

    // Beyond the roughness: no contact
    cc.update(*m, pointField({point(0.5, 2, 5), point(8.5 - 1.01*hr, 2, 5),
        point(5, 1 + 1.01*hr, 5)}));
    EXPECT_EQ(m->nContacts(), 0);
    EXPECT_EQ(m->loads().force[2], vector::zero);
}


TEST(particleContacts, slipSurvivesTheRestartState)
{
    contactCase cc("particleContactsState");
    const pointField x({point(3, 1 + 0.4*hr, 3)});
    autoPtr<contactModel> first = cc.model(1);
    cc.update(*first, x);
    // Slide along the wall for a step: the tangential spring loads up
    first->advance(List<vector>(1, vector(1e-3, 0, 0)), List<vector>(1), 1);
    cc.update(*first, x);
    const vector Ft = first->loads().force[0];
    EXPECT_GT(mag(Ft.x()), 0);

    OStringStream os;
    os.precision(17);
    first->writeState(os, first->loads());
    IStringStream is(os.str());
    const dictionary state(is);

    autoPtr<contactModel> restarted = cc.model(1);
    fdm::particleLoads loads(1);
    restarted->readState(state, loads);
    cc.update(*restarted, x);
    EXPECT_EQ(restarted->loads().force[0], Ft);
}
