/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleCloudOutput.H"
#include "lagrangianCloudWriter.H"
#include "particleVTKWriter.H"
#include "checkKeywords.H"
#include "checkTimeControls.H"
#include <cctype>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- Force, torque and stresslet as the fields force, torque, stresslet, or
//  with a prefix <prefix>Force, <prefix>Torque, <prefix>Stresslet, of the
//  lagrangian cloud or a VTK file
template<class Writer>
void writeLoads
(
    Writer& w,
    const std::string& prefix,
    const Foam::fdm::particleLoads& loads
)
{
    const auto name = [&](const std::string& n)
    {
        if (prefix.empty())
        {
            return Foam::word(n);
        }
        return Foam::word(prefix + char(std::toupper(n[0])) + n.substr(1));
    };
    w.write(name("force"), loads.force);
    w.write(name("torque"), loads.torque);
    w.write(name("stresslet"), loads.stresslet);
}

} // namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleCloudOutput::particleCloudOutput
(
    const fvMesh& mesh,
    const dictionary& output,
    const dictionary& dict
)
:
    mesh_(mesh),
    timeSeriesInterval_(1),
    vtkInterval_(0),
    vtkStarted_(false)
{
    fdm::checkKeywords
    (
        output, {"timeSeriesInterval", "vtkInterval"}, "output block"
    );
    vtkInterval_ = fdm::particleVTKWriter::readInterval(output);
    timeSeriesInterval_ = output.getOrDefault<label>("timeSeriesInterval", 1);
    if (timeSeriesInterval_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "output.timeSeriesInterval " << timeSeriesInterval_ << " in "
            << dict.name() << ": allowed values are integers >= 1"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::particleCloudOutput::~particleCloudOutput()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::particleCloudOutput::timeSeriesDue() const
{
    return mesh_.time().timeIndex() % timeSeriesInterval_ == 0;
}


bool Foam::particleCloudOutput::recordDue() const
{
    // The same on every rank
    const Time& runTime = mesh_.time();
    return
        timeSeriesDue()
     || runTime.writeTime()
     || fdm::lastStepOfRun(runTime)
     || fdm::particleVTKWriter::due
        (
            vtkInterval_, runTime.timeIndex(), runTime.writeTime()
        );
}


void Foam::particleCloudOutput::writeTimeSeries
(
    const particles& p,
    const std::function<particleHDF5Metadata::description()>& description
)
{
    const Time& runTime = mesh_.time();
    if (timeSeriesDue())
    {
        if (!timeSeries_)
        {
            // Created at the first record, so that -postProcess, which
            // constructs the cloud but records nothing, leaves it alone
            timeSeries_.reset
            (
                new particleHDF5Writer
                (
                    runTime.globalPath()/"postProcessing"/"particles.h5",
                    p.state.radius,
                    p.state.group,
                    runTime.value(),
                    description()
                )
            );
        }
        timeSeries_->append
        (
            runTime.value(),
            {
                p.state.position, p.state.U, p.state.Omega,
                p.hydro.force, p.hydro.torque, p.hydro.stresslet,
                p.dipoleTrace,
                p.contact.force, p.contact.torque, p.contact.stresslet
            }
        );
    }
    if (timeSeries_ && runTime.writeTime())
    {
        // Publish the records up to this write time
        timeSeries_->commit();
    }
}


void Foam::particleCloudOutput::writeLagrangian(const particles& p) const
{
    const fdm::particleState& s = p.state;
    const lagrangianCloudWriter cloud
    (
        mesh_, "particles", s.position, p.current
    );
    cloud.write("id", labelList(identity(s.size())));
    cloud.write("group", s.group);
    cloud.write("d", scalarField(2*s.radius));
    cloud.write("U", s.U);
    cloud.write("omega", s.Omega);
    writeLoads(cloud, "", p.hydro);
    writeLoads(cloud, "contact", p.contact);
}


bool Foam::particleCloudOutput::vtkDue() const
{
    const Time& runTime = mesh_.time();
    return
        !vtkStarted_
     || fdm::particleVTKWriter::due
        (
            vtkInterval_, runTime.timeIndex(), runTime.writeTime()
        );
}


void Foam::particleCloudOutput::writeVTK
(
    const particles& p,
    const fdm::contactNetwork& contacts
)
{
    vtkStarted_ = true;
    if (!Pstream::master())
    {
        return;
    }
    const Time& runTime = mesh_.time();
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

    const fdm::particleState& s = p.state;
    auto file =
        vtk_->particles(runTime.timeName(), runTime.value(), s.position);
    file.write("id", labelList(identity(s.size())));
    file.write("group", s.group);
    file.write("radius", s.radius);
    file.write("velocity", s.U);
    file.write("angularVelocity", s.Omega);
    writeLoads(file, "", p.hydro);
    file.write("dipoleTrace", p.dipoleTrace);
    writeLoads(file, "contact", p.contact);
    file.close();

    vtk_->contacts(runTime.timeName(), runTime.value(), s.position, contacts);
}


// ************************************************************************* //
