/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "checkTimeControls.H"
#include <cmath>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::fdm::checkTimeControls(const Time& runTime)
{
    const dictionary& dict = runTime.controlDict();
    const scalar deltaT = dict.get<scalar>("deltaT");
    if (!(deltaT > 0 && std::isfinite(deltaT)))
    {
        FatalIOErrorInFunction(dict)
            << "deltaT " << deltaT << " in " << dict.name()
            << ": allowed values are finite numbers > 0" << exit(FatalIOError);
    }
    const scalar endTime = dict.get<scalar>("endTime");
    if (!(endTime >= runTime.startTime().value() && std::isfinite(endTime)))
    {
        FatalIOErrorInFunction(dict)
            << "endTime " << endTime << " in " << dict.name() << " is before"
            << " the start time " << runTime.startTime().value()
            << ": allowed values are >= the start time" << exit(FatalIOError);
    }
}


bool Foam::fdm::lastStepOfRun(const Time& runTime)
{
    return
        runTime.value()
     >= runTime.endTime().value() - 0.5*runTime.deltaTValue();
}


// ************************************************************************* //
