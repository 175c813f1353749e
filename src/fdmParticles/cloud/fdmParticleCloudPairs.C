/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The cloud's pairs: one neighbour search per step at the largest reach
    that any user of it needs, the pair interactions on it (sub-grid
    lubrication, rough contacts: pairInteraction) and their loads at the
    solved velocities, the pairs whose supports overlap, and the smallest
    gap of the progress line.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "sumToOwners.H"
#include "pairSearch.H"
#include "ListOps.H"
#include "clockTime.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Gap below which the smallest gap of the progress line is exact: 2 a_1
Foam::scalar smallestGapReach(const Foam::scalarField& radii)
{
    return 2*Foam::min(radii);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fdmParticleCloud::supportOverlapReach() const
{
    if (!consistentOverlaps_)
    {
        return 0;
    }
    const scalar a = max(state_.radius);
    return 2*(indicator_.supportRadius(a) - a);
}


Foam::scalar Foam::fdmParticleCloud::interactionReach() const
{
    scalar reach = supportOverlapReach();
    for (const pairInteraction& pi : pairInteractions_)
    {
        reach = max(reach, pi.pairReach());
    }
    return reach;
}


void Foam::fdmParticleCloud::setHalo()
{
    if (!distributedSolve_)
    {
        return;
    }
    // What a particle reaches beyond its centre: the cells of its support
    // (centres within supportRadius) and the partners of its pairs and
    // overlaps (centres within a + a_max + their gap), a hair more
    const scalar aMax = max(state_.radius);
    const scalar gap = interactionReach();
    scalarField reach(size());
    forAll(reach, p)
    {
        const scalar a = state_.radius[p];
        reach[p] =
            (1 + 1e-9)*max(indicator_.supportRadius(a), a + aMax + gap);
    }
    halo_ = fdm::particleHalo
    (
        fdm::particleHalo::gatherBoxes(boundBox(mesh_.points(), false)),
        reach
    );
}


void Foam::fdmParticleCloud::findOverlapBlocks()
{
    if (!consistentOverlaps_)
    {
        return;
    }
    // From the whole neighbour list; by subdomain, every pair among the
    // particles held here whose supports may meet in this rank's cells,
    // each block summed on the owners of its two particles
    if (distributedSolve_)
    {
        fdm::findNearPairs
        (
            box_, state_.position, state_.radius, supportOverlapReach(),
            findIndices(halo_.held(), true), halo_.held(), overlapPairs_
        );
    }
    else
    {
        fdm::selectNearPairs
        (
            box_, state_.position, state_.radius, supportOverlapReach(),
            near_, overlapPairs_
        );
    }
    overlapBlocks_ =
        stencils_.overlapBlocks(mesh_.V(), alphaLambda_, overlapPairs_);
    fdm::sumPairsToOwners
    (
        overlapPairs_, overlapBlocks_, halo_.owner(), stencils_
    );
}


void Foam::fdmParticleCloud::updatePairs()
{
    clockTime clock;

    // One neighbour search per step serves the pair interactions, the
    // overlapping supports and the smallest gap of the progress line.
    const scalar reach =
        max(smallestGapReach(state_.radius), interactionReach());
    // Solved by subdomain, a rank has the pairs with a particle it owns
    // (both owners of a pair across ranks compute it), among those it holds
    if (distributedSolve_)
    {
        fdm::findNearPairs
        (
            box_, state_.position, state_.radius, reach,
            halo_.owned(), halo_.held(), near_
        );
    }
    else
    {
        fdm::findNearPairs
        (
            box_, state_.position, state_.radius, reach, near_
        );
    }
    findOverlapBlocks();

    const fdm::positionStep step
    (
        fdm::positionStep::after
        (
            positionScheme_, historyDeltaT_, mesh_.time().deltaTValue()
        )
    );
    const fdm::pairStepInput in
    {
        state_.position, state_.radius, box_, near_, step, state_.Uold, 0,
        halo_.owner()
    };
    for (pairInteraction& pi : pairInteractions_)
    {
        pi.update(in);
        if (verbose_)
        {
            pi.report();
        }
    }
    timings_.pairs += clock.elapsedTime();
}


void Foam::fdmParticleCloud::addPairLoads()
{
    // Hydrodynamic totals: FDM + sub-grid (eqs 2.9, 2.68); contact loads:
    // the explicit part and the implicit stiffness' share at the solved
    // velocities
    clockTime clock;
    contact_ = contacts_->loads();
    const fdm::fluidProperties fluid{rhoFluid_, nu_};
    const auto addTo = [&](fdm::particleLoads& hydro, List<scalar>& trace)
    {
        for (const pairInteraction& pi : pairInteractions_)
        {
            const bool h =
                pi.share() == pairInteraction::loadShare::hydrodynamic;
            pi.addSolvedLoads
            (
                state_.U, state_.Omega, fluid, h ? hydro : contact_, trace
            );
        }
    };
    if (!distributedSolve_)
    {
        addTo(hydro_, dipoleTrace_);
        timings_.pairs += clock.elapsedTime();
        return;
    }
    // Solved by subdomain, a rank holds the pair loads of its own
    // particles whole (and shares of its partners', which their owners
    // count)
    fdm::particleLoads pairs(size());
    List<scalar> trace(size(), Zero);
    addTo(pairs, trace);
    const labelList& owner = halo_.owner();
    for (fdm::particleLoads* loads : {&pairs, &contact_})
    {
        fdm::keepOwned(loads->force, owner);
        fdm::keepOwned(loads->torque, owner);
        fdm::keepOwned(loads->stresslet, owner);
    }
    fdm::keepOwned(trace, owner);
    forAll(pairs.force, p)
    {
        hydro_.force[p] += pairs.force[p];
        hydro_.torque[p] += pairs.torque[p];
        hydro_.stresslet[p] += pairs.stresslet[p];
        dipoleTrace_[p] += trace[p];
    }
    timings_.pairs += clock.elapsedTime();
}


void Foam::fdmParticleCloud::relinearisePairs()
{
    clockTime clock;
    for (pairInteraction& pi : pairInteractions_)
    {
        pi.relinearise(state_.U);
    }
    timings_.pairs += clock.elapsedTime();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::fdmParticleCloud::nContacts() const
{
    // Over all ranks (each rank counts its own when solved by subdomain)
    return contacts_->nContacts();
}


Foam::scalar Foam::fdmParticleCloud::smallestGap() const
{
    if (empty())
    {
        return 2;
    }
    const scalar a1 = min(state_.radius);
    const scalar gap =
        fdm::smallestSurfaceGap
        (
            box_, state_.position, state_.radius,
            smallestGapReach(state_.radius), near_
        )/a1;
    // Each rank's pairs, when it has those of its own particles (among
    // those it holds: exact up to the interactions' reach, where the
    // gaps that matter are)
    return distributedSolve_ ? returnReduce(gap, minOp<scalar>()) : gap;
}


// ************************************************************************* //
