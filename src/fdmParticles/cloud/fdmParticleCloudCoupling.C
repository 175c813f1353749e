/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The FDM coupling of one outer iteration (thesis 1, eqs 2.41-2.45 in the
    smoothed form 2.53) and the motion between time steps.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "adamsBashforth.H"
#include "clockTime.H"
#include "sumOverRanks.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdmParticleCloud::buildStencils()
{
    clockTime clock;

    const vectorField& C = mesh_.C().primitiveField();
    const scalarField& V = mesh_.V();

    stencilStart_.setSize(size() + 1);
    stencilCell_.clear();
    stencilOffset_.clear();
    stencilJu_.clear();
    stencilJlambda_.clear();

    // Periodic image shifts: -span, 0, +span along periodic directions
    DynamicList<vector> shifts(27);
    for (label k = -1; k <= 1; ++k)
    for (label j = -1; j <= 1; ++j)
    for (label i = -1; i <= 1; ++i)
    {
        const FixedList<label, 3> s({i, j, k});
        bool valid = true;
        vector shift(Zero);
        for (direction d = 0; d < 3; ++d)
        {
            if (s[d] != 0 && !box_.periodic(d))
            {
                valid = false;
            }
            shift[d] = s[d]*box_.span()[d];
        }
        if (valid)
        {
            shifts.append(shift);
        }
    }

    DynamicList<label> found;
    forAll(position_, p)
    {
        stencilStart_[p] = stencilCell_.size();
        const scalar a = radius_[p];
        const scalar R = indicator_.supportRadius(a);

        for (const vector& shift : shifts)
        {
            const point centre = position_[p] + shift;
            found.clear();
            cellBins_->findInSphere(centre, R, found);
            for (const label celli : found)
            {
                const vector r = C[celli] - centre;
                stencilCell_.append(celli);
                stencilOffset_.append(r);
                stencilJu_.append(indicator_.Ju(mag(r), a));
                stencilJlambda_.append(1);
            }
        }
    }
    stencilStart_[size()] = stencilCell_.size();

    // J_lambda shared where supports overlap (section 2.3.2: 1/2 for two)
    labelList count(mesh_.nCells(), 0);
    DynamicList<label> support;
    for (const label celli : stencilCell_)
    {
        if (count[celli]++ == 0)
        {
            support.append(celli);
        }
    }
    forAll(stencilCell_, e)
    {
        stencilJlambda_[e] = 1.0/count[stencilCell_[e]];
    }
    supportCells_.transfer(support);
    lambdaPrev_.setSize(supportCells_.size());

    // Pseudo-mass moments (eq 2.53), summed over ranks
    List<scalar> m(10*size(), Zero);
    forAll(position_, p)
    {
        fdm::rigidBodyMoments mp;
        for (label e = stencilStart_[p]; e < stencilStart_[p + 1]; ++e)
        {
            mp.add(stencilJu_[e], stencilOffset_[e], V[stencilCell_[e]]);
        }
        scalar* s = &m[10*p];
        s[0] = mp.volume;
        for (direction d = 0; d < 3; ++d) { s[1 + d] = mp.firstMoment[d]; }
        for (direction d = 0; d < 6; ++d) { s[4 + d] = mp.inertia[d]; }
    }
    fdm::sumOverRanks(m);
    forAll(position_, p)
    {
        const scalar* s = &m[10*p];
        moments_[p].volume = s[0];
        for (direction d = 0; d < 3; ++d) { moments_[p].firstMoment[d] = s[1 + d]; }
        for (direction d = 0; d < 6; ++d) { moments_[p].inertia[d] = s[4 + d]; }
    }

    timings_.indicators += clock.elapsedTime();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdmParticleCloud::prepare(volVectorField& lambda)
{
    if (empty())
    {
        return;
    }

    buildStencils();
    subGrid_->update(position_, radius_, box_);
    if (verbose_)
    {
        subGrid_->report();
    }
    if (contacts_)
    {
        contacts_->update
        (
            position_, radius_, box_, mesh_.time().deltaTValue()
        );
        if (verbose_)
        {
            contacts_->report();
        }
        // Explicit loads for the coming solve; a solved state read at a
        // restart keeps the loads it was written with
        if (!solved_)
        {
            contactForce_ = contacts_->forces();
            contactTorque_ = contacts_->torques();
            contactStresslet_ = contacts_->stresslets();
        }
    }

    // lambda is not advected (thesis 2.4, step 2): keep it where a support
    // still covers the cell as the initial guess, zero elsewhere.
    boolList inSupport(mesh_.nCells(), false);
    for (const label celli : supportCells_)
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

    if (contacts_)
    {
        contacts_->advance(U_, Omega_, deltaT);
    }
    forAll(position_, p)
    {
        const point x =
            hasHistory_
          ? fdm::adamsBashforth2Step(position_[p], U_[p], Uold_[p], deltaT)
          : fdm::eulerStep(position_[p], U_[p], deltaT);
        position_[p] = box_.wrap(x);
    }
    Uold_ = U_;
    hasHistory_ = true;
    solved_ = false;

    // A particle pushed through a wall means the coupling has failed
    forAll(position_, p)
    {
        for (direction d = 0; d < 3; ++d)
        {
            const scalar lo = box_.min()[d];
            const scalar hi = lo + box_.span()[d];
            if
            (
                !box_.periodic(d)
             && (position_[p][d] < lo || position_[p][d] > hi)
            )
            {
                FatalErrorInFunction
                    << "Particle " << p << " left the domain at time "
                    << mesh_.time().timeName() << ": position "
                    << position_[p] << ", velocity " << U_[p] << nl
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

    // Integrals of eq 2.53 over the supports: J_u u**, J_u r x u**,
    // J_lambda lambda, J_lambda r x lambda
    List<scalar> sums(12*size(), Zero);
    forAll(position_, p)
    {
        vector fu(Zero), tu(Zero), fl(Zero), tl(Zero);
        for (label e = stencilStart_[p]; e < stencilStart_[p + 1]; ++e)
        {
            const label c = stencilCell_[e];
            const vector& r = stencilOffset_[e];
            const vector wu = (stencilJu_[e]*V[c])*u[c];
            const vector wl = (stencilJlambda_[e]*V[c])*l[c];
            fu += wu;
            tu += r ^ wu;
            fl += wl;
            tl += r ^ wl;
        }
        for (direction d = 0; d < 3; ++d)
        {
            sums[12*p + d] = fu[d];
            sums[12*p + 3 + d] = tu[d];
            sums[12*p + 6 + d] = fl[d];
            sums[12*p + 9 + d] = tl[d];
        }
    }
    fdm::sumOverRanks(sums);
    timings_.integrals += clock.timeIncrement();

    // Particle system (eqs 2.43-2.44, smoothed form 2.53), per unit fluid
    // density
    system_.clear();
    forAll(position_, p)
    {
        const particleGroup& g = groups_[group_[p]];
        const vector fu(sums[12*p], sums[12*p + 1], sums[12*p + 2]);
        const vector tu(sums[12*p + 3], sums[12*p + 4], sums[12*p + 5]);
        const vector fl(sums[12*p + 6], sums[12*p + 7], sums[12*p + 8]);
        const vector tl(sums[12*p + 9], sums[12*p + 10], sums[12*p + 11]);

        system_.addMass(p, moments_[p], 1/alphaLambda_);
        system_.addRhs
        (
            p,
            fu/alphaLambda_ - fl + bodyForce(p) + contactForce_[p]/rhoFluid_,
            tu/alphaLambda_ - tl
          + (g.torque() + contactTorque_[p])/rhoFluid_
        );
        for (direction d = 0; d < 3; ++d)
        {
            if (g.translationPrescribed())
            {
                system_.prescribe(p, d, g.translation()[d]);
            }
            if (g.rotationPrescribed())
            {
                system_.prescribe(p, 3 + d, g.rotation()[d]);
            }
        }
    }
    // Sub-grid resistance and implicit contact stiffness on the left of eq
    // 2.43, per unit fluid density
    subGrid_->addTo(system_, nu_);
    if (contacts_)
    {
        contacts_->addTo(system_, 1/rhoFluid_);
    }

    lastSolve_ = system_.solve(solveTolerance_, 1000, U_, Omega_);
    if (!lastSolve_.converged)
    {
        WarningInFunction
            << "Particle velocity solve not converged in "
            << lastSolve_.iterations << " iterations (relative residual "
            << lastSolve_.relativeResidual << ", particleSolveTolerance "
            << solveTolerance_ << ")" << endl;
    }
    timings_.solve += clock.timeIncrement();

    // Corrections (eq 2.53): lambda from u** first, then u.  Where two
    // J_u supports overlap the second particle corrects the already
    // corrected value, so each update stays a convex combination.
    forAll(supportCells_, i)
    {
        lambdaPrev_[i] = l[supportCells_[i]];
    }
    forAll(position_, p)
    {
        for (label e = stencilStart_[p]; e < stencilStart_[p + 1]; ++e)
        {
            const label c = stencilCell_[e];
            const vector rigid = U_[p] + (Omega_[p] ^ stencilOffset_[e]);
            l[c] += (stencilJlambda_[e]/alphaLambda_)*(rigid - u[c]);
        }
    }
    forAll(position_, p)
    {
        for (label e = stencilStart_[p]; e < stencilStart_[p + 1]; ++e)
        {
            const label c = stencilCell_[e];
            const vector rigid = U_[p] + (Omega_[p] ^ stencilOffset_[e]);
            u[c] += stencilJu_[e]*(rigid - u[c]);
        }
    }
    U.correctBoundaryConditions();
    lambda.correctBoundaryConditions();

    // Residual of eq 2.54; lambda is zero outside the supports, so the sums
    // over support cells are the sums over the mesh
    scalar diff = 0, norm = 0;
    forAll(supportCells_, i)
    {
        const vector& li = l[supportCells_[i]];
        diff += mag(li - lambdaPrev_[i]);
        norm += mag(li);
    }
    reduce(diff, sumOp<scalar>());
    reduce(norm, sumOp<scalar>());
    lambdaResidual_ = diff == 0 ? 0 : diff/max(norm, VSMALL);

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

    // Per particle: force (3), lambda (x) r (9), pressure integral (1)
    const label nSum = 13;
    List<scalar> sums(nSum*size(), Zero);
    forAll(position_, n)
    {
        vector f(Zero);
        tensor moment(Zero);
        scalar pressure = 0;
        for (label e = stencilStart_[n]; e < stencilStart_[n + 1]; ++e)
        {
            const label c = stencilCell_[e];
            const vector w = (stencilJlambda_[e]*V[c])*l[c];
            f += w;
            moment += w*stencilOffset_[e];
            pressure += stencilJu_[e]*V[c]*(pc[c] - pMean);
        }
        scalar* s = &sums[nSum*n];
        for (direction d = 0; d < 3; ++d)
        {
            s[d] = f[d];
        }
        for (direction d = 0; d < 9; ++d)
        {
            s[3 + d] = moment[d];
        }
        s[12] = pressure;
    }
    fdm::sumOverRanks(sums);
    lambdaPartsSum_ = Zero;
    forAll(position_, n)
    {
        const scalar* s = &sums[nSum*n];
        lambdaPartsSum_ += vector(s[0], s[1], s[2]);
        force_[n] = -rhoFluid_*vector(s[0], s[1], s[2]);
        const tensor D =
            -rhoFluid_
           *(
                tensor(s[3], s[4], s[5], s[6], s[7], s[8], s[9], s[10], s[11])
              + s[12]*tensor::I
            );
        // T = int r x (sigma n) dS: epsilon_ijk D_kj with D_kj = f_k r_j
        torque_[n] = vector
        (
            D.zy() - D.yz(),
            D.xz() - D.zx(),
            D.yx() - D.xy()
        );
        stresslet_[n] = dev(symm(D));
        dipoleTrace_[n] = tr(D);
    }

    // Hydrodynamic totals: FDM + sub-grid (eqs 2.9, 2.68)
    subGrid_->addHydrodynamics
    (
        U_, Omega_, rhoFluid_*nu_, force_, torque_, stresslet_, dipoleTrace_
    );

    // Contact loads: explicit part and the implicit stiffness' share at the
    // solved velocities
    if (contacts_)
    {
        contactForce_ = contacts_->forces();
        contactTorque_ = contacts_->torques();
        contactStresslet_ = contacts_->stresslets();
        contacts_->addImplicitLoads
        (
            U_, Omega_, contactForce_, contactTorque_, contactStresslet_
        );
    }

    firstSolveDone_ = true;
}


// ************************************************************************* //
