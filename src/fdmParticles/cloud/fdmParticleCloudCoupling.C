/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The FDM coupling of one outer iteration (thesis 1, eqs 2.41-2.45 in the
    smoothed form 2.53) and the motion between time steps.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "ranksHoldingPoints.H"
#include "adamsBashforth.H"
#include "clockTime.H"
#include "sumToOwners.H"
#include "leesEdwardsShear.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdmParticleCloud::buildStencils()
{
    clockTime clock;

    stencils_.build
    (
        mesh_.C().primitiveField(),
        cellBins_(),
        state_.position,
        state_.radius,
        indicator_,
        box_,
        consistentOverlaps_
    );
    lambdaPrev_.setSize(stencils_.supportCells().size());

    // The rank that solves each particle's rows: its centre's (the master
    // for a centre in no rank's cells)
    if (distributedSolve_)
    {
        owner_ = fdm::ranksHoldingPoints
        (
            state_.position, mesh_.C().primitiveField(), cellBins_(), delta_
        );
        forAll(owner_, p)
        {
            owner_[p] = owner_[p] < 0 ? Pstream::masterNo() : owner_[p];
        }
        ownedRows_.setOwners(owner_);
    }

    // Pseudo-mass moments (eq 2.53), summed over ranks
    moments_ = stencils_.moments(mesh_.V());
    fdm::sumToOwners(moments_, owner_, stencils_);

    timings_.indicators += clock.elapsedTime();
}


Foam::scalar Foam::fdmParticleCloud::assembleSystem
(
    const List<fdm::couplingStencils::supportIntegrals>& sums
)
{
    // Particle system (eqs 2.43-2.44, smoothed form 2.53), per unit fluid
    // density: whole, or the rows of this rank's particles
    system_.clear();
    ownedRows_.clear();
    fdm::particleSystemSink& system =
        distributedSolve_
      ? static_cast<fdm::particleSystemSink&>(ownedRows_)
      : system_;
    // The contacts' explicit loads, linearised about the latest velocities
    const fdm::particleLoads& contact = contacts_->loads();
    scalar flowLoads2 = 0;
    forAll(state_.position, p)
    {
        // Solved by subdomain, this rank holds the sums of its own only
        if (distributedSolve_ && owner_[p] != Pstream::myProcNo())
        {
            continue;
        }
        const particleGroup& g = groups_[state_.group[p]];
        const fdm::couplingStencils::supportIntegrals& s = sums[p];

        system.addMass(p, moments_[p], 1/alphaLambda_);
        const vector force = s.fu/alphaLambda_ - s.fl + bodyForce(p);
        const vector torque = s.tu/alphaLambda_ - s.tl + g.torque()/rhoFluid_;
        flowLoads2 += magSqr(force) + magSqr(torque);
        system.addRhs
        (
            p,
            force + contact.force[p]/rhoFluid_,
            torque + contact.torque[p]/rhoFluid_
        );
        for (direction d = 0; d < 3; ++d)
        {
            if (g.translationPrescribed())
            {
                system.prescribe(p, d, g.translation()[d]);
            }
            if (g.rotationPrescribed())
            {
                system.prescribe(p, 3 + d, g.rotation()[d]);
            }
        }
    }
    // Neighbours coupled through shared cells (consistent overlaps); the
    // sub-grid resistance and the implicit contact stiffness on the left
    // of eq 2.43, per unit fluid density
    fdm::couplingStencils::addOverlapBlocks
    (
        overlapPairs_, overlapBlocks_, system
    );
    for (const pairInteraction& pi : pairInteractions_)
    {
        pi.addTo(system, fdm::fluidProperties{rhoFluid_, nu_});
    }
    if (distributedSolve_)
    {
        reduce(flowLoads2, sumOp<scalar>());
    }
    return Foam::sqrt(flowLoads2);
}


Foam::scalar Foam::fdmParticleCloud::lambdaChange
(
    const vectorField& l
) const
{
    // Residual of eq 2.54; lambda is zero outside the supports, so the sums
    // over support cells are the sums over the mesh
    const labelList& supportCells = stencils_.supportCells();
    scalar diff = 0, norm = 0;
    forAll(supportCells, i)
    {
        const vector& li = l[supportCells[i]];
        diff += mag(li - lambdaPrev_[i]);
        norm += mag(li);
    }
    reduce(diff, sumOp<scalar>());
    reduce(norm, sumOp<scalar>());
    return diff == 0 ? 0 : diff/max(norm, VSMALL);
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
    forAll(state_.position, p)
    {
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

    prepare(lambda);
}


Foam::scalar Foam::fdmParticleCloud::correct
(
    volVectorField& U,
    volVectorField& lambda
)
{
    if (empty())
    {
        return 0;
    }

    clockTime clock;
    const scalarField& V = mesh_.V();
    vectorField& u = U.primitiveFieldRef();
    vectorField& l = lambda.primitiveFieldRef();

    // Integrals of eq 2.53 over the supports
    List<fdm::couplingStencils::supportIntegrals> sums
    (
        stencils_.integrals(V, u, l)
    );
    fdm::sumToOwners(sums, owner_, stencils_);
    timings_.integrals += clock.timeIncrement();

    // From the second outer iteration on, the contacts linearised again
    // about the end-of-step gaps of the last solved velocities (as often
    // as the contact model does: particleContacts twice a step)
    if (solved_)
    {
        relinearisePairs();
        clock.timeIncrement();      // counted in timings_.pairs
    }
    const scalar residualScale = assembleSystem(sums);
    lastSolve_ =
        distributedSolve_
      ? ownedSolve_.solve
        (
            ownedRows_.entries(), owner_, solveTolerance_, 1000, state_.U,
            state_.Omega, residualScale
        )
      : system_.solve
        (
            solveTolerance_, 1000, state_.U, state_.Omega, residualScale
        );
    if (!lastSolve_.converged)
    {
        WarningInFunction
            << "Particle velocity solve not converged in "
            << lastSolve_.iterations << " iterations (relative residual "
            << lastSolve_.relativeResidual << ", particleSolveTolerance "
            << solveTolerance_ << ")" << endl;
    }
    timings_.solve += clock.timeIncrement();

    // Corrections (eq 2.53): lambda from u** first, then u
    const labelList& supportCells = stencils_.supportCells();
    forAll(supportCells, i)
    {
        lambdaPrev_[i] = l[supportCells[i]];
    }
    stencils_.correctLambda(state_.U, state_.Omega, alphaLambda_, u, l);
    stencils_.correctVelocity(state_.U, state_.Omega, u);
    U.correctBoundaryConditions();
    lambda.correctBoundaryConditions();

    lambdaResidual_ = lambdaChange(l);
    solved_ = true;
    timings_.corrections += clock.timeIncrement();

    return lambdaResidual_;
}


void Foam::fdmParticleCloud::finishSolve
(
    const volVectorField& lambda,
    const volScalarField& p
)
{
    if (empty())
    {
        return;
    }

    // The force dipole of particle n (eq 2.66, no inertia):
    //     D = -rho_f int J_lambda lambda (x) r dV - rho_f int J_u p dV I
    // its antisymmetric part is the torque, its symmetric traceless part
    // the stresslet and its trace s (eq 2.67).  The force is minus the
    // J_lambda-weighted integral of rho_f lambda (eq 2.6).  The pressure is
    // taken relative to its domain mean (thesis 2.7.2) and weighted with
    // J_u, the indicator of the particle volume where sigma = -p I.
    const scalarField& V = mesh_.V();
    const vectorField& l = lambda.primitiveField();
    const scalarField& pc = p.primitiveField();
    const scalar pMean = gSum(pc*V)/gSum(V);

    List<fdm::couplingStencils::dipoleIntegrals> sums
    (
        stencils_.dipoles(V, l, pc, pMean)
    );
    fdm::sumOverRanks(sums);
    lambdaPartsSum_ = Zero;
    forAll(state_.position, n)
    {
        const fdm::couplingStencils::dipoleIntegrals& s = sums[n];
        lambdaPartsSum_ += s.force;
        hydro_.force[n] = -rhoFluid_*s.force;
        const tensor D = -rhoFluid_*(s.moment + s.pressure*tensor::I);
        // T = int r x (sigma n) dS: epsilon_ijk D_kj with D_kj = f_k r_j
        hydro_.torque[n] = vector
        (
            D.zy() - D.yz(),
            D.xz() - D.zx(),
            D.yx() - D.xy()
        );
        hydro_.stresslet[n] = dev(symm(D));
        dipoleTrace_[n] = tr(D);
    }

    addPairLoads();

    firstSolveDone_ = true;
}


// ************************************************************************* //
