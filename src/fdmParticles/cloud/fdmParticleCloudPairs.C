/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The cloud's pairs: one neighbour search per step at the largest reach
    that any user of it needs, the pair interactions on it (sub-grid
    lubrication, rough contacts: pairInteraction), the pairs whose supports
    overlap, and the smallest gap of the progress line.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "sumOverRanks.H"
#include "pairSearch.H"

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


void Foam::fdmParticleCloud::findOverlapBlocks()
{
    if (!consistentOverlaps_)
    {
        return;
    }
    fdm::selectNearPairs
    (
        box_, state_.position, state_.radius, supportOverlapReach(), near_,
        overlapPairs_
    );
    overlapBlocks_ =
        stencils_.overlapBlocks(mesh_.V(), alphaLambda_, overlapPairs_);
    fdm::sumOverRanks(overlapBlocks_);
}


void Foam::fdmParticleCloud::updatePairs()
{
    // One neighbour search per step serves the pair interactions, the
    // overlapping supports and the smallest gap of the progress line
    scalar reach =
        max(smallestGapReach(state_.radius), supportOverlapReach());
    for (const pairInteraction& pi : pairInteractions_)
    {
        reach = max(reach, pi.pairReach());
    }
    fdm::findNearPairs(box_, state_.position, state_.radius, reach, near_);
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
        state_.position, state_.radius, box_, near_, step, state_.Uold, 0
    };
    for (pairInteraction& pi : pairInteractions_)
    {
        pi.update(in);
        if (verbose_)
        {
            pi.report();
        }
    }
}


void Foam::fdmParticleCloud::relinearisePairs()
{
    for (pairInteraction& pi : pairInteractions_)
    {
        pi.relinearise(state_.U);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::fdmParticleCloud::nContacts() const
{
    return contacts_->nContacts();
}


Foam::scalar Foam::fdmParticleCloud::smallestGap() const
{
    if (empty())
    {
        return 2;
    }
    const scalar a1 = min(state_.radius);
    return
        fdm::smallestSurfaceGap
        (
            box_, state_.position, state_.radius,
            smallestGapReach(state_.radius), near_
        )/a1;
}


// ************************************************************************* //
