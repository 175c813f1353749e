// Unit test of the pair-interaction interface as the cloud drives it: the
// sub-grid lubrication and the rough contacts, held as pairInteraction
// only, find a touching pair from one neighbour list at the largest reach,
// both slow its approach in the particle system, and put equal and
// opposite loads into their own share (hydrodynamic, contact); the none
// models reach nothing and add nothing.

#include "pairInteraction.H"
#include "particleVelocitySystem.H"
#include "subGridModel.H"
#include "contactModel.H"
#include "pairSearch.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const subGridModel::settings aOver5{0.2, 5, 0.3, 1e-5};
const fdm::fluidProperties fluid{1, 1};
const fdm::periodicBox box
(
    point::zero, point(10, 10, 10), FixedList<bool, 3>({true, true, true})
);

//- Two unit spheres a gap apart along x, the second pushed onto the first
//  (held) by a unit force against a drag R per unit velocity
struct pushedPair
{
    unitTest::scratchCase sc;
    autoPtr<fvMesh> mesh;
    autoPtr<subGridModel> subGrid;
    autoPtr<contactModel> contacts;
    UPtrList<pairInteraction> all;

    pushedPair(const word& name, const char* props)
    :
        sc(name),
        all(2)
    {
        mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(2, 2, 2), 0.2, wordList(6, "cyclic")
        );
        const dictionary dict(unitTest::parse(props));
        const scalarField radii(2, 1.0);
        subGrid = subGridModel::New(dict, *mesh, aOver5, radii);
        contacts = contactModel::New(dict, *mesh, radii, 1, 1e-5);
        all.set(0, &subGrid());
        all.set(1, &contacts());
    }

    //- Velocity of the pushed sphere along x
    scalar approach(const scalar gap, const scalar R)
    {
        const pointField x({point(3, 5, 5), point(5 + gap, 5, 5)});
        const scalarField radii(2, 1.0);
        scalar reach = 0;
        for (const pairInteraction& pi : all)
        {
            reach = max(reach, pi.pairReach());
        }
        DynamicList<labelPair> near;
        fdm::findNearPairs(box, x, radii, reach, near);
        const fdm::positionStep euler(fdm::positionStep::euler(1e-3));
        const List<vector> Uold(2, Zero);
        for (pairInteraction& pi : all)
        {
            pi.update({x, radii, box, near, euler, Uold, 0, labelList()});
        }
        fdm::particleVelocitySystem system(2);
        for (direction d = 0; d < 6; ++d)
        {
            system.addEntry(6 + d, 6 + d, R);
            system.prescribe(0, d, 0);
        }
        system.addRhs(1, vector(-1, 0, 0) + contacts->loads().force[1], Zero);
        for (const pairInteraction& pi : all)
        {
            pi.addTo(system, fluid);
        }
        List<vector> U(2, Zero), Omega(2, Zero);
        system.solve(1e-12, 200, U, Omega, 0);
        U_ = U;
        return U[1].x();
    }

    //- The loads of each share at the last solved velocities
    void loads(fdm::particleLoads& hydro, fdm::particleLoads& contact) const
    {
        List<scalar> trace(2, 0.0);
        const List<vector> Omega(2, Zero);
        contact = contacts->loads();
        for (const pairInteraction& pi : all)
        {
            const bool h =
                pi.share() == pairInteraction::loadShare::hydrodynamic;
            pi.addSolvedLoads(U_, Omega, fluid, h ? hydro : contact, trace);
        }
    }

    List<vector> U_;
};

const char* bothModels =
    "subGrid { model frameInvariant; walls false; }"
    "contact { model hertz; roughness 2e-3; friction 0.5; kn 1; }";

} // End anonymous namespace


TEST(pairInteraction, bothFamiliesActThroughTheOneInterface)
{
    pushedPair pp("pairInteractionBoth", bothModels);
    EXPECT_EQ(pp.subGrid->share(), pairInteraction::loadShare::hydrodynamic);
    EXPECT_EQ(pp.contacts->share(), pairInteraction::loadShare::contact);

    // The push against the drag alone gives U = -1/R; the touching pair's
    // lubrication and contact stiffness slow it a hundred times and more
    const scalar R = 10;
    const scalar touching = pp.approach(1e-3, R);
    EXPECT_EQ(pp.subGrid->nPairs(), 1);
    EXPECT_EQ(pp.contacts->nPairs(), 1);
    EXPECT_LT(touching, 0);
    EXPECT_GT(touching, -1e-2/R);

    fdm::particleLoads hydro(2), contact(2);
    pp.loads(hydro, contact);
    for (const fdm::particleLoads* l : {&hydro, &contact})
    {
        EXPECT_GT(l->force[1].x(), 0);
        EXPECT_LT(mag(l->force[0] + l->force[1]), 1e-9*mag(l->force[1]));
    }
    // The pushed sphere's balance: push, drag and both shares
    EXPECT_NEAR
    (
        -1 - R*touching + hydro.force[1].x() + contact.force[1].x(), 0,
        1e-6
    );
}


TEST(pairInteraction, noneModelsReachAndAddNothing)
{
    pushedPair pp("pairInteractionNone", "");
    for (const pairInteraction& pi : pp.all)
    {
        EXPECT_EQ(pi.pairReach(), 0);
    }
    const scalar R = 10;
    EXPECT_NEAR(pp.approach(1e-3, R), -1/R, 1e-12);
    fdm::particleLoads hydro(2), contact(2);
    pp.loads(hydro, contact);
    EXPECT_EQ(hydro.force[1], vector::zero);
    EXPECT_EQ(contact.force[1], vector::zero);
    EXPECT_EQ(pp.subGrid->nPairs() + pp.contacts->nContacts(), 0);
}
