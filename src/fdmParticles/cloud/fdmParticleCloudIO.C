/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    Particle state for restarts, and the calls of particleCloudOutput (HDF5
    time series, lagrangian cloud, VTK series) after the finite check.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "particleStateFile.H"
#include "isFinite.H"
#include "planeWalls.H"

// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::fdmParticleCloud::~fdmParticleCloud()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdmParticleCloud::checkFinite() const
{
    const Time& runTime = mesh_.time();
    const auto stop = [&](const char* what, const label p)
    {
        FatalErrorInFunction
            << "Non-finite " << what << " of particle " << p << " at time "
            << runTime.timeName() << ": nothing of this time is written"
            << " (particleState, particles.h5, VTK); the last written time"
            << " is the last good state." << nl
            << "    The solve diverged: lower the U relaxation factor in"
            << " system/fvSolution, use acceleration anderson there, or"
            << " lower deltaT in system/controlDict." << exit(FatalError);
    };
    forAll(state_.position, p)
    {
        if (!fdm::isFinite(state_.position[p])) stop("position", p);
        if (!fdm::isFinite(state_.U[p])) stop("velocity", p);
        if (!fdm::isFinite(state_.Omega[p])) stop("angular velocity", p);
        if (!fdm::isFinite(hydro_.force[p])) stop("force", p);
        if (!fdm::isFinite(hydro_.torque[p])) stop("torque", p);
        if (!fdm::isFinite(hydro_.stresslet[p])) stop("stresslet", p);
        if (!fdm::isFinite(dipoleTrace_[p])) stop("dipole trace", p);
        if (!fdm::isFinite(contact_.force[p])) stop("contact force", p);
        if (!fdm::isFinite(contact_.torque[p])) stop("contact torque", p);
        if (!fdm::isFinite(contact_.stresslet[p])) stop("contact stresslet", p);
    }
}


void Foam::fdmParticleCloud::checkMotionResolved(const scalar deltaT) const
{
    // A step moving a particle by more than a cell has not resolved its
    // motion: a contact or lubrication force evaluated at the start of the
    // step lets pairs overlap deeper than the roughness, and the next solve
    // throws them apart (the Couette suspension at gammaDot deltaT 8e-3:
    // Courant 410 after 1.67 strain, where 0.19 is the largest at 4e-3;
    // validation/benchmarks/couetteTimeStep)
    label fastest = -1;
    scalar largest = 0;
    forAll(state_.U, p)
    {
        if (!halo_.holds(p))
        {
            continue;
        }
        const scalar courant = mag(state_.U[p])*deltaT/delta_;
        if (!(courant <= largest))
        {
            fastest = p;
            largest = courant;
        }
    }
    if (fastest < 0 || largest <= maxCourant_)
    {
        return;
    }
    FatalErrorInFunction
        << "Particle " << fastest << " would move "
        << largest*delta_/state_.radius[fastest] << " radii ("
        << largest << " mesh spacings) in one step at time "
        << mesh_.time().timeName() << ": velocity " << state_.U[fastest]
        << ", deltaT " << deltaT << "; coupling.maxParticleCourant in "
        << dict_.objectPath() << " allows " << maxCourant_ << " (values > 0)."
        << nl << "    Nothing of this time is written; the last written"
        << " time is the last good state.  The step does not resolve the"
        << " particles' motion: lower deltaT in system/controlDict."
        << exit(FatalError);
}


void Foam::fdmParticleCloud::gatherOnMaster()
{
    // Once per time step: the time series, VTK and restart writers may all
    // write the same step
    const label timeIndex = mesh_.time().timeIndex();
    if (timeIndex == gatheredTimeIndex_)
    {
        return;
    }
    gatheredTimeIndex_ = timeIndex;
    halo_.gatherOnMaster
    (
        state_.position, state_.U, state_.Omega, state_.Uold,
        hydro_.force, hydro_.torque, hydro_.stresslet, dipoleTrace_,
        contact_.force, contact_.torque, contact_.stresslet
    );
}


void Foam::fdmParticleCloud::writeState()
{
    // Every rank has written its fields of this time before the particle
    // state, the last file of a time directory, appears: a time with a
    // particleState is whole (a restart relies on it)
    label sync = 0;
    reduce(sync, sumOp<label>());

    if (empty())
    {
        return;
    }
    // Each rank's particles and contacts when solved by subdomain, on the
    // master
    gatherOnMaster();
    const fdm::pairHistory<vector> contactHistory(contacts_->wholeHistory());
    if (!Pstream::master())
    {
        return;
    }
    checkFinite();

    const Time& runTime = mesh_.time();
    fdm::writeParticleStateFile
    (
        runTime.globalPath()/runTime.timeName(),
        runTime.timeName(),
        mesh_,
        [&](Ostream& os)
        {
            os.writeEntry("nParticles", size());
            os.writeEntry("solved", solved_);
            os.writeEntry("hasHistory", historyDeltaT_ > 0);
            os.writeEntry("historyDeltaT", historyDeltaT_);
            os.writeEntry("radius", state_.radius);
            os.writeEntry("position", state_.position);
            os.writeEntry("velocity", state_.U);
            os.writeEntry("angularVelocity", state_.Omega);
            os.writeEntry("previousVelocity", state_.Uold);
            os.writeEntry("force", hydro_.force);
            os.writeEntry("torque", hydro_.torque);
            os.writeEntry("stresslet", hydro_.stresslet);
            os.writeEntry("dipoleTrace", dipoleTrace_);
            contacts_->writeState(os, contact_, contactHistory);
        }
    );
}


Foam::particleHDF5Metadata::description
Foam::fdmParticleCloud::hdf5Description() const
{
    wordList groupNames(groups_.size());
    forAll(groups_, g)
    {
        groupNames[g] = groups_[g].name();
    }
    // The imposed shear rate: the Lees-Edwards box's or the walls'
    const scalar shearRate = box_.shearVelocity() != 0
      ? box_.shearVelocity()/box_.span().y()
      : planeWalls(mesh_, "HDF5 description", false).shearRate();
    particleHDF5Metadata::description d =
        particleHDF5Metadata::runDescription
        (
            "fdmSuspensionFoam (libfdmParticles)", mesh_.time().globalPath(),
            groupNames, dict_, rhoFluid_*nu_, shearRate,
            mesh_.bounds(), box_.periodic()
        );
    d.numbers.insert
    (
        d.numbers.end(),
        {
            {"fluidDensity", {rhoFluid_}},
            {"kinematicViscosity", {nu_}},
            {"gravity", {gravity_.x(), gravity_.y(), gravity_.z()}},
            {"meshSpacing", {delta_}}
        }
    );
    return d;
}


Foam::particleCloudOutput::particles
Foam::fdmParticleCloud::outputView() const
{
    return {state_, hydro_, dipoleTrace_, contact_, halo_.held()};
}


void Foam::fdmParticleCloud::writeTimeSeries()
{
    if (empty())
    {
        return;
    }
    if (output_->timeSeriesDue())
    {
        gatherOnMaster();
        checkFinite();
    }
    output_->writeTimeSeries
    (
        outputView(),
        [this]() { return hdf5Description(); }
    );
}


void Foam::fdmParticleCloud::writeLagrangian() const
{
    if (empty())
    {
        return;
    }
    checkFinite();
    output_->writeLagrangian(outputView());
}


void Foam::fdmParticleCloud::writeVTK()
{
    if (empty() || !output_->vtkDue())
    {
        return;
    }
    gatherOnMaster();
    checkFinite();
    // Each rank's contacts when solved by subdomain, on the master
    output_->writeVTK
    (
        outputView(),
        contacts_->network(state_.U, state_.Omega)
    );
}


// ************************************************************************* //
