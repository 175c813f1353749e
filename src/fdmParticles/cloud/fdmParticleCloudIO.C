/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    Particle state for restarts, the HDF5 time series, the lagrangian
    cloud and the VTK series for ParaView.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "lagrangianCloudWriter.H"
#include "particleVTKWriter.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOobject.H"
#include "isFinite.H"
#include "planeWalls.H"
#include "StringStream.H"

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
    forAll(position_, p)
    {
        if (!fdm::isFinite(position_[p])) stop("position", p);
        if (!fdm::isFinite(U_[p])) stop("velocity", p);
        if (!fdm::isFinite(Omega_[p])) stop("angular velocity", p);
        if (!fdm::isFinite(force_[p])) stop("force", p);
        if (!fdm::isFinite(torque_[p])) stop("torque", p);
        if (!fdm::isFinite(stresslet_[p])) stop("stresslet", p);
        if (!fdm::isFinite(dipoleTrace_[p])) stop("dipole trace", p);
        if (!fdm::isFinite(contactForce_[p])) stop("contact force", p);
        if (!fdm::isFinite(contactTorque_[p])) stop("contact torque", p);
        if (!fdm::isFinite(contactStresslet_[p])) stop("contact stresslet", p);
    }
}


void Foam::fdmParticleCloud::writeState() const
{
    // Every rank has written its fields of this time before the particle
    // state, the last file of a time directory, appears: a time with a
    // particleState is whole (a restart relies on it)
    label sync = 0;
    reduce(sync, sumOp<label>());

    if (empty() || !Pstream::master())
    {
        return;
    }
    checkFinite();

    const Time& runTime = mesh_.time();
    const fileName dir = runTime.globalPath()/runTime.timeName();
    mkDir(dir);

    // Written under a temporary name and renamed: a kill leaves either no
    // particleState or a whole one
    const fileName tmp = dir/"particleState.tmp";
    {
        OFstream os(tmp);
        // Full precision: a restart must continue the same trajectory
        os.precision(17);
        IOobject io
        (
            "particleState",
            runTime.timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        );
        io.writeHeader(os, "dictionary");

        os.writeEntry("nParticles", size());
        os.writeEntry("solved", solved_);
        os.writeEntry("hasHistory", hasHistory_);
        os.writeEntry("radius", radius_);
        os.writeEntry("position", position_);
        os.writeEntry("velocity", U_);
        os.writeEntry("angularVelocity", Omega_);
        os.writeEntry("previousVelocity", Uold_);
        os.writeEntry("force", force_);
        os.writeEntry("torque", torque_);
        os.writeEntry("stresslet", stresslet_);
        os.writeEntry("dipoleTrace", dipoleTrace_);
        if (contacts_)
        {
            os.writeEntry("contactForce", contactForce_);
            os.writeEntry("contactTorque", contactTorque_);
            os.writeEntry("contactStresslet", contactStresslet_);
            contacts_->writeState(os);
        }
        IOobject::writeEndDivider(os);
        os.flush();
        if (!os.good())
        {
            FatalErrorInFunction
                << "Cannot write " << tmp << " (disk full?)"
                << exit(FatalError);
        }
    }
    mv(tmp, dir/"particleState");
}


Foam::particleHDF5Metadata::description
Foam::fdmParticleCloud::hdf5Description() const
{
    particleHDF5Metadata::description d;
    std::string groups;
    for (const particleGroup& g : groups_)
    {
        groups += g.name() + "\n";
    }
    dictionary parameters(dict_);
    parameters.remove("particles");
    OStringStream entries;
    parameters.write(entries, false);
    d.text =
    {
        {"solver", "fdmSuspensionFoam (libfdmParticles)"},
        {"openfoamApi", std::to_string(OPENFOAM)},
        {"case", mesh_.time().globalPath()},
        {"groupNames", groups},
        {"particleProperties", entries.str()}
    };

    const boundBox& bb = mesh_.bounds();
    auto numbers = [](const vector& v)
    {
        return std::vector<double>{v.x(), v.y(), v.z()};
    };
    d.numbers =
    {
        {"fluidDensity", {rhoFluid_}},
        {"viscosity", {rhoFluid_*nu_}},
        {"kinematicViscosity", {nu_}},
        {
            "shearRate",
            {planeWalls(mesh_, "HDF5 description", false).shearRate()}
        },
        {"boxMin", numbers(bb.min())},
        {"boxMax", numbers(bb.max())},
        {
            "periodic",
            {
                double(box_.periodic(0)), double(box_.periodic(1)),
                double(box_.periodic(2))
            }
        },
        {"gravity", numbers(gravity_)},
        {"meshSpacing", {delta_}}
    };
    return d;
}


void Foam::fdmParticleCloud::writeTimeSeries()
{
    if (empty())
    {
        return;
    }
    const Time& runTime = mesh_.time();
    if (runTime.timeIndex() % timeSeriesInterval_ == 0)
    {
        checkFinite();
        if (!timeSeries_)
        {
            // Created at the first record, so that -postProcess, which
            // constructs the cloud but records nothing, leaves it alone
            timeSeries_.reset
            (
                new particleHDF5Writer
                (
                    runTime.globalPath()/"postProcessing"/"particles.h5",
                    radius_,
                    group_,
                    runTime.value(),
                    hdf5Description()
                )
            );
        }
        timeSeries_->append
        (
            runTime.value(),
            {
                position_, U_, Omega_, force_, torque_, stresslet_,
                dipoleTrace_, contactForce_, contactTorque_,
                contactStresslet_
            }
        );
    }
    if (timeSeries_ && runTime.writeTime())
    {
        // Publish the records up to this write time
        timeSeries_->commit();
    }
}


void Foam::fdmParticleCloud::writeLagrangian() const
{
    if (empty())
    {
        return;
    }
    checkFinite();

    const lagrangianCloudWriter cloud(mesh_, "particles", position_);
    cloud.write("id", labelList(identity(size())));
    cloud.write("group", group_);
    cloud.write("d", scalarField(2*radius_));
    cloud.write("U", U_);
    cloud.write("omega", Omega_);
    cloud.write("force", force_);
    cloud.write("torque", torque_);
    cloud.write("stresslet", stresslet_);
    cloud.write("contactForce", contactForce_);
    cloud.write("contactTorque", contactTorque_);
    cloud.write("contactStresslet", contactStresslet_);
}


void Foam::fdmParticleCloud::writeVTK()
{
    const Time& runTime = mesh_.time();
    const bool due = fdm::particleVTKWriter::due
    (
        vtkInterval_, runTime.timeIndex(), runTime.writeTime()
    );
    if (empty() || !Pstream::master() || (vtk_ && !due))
    {
        return;
    }
    checkFinite();
    if (!vtk_)
    {
        // Created at the first call, the start time: the series begins
        // with the initial state (and -postProcess never gets here)
        vtk_.reset
        (
            new fdm::particleVTKWriter
            (
                runTime.globalPath()/"VTK", runTime.value()
            )
        );
    }

    auto file = vtk_->particles
    (
        runTime.timeName(), runTime.value(), position_
    );
    file.write("id", labelList(identity(size())));
    file.write("group", group_);
    file.write("radius", radius_);
    file.write("velocity", U_);
    file.write("angularVelocity", Omega_);
    file.write("force", force_);
    file.write("torque", torque_);
    file.write("stresslet", stresslet_);
    file.write("dipoleTrace", dipoleTrace_);
    file.write("contactForce", contactForce_);
    file.write("contactTorque", contactTorque_);
    file.write("contactStresslet", contactStresslet_);
    file.close();

    vtk_->contacts
    (
        runTime.timeName(),
        runTime.value(),
        position_,
        contacts_ ? contacts_->network(U_, Omega_) : fdm::contactNetwork()
    );
}


// ************************************************************************* //
