/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    Particle state for restarts and VTK output for ParaView.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "lagrangianCloudWriter.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOobject.H"
#include "isFinite.H"

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
                    runTime.value()
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
    labelList id(size());
    forAll(id, p)
    {
        id[p] = p;
    }
    cloud.write("id", id);
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


void Foam::fdmParticleCloud::writeVTK() const
{
    if (empty() || !Pstream::master())
    {
        return;
    }

    const Time& runTime = mesh_.time();
    const fileName dir = runTime.globalPath()/"VTK";
    mkDir(dir);
    const word name = "particles_" + runTime.timeName() + ".vtk";

    {
        // Legacy ASCII polydata: one vertex per particle with its data;
        // in ParaView show with the Glyph filter (sphere, scale by radius)
        OFstream os(dir/name);
        os.precision(10);
        os  << "# vtk DataFile Version 3.0" << nl
            << "fdmSuspension particles, time " << runTime.timeName() << nl
            << "ASCII" << nl
            << "DATASET POLYDATA" << nl
            << "POINTS " << size() << " double" << nl;
        for (const point& x : position_)
        {
            os  << x.x() << ' ' << x.y() << ' ' << x.z() << nl;
        }
        os  << "VERTICES " << size() << ' ' << 2*size() << nl;
        forAll(position_, p)
        {
            os  << "1 " << p << nl;
        }
        os  << "POINT_DATA " << size() << nl
            << "SCALARS radius double 1" << nl
            << "LOOKUP_TABLE default" << nl;
        for (const scalar a : radius_)
        {
            os  << a << nl;
        }
        os  << "SCALARS group int 1" << nl
            << "LOOKUP_TABLE default" << nl;
        for (const label g : group_)
        {
            os  << g << nl;
        }

        auto writeVectors = [&os](const char* title, const List<vector>& v)
        {
            os  << "VECTORS " << title << " double" << nl;
            for (const vector& x : v)
            {
                os  << x.x() << ' ' << x.y() << ' ' << x.z() << nl;
            }
        };
        writeVectors("velocity", U_);
        writeVectors("angularVelocity", Omega_);
        writeVectors("force", force_);
        writeVectors("torque", torque_);
        writeVectors("contactForce", contactForce_);
    }

    // Series file listing every particles_<time>.vtk present, by time
    fileNameList files = readDir(dir, fileName::FILE);
    DynamicList<Tuple2<scalar, word>> entries;
    for (const fileName& f : files)
    {
        const word n = f.name();
        if (n.startsWith("particles_") && n.hasExt("vtk"))
        {
            const word t = n.substr(10, n.size() - 14);
            scalar value;
            if (readScalar(t, value))
            {
                entries.append(Tuple2<scalar, word>(value, n));
            }
        }
    }
    Foam::sort(entries);

    OFstream series(dir/"particles.vtk.series");
    series.precision(12);
    series << "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
    forAll(entries, i)
    {
        series
            << "    { \"name\" : \"" << entries[i].second().c_str()
            << "\", \"time\" : " << entries[i].first() << " }"
            << (i + 1 < entries.size() ? ",\n" : "\n");
    }
    series << "  ]\n}\n";
}


// ************************************************************************* //
