/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The FDM coupling of one outer iteration (thesis 1, eqs 2.41-2.45 in the
    smoothed form 2.53): the stencils and owners at the current positions,
    the particle system, its solve and the corrections, and the loads.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "ranksHoldingPoints.H"
#include "clockTime.H"
#include "sumToOwners.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdmParticleCloud::buildStencils()
{
    clockTime clock;

    // The rank that solves each particle's rows: its centre's, found among
    // the ranks holding the particle
    if (distributedSolve_)
    {
        const labelList owner
        (
            fdm::ranksHoldingPoints
            (
                state_.position, mesh_.C().primitiveField(), cellBins_(),
                delta_, halo_.held()
            )
        );
        const label lost = owner.find(-1);
        if (lost >= 0)
        {
            FatalErrorInFunction
                << "Particle " << lost << " at time "
                << mesh_.time().timeName() << ": its centre "
                << state_.position[lost] << " is in no cell of the ranks"
                << " holding it; it moved further than its reach in one"
                << " step." << nl << "    Lower deltaT in system/controlDict;"
                << " the last written time is the last good state."
                << exit(FatalError);
        }
        halo_.setOwners
        (
            owner, state_.position, fdm::couplingStencils::imageShifts(box_)
        );
        ownedRows_.setOwners(owner);
        if (!firstSolveDone_)
        {
            halo_.report();
        }
    }

    stencils_.build
    (
        mesh_.C().primitiveField(),
        cellBins_(),
        state_.position,
        state_.radius,
        indicator_,
        box_,
        consistentOverlaps_,
        halo_.held()
    );
    lambdaPrev_.setSize(stencils_.supportCells().size());

    // Pseudo-mass moments (eq 2.53), summed over ranks (on the owners)
    moments_ = stencils_.moments(mesh_.V());
    fdm::sumToOwners(moments_, halo_.owner(), stencils_);

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
        if (!halo_.owns(p))
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
    fdm::sumToOwners(sums, halo_.owner(), stencils_);
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
            ownedRows_.entries(), halo_.owner(), solveTolerance_, 1000,
            state_.U, state_.Omega, residualScale
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
    halo_.sendToGhosts(state_.U, state_.Omega);
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
    fdm::sumToOwners(sums, halo_.owner(), stencils_);
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
    if (distributedSolve_)
    {
        reduce(lambdaPartsSum_, sumOp<vector>());
    }

    addPairLoads();

    firstSolveDone_ = true;
}


// ************************************************************************* //
