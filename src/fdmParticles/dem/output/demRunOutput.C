/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demRunOutput.H"
#include "demState.H"
#include "checkTimeControls.H"
#include "Time.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::demRunOutput::demRunOutput
(
    const Time& runTime,
    const lubricatedDEM& dem,
    const dictionary& properties
)
:
    interval_(demSeries::readInterval(properties.subOrEmptyDict("output"))),
    tracks_(runTime, dem, properties.subOrEmptyDict("output")),
    series_(runTime, dem),
    particleSeries_(runTime, properties),
    vtk_(runTime, properties.subOrEmptyDict("output")),
    monitor_(runTime.value(), runTime.elapsedCpuTime()),
    clock_(),
    steps_(0),
    sMax_(0),
    lastReport_(-GREAT)
{
    vtk_.write(dem, runTime, 0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::demRunOutput::afterStep
(
    const lubricatedDEM& dem,
    const Time& runTime
)
{
    ++steps_;
    sMax_ = max(sMax_, dem.stabilityNumber());
    monitor_.check(dem, runTime);

    if (steps_ % interval_ == 0)
    {
        series_.append(dem);
        particleSeries_.append(dem);
        tracks_.append(dem);
    }
    const bool last = lastStepOfRun(runTime);
    if (clock_.elapsedTime() >= lastReport_ + 10 || last)
    {
        lastReport_ = clock_.elapsedTime();
        monitor_.report(dem, runTime, clock_, sMax_);
        sMax_ = 0;
    }

    vtk_.write(dem, runTime, steps_);
    if (runTime.writeTime() || last)
    {
        writeDEMState(dem, runTime);
        particleSeries_.commit();
    }
}


void Foam::fdm::demRunOutput::end(const lubricatedDEM& dem) const
{
    Info<< nl << "End: " << steps_ << " steps, "
        << clock_.elapsedTime() << " s, "
        << steps_*dem.size()/max(clock_.elapsedTime(), SMALL)
        << " particle-steps/s" << nl << endl;
}


// ************************************************************************* //
