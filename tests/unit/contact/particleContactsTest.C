// Unit test of the cloud's rough contacts on a channel mesh: the normal
// force of a pair and of a wall gap against eq 2.57 evaluated here by hand
// (k_n given, a = 1), equal and opposite across a periodic boundary, none
// beyond the roughness; the accumulated slip survives the restart state; a
// sphere driven into another far harder than the barrier's force at the
// start gap settles on the barrier without crossing its floor; a pair
// found below the floor is pushed back above it by converged solves; solved
// by subdomain a rank holds the contacts of its own particles and counts
// each once.

#include "particleContacts.H"
#include "particleVelocitySystem.H"
#include "pairSearch.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const scalar hr = 5e-3, kn = 1e4, gapFloor = 1e-5;

//- A fluid of unit density: the stiffnesses enter the system unscaled
const fdm::fluidProperties unitDensity{1, 1};

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

    //- One step of sphere 1 pushed by P along -x against a drag R onto
    //  sphere 0 (held): Adams-Bashforth after the first, 8 outer
    //  iterations relinearised as the solver's are; whether every particle
    //  solve converged
    bool stepPair
    (
        contactModel& m, pointField& x, List<vector>& U, List<vector>& Uold,
        bool& history, const scalar dt, const scalar R, const scalar P
    ) const
    {
        const fdm::positionStep s
        (
            fdm::positionStep::after(history ? dt : 0, dt)
        );
        DynamicList<labelPair> near;
        const scalarField radii(2, 1.0);
        fdm::findNearPairs(box, x, radii, m.pairReach(), near);
        m.update({x, radii, box, near, s, Uold, 0, labelList()});
        List<vector> Omega(2, Zero);
        bool converged = true;
        for (label outer = 0; outer < 8; ++outer)
        {
            if (outer)
            {
                m.relinearise(U);
            }
            fdm::particleVelocitySystem system(2);
            for (direction d = 0; d < 6; ++d)
            {
                system.addEntry(6 + d, 6 + d, R);
                system.prescribe(0, d, 0);
            }
            system.addRhs
            (
                1, vector(-P, 0, 0) + m.loads().force[1], m.loads().torque[1]
            );
            m.addTo(system, unitDensity);
            converged =
                system.solve(1e-12, 200, U, Omega, 0).converged && converged;
        }
        m.advance(U, Omega, dt);
        forAll(x, p)
        {
            x[p] += s.displacement(U[p], Uold[p]);
        }
        Uold = U;
        history = true;
        return converged;
    }

    //- owner: the rank of each particle (solved by subdomain), or empty
    void update
    (
        contactModel& m, const pointField& x,
        const labelList& owner = labelList()
    ) const
    {
        const scalarField radii(x.size(), 1.0);
        DynamicList<labelPair> near;
        fdm::findNearPairs(box, x, radii, m.pairReach(), near);
        const fdm::positionStep euler(fdm::positionStep::euler(1e-3));
        const List<vector> Uold(x.size(), Zero);
        m.update({x, radii, box, near, euler, Uold, 0, owner});
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


TEST(particleContacts, aRankHoldsItsParticlesContactsAndCountsThemOnce)
{
    // A pair (0, 1) and a wall gap of 2, all touching.  Solved by
    // subdomain, this rank (0) holds the pairs with a particle it owns and
    // the wall gaps of its own particles, and counts a pair on the owner of
    // its first particle: the run's totals, restart history and contact
    // network then take each contact once over the ranks
    contactCase cc("particleContactsOwners");
    const pointField x({point(3, 2, 5), point(5 + 0.5*hr, 2, 5),
        point(7, 1 + 0.4*hr, 5)});
    autoPtr<contactModel> m = cc.model(3);
    cc.update(*m, x);
    EXPECT_EQ(m->nContacts(), 2);
    EXPECT_EQ(m->wholeHistory().size(), 2);

    // Particle 1 here, 0 and 2 on rank 1: the pair held for 1's rows and
    // loads, counted on rank 1; the wall gap not held
    cc.update(*m, x, labelList({1, 0, 1}));
    EXPECT_EQ(m->nContacts(), 0);
    EXPECT_EQ(m->wholeHistory().size(), 0);
    EXPECT_EQ(m->network(List<vector>(3), List<vector>(3)).size(), 0);
    EXPECT_GT(m->loads().force[1].x(), 0);
    EXPECT_EQ(m->loads().force[2], vector::zero);

    // Particles 0 and 2 here: both contacts held and counted
    cc.update(*m, x, labelList({0, 1, 0}));
    EXPECT_EQ(m->nPairs(), 1);
    EXPECT_EQ(m->nWallGaps(), 1);
    EXPECT_EQ(m->wholeHistory().size(), 2);
    EXPECT_EQ(m->network(List<vector>(3), List<vector>(3)).size(), 2);
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
    first->writeState(os, first->loads(), first->wholeHistory());
    IStringStream is(os.str());
    const dictionary state(is);

    autoPtr<contactModel> restarted = cc.model(1);
    fdm::particleLoads loads(1);
    restarted->readState(state, loads);
    cc.update(*restarted, x);
    EXPECT_EQ(restarted->loads().force[0], Ft);
}


TEST(particleContacts, drivenPairSettlesOnTheBarrierWithoutCrossingTheFloor)
{
    // Sphere 0 held, sphere 1 pushed onto it by P against a drag R: a
    // stiff approach, P/R dt = 0.5 h_r per step, and a load 30 times the
    // Hertz force at full overlap, so that the balance F_el(gap) = P lies
    // within 1e-2 h_r of the floor.  Adams-Bashforth steps, a few
    // relinearisations per step as the outer iterations make them.
    contactCase cc("particleContactsDriven");
    autoPtr<contactModel> m = cc.model(2);
    const scalar dt = 1e-3, floorGap = gapFloor;
    const scalar P = 30*kn*std::pow(hr, 1.5), R = P*dt/(0.5*hr);
    pointField x({point(3, 2, 5), point(5 + 0.9*hr, 2, 5)});
    List<vector> U(2, Zero), Uold(2, Zero);
    bool history = false;
    scalar smallest = GREAT, gap = GREAT;
    for (label step = 0; step < 60; ++step)
    {
        cc.stepPair(m(), x, U, Uold, history, dt, R, P);
        gap = x[1].x() - x[0].x() - 2;
        smallest = min(smallest, gap);
    }

    // The balance F_el(gap) = P by bisection on eq 2.57
    scalar lo = floorGap*(1 + 1e-12), hi = hr;
    for (label k = 0; k < 200; ++k)
    {
        const scalar mid = 0.5*(lo + hi);
        (elasticForce(mid) > P ? lo : hi) = mid;
    }
    EXPECT_GT(smallest, floorGap);
    EXPECT_LT(hi - floorGap, 1e-2*hr);
    EXPECT_NEAR(gap, hi, 1e-6*hr);
}


TEST(particleContacts, pairBelowTheFloorIsPushedBackWithAConvergedSolve)
{
    // A pair that crossed the barrier's floor within a step (gap -0.17 h_r,
    // as at phi0 = 0.52, strain 0.754), sphere 0 held, sphere 1 free
    // against a drag R (the order of the lubrication resistance at a gap
    // of h_r): each particle solve converges, the barrier moves sphere 1
    // by less than h_r a step, and the pair is back above the floor within
    // 20 steps of gammaDot dt = 4e-3 (before, linearised at the floor,
    // k' dt was 1e8 times R, and in the suspension the solve ran to its
    // iteration limit)
    contactCase cc("particleContactsBelowFloor");
    autoPtr<contactModel> m = cc.model(2);
    const scalar dt = 4e-3, R = 1e3;
    pointField x({point(3, 2, 5), point(5 - 0.17*hr, 2, 5)});
    List<vector> U(2, Zero), Uold(2, Zero);
    bool history = false;
    scalar gap = x[1].x() - x[0].x() - 2;
    label steps = 0;
    for (; steps < 20 && gap <= gapFloor; ++steps)
    {
        const point before = x[1];
        EXPECT_TRUE(cc.stepPair(m(), x, U, Uold, history, dt, R, 0))
            << "step " << steps;
        EXPECT_LT(mag(x[1] - before), hr) << steps;
        gap = x[1].x() - x[0].x() - 2;
    }
    EXPECT_GT(gap, gapFloor) << "after " << steps << " steps";
}


TEST(particleContacts, pairBelowTheFloorIsAsStiffAsAHundredthOfHrAboveIt)
{
    // The response of sphere 1 to a unit push against sphere 0 (held),
    // with a drag R: 1/(R + k' dt) for the stiffness k' the contact
    // brings into the particle system.  Found below the floor (or on it),
    // the contact is linearised a hundredth of h_r above the floor: the
    // same response as there, where k' dt is about 1e2 R at dt = 4e-3.
    // Linearised on the floor itself it was about 1e8 R.
    contactCase cc("particleContactsBelowFloorStiffness");
    const scalar dt = 4e-3, R = 1e3;
    auto response = [&](const scalar gap)
    {
        autoPtr<contactModel> m = cc.model(2);
        const pointField x({point(3, 2, 5), point(5 + gap, 2, 5)});
        DynamicList<labelPair> near;
        fdm::findNearPairs(cc.box, x, scalarField(2, 1.0), m->pairReach(),
            near);
        const scalarField radii(2, 1.0);
        const fdm::positionStep euler(fdm::positionStep::euler(dt));
        const List<vector> Uold(2, Zero);
        m->update({x, radii, cc.box, near, euler, Uold, 0, labelList()});
        fdm::particleVelocitySystem system(2);
        for (direction d = 0; d < 6; ++d)
        {
            system.addEntry(6 + d, 6 + d, R);
            system.prescribe(0, d, 0);
        }
        system.addRhs(1, vector(-1, 0, 0), Zero);
        m->addTo(system, unitDensity);
        List<vector> U(2, Zero), Omega(2, Zero);
        system.solve(1e-12, 100, U, Omega, 0);
        return -U[1].x();
    };
    const scalar above = response(gapFloor + 1e-2*hr);
    EXPECT_LT(above, 1/R);
    EXPECT_GT(above, 1e-4/R);
    for (const scalar gap : {-0.17*hr, gapFloor})
    {
        EXPECT_NEAR(response(gap), above, 1e-9*above) << "gap " << gap;
    }
}
