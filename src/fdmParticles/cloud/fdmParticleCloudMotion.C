/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The particles between time steps (thesis 1, section 2.4, steps 1-2):
    the move by Adams-Bashforth (by subdomain, each owner moving its own
    and sending them to the ranks within reach), and the preparation of
    the next solve at the new positions.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "adamsBashforth.H"
#include "leesEdwardsShear.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdmParticleCloud::checkAlternation(const scalar deltaT)
{
    // The zig-zag is measured against the contacts' roughness, over which
    // their forces change; without contacts there is nothing to bias
    const scalar roughness = contacts_->pairReach();
    if (roughness <= 0)
    {
        return;
    }
    boolList moved;
    if (distributedSolve_)
    {
        moved.setSize(state_.U.size());
        forAll(moved, p)
        {
            moved[p] = halo_.owns(p);
        }
    }
    const scalar limit =
        fdm::velocityAlternation::roughnessFraction*roughness;
    scalar zigzag = 0;
    const bool warn = alternation_.check
    (
        state_.U, state_.Uold, deltaT, limit, moved, distributedSolve_, zigzag
    );
    if (verbose_ && zigzag >= 0)
    {
        Info<< "Velocity alternation: positions zig-zag by "
            << zigzag/roughness << " h_r rms" << endl;
    }
    if (warn)
    {
        WarningInFunction
            << "Time " << mesh_.time().timeName() << ": the particle"
            << " velocities alternate from step to step; for "
            << fdm::velocityAlternation::stepsInARow << " steps the"
            << " positions zig-zagged by more than "
            << fdm::velocityAlternation::roughnessFraction << " h_r rms ("
            << zigzag/roughness << " h_r now): the two-step position"
            << " update is beyond its stable step and the contact stresses"
            << " are biased (adhesive contacts at gammaDot deltaT 4e-3:"
            << " eta_core 16 % low)." << nl
            << "    Lower deltaT in system/controlDict (there 1e-3: within"
            << " 0.2 %)." << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdmParticleCloud::prepare(volVectorField& lambda)
{
    if (empty())
    {
        return;
    }

    buildStencils();
    updatePairs();

    // A solved state read at a restart keeps the loads it was written
    // with, and its contacts are linearised about the gaps its velocities
    // predict, as they were
    if (solved_)
    {
        relinearisePairs();
    }

    // lambda is not advected (thesis 2.4, step 2): keep it where a support
    // still covers the cell as the initial guess, zero elsewhere.
    boolList inSupport(mesh_.nCells(), false);
    for (const label celli : stencils_.supportCells())
    {
        inSupport[celli] = true;
    }
    vectorField& l = lambda.primitiveFieldRef();
    forAll(l, celli)
    {
        if (!inSupport[celli])
        {
            l[celli] = Zero;
        }
    }
    lambda.correctBoundaryConditions();
}


void Foam::fdmParticleCloud::move(const scalar deltaT, volVectorField& lambda)
{
    if (empty())
    {
        return;
    }
    if (!solved_)
    {
        FatalErrorInFunction
            << "Particles cannot move before their velocities are solved"
            << abort(FatalError);
    }

    checkAlternation(deltaT);
    for (pairInteraction& pi : pairInteractions_)
    {
        pi.advance(state_.U, state_.Omega, deltaT);
    }
    // The sheared images of the new time (Lees-Edwards): a particle
    // wrapped across the sheared faces takes the flow's velocity there
    fdm::setLeesEdwardsShear(mesh_, box_);
    const fdm::positionStep step
    (
        fdm::positionStep::after(positionScheme_, historyDeltaT_, deltaT)
    );
    // By subdomain each owner moves its own, then sends them to the ranks
    // within their reach
    forAll(state_.position, p)
    {
        if (!halo_.owns(p))
        {
            continue;
        }
        const point x =
            state_.position[p]
          + step.displacement(state_.U[p], state_.Uold[p]);
        state_.U[p] = box_.wrapVelocity(x, state_.U[p]);
        state_.position[p] = box_.wrap(x);
    }
    state_.Uold = state_.U;
    historyDeltaT_ = deltaT;
    solved_ = false;

    // A particle pushed through a wall means the coupling has failed
    forAll(state_.position, p)
    {
        if (!halo_.owns(p))
        {
            continue;
        }
        for (direction d = 0; d < 3; ++d)
        {
            const scalar lo = box_.min()[d];
            const scalar hi = lo + box_.span()[d];
            if
            (
                !box_.periodic(d)
             && (state_.position[p][d] < lo || state_.position[p][d] > hi)
            )
            {
                FatalErrorInFunction
                    << "Particle " << p << " left the domain at time "
                    << mesh_.time().timeName() << ": position "
                    << state_.position[p] << ", velocity " << state_.U[p] << nl
                    << "    Reduce deltaT in system/controlDict; the last"
                    << " written time is the last good state."
                    << exit(FatalError);
            }
        }
    }
    halo_.sendMoved(state_, fdm::couplingStencils::imageShifts(box_));

    prepare(lambda);
}


// ************************************************************************* //
