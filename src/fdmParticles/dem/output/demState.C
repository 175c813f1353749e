/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demState.H"
#include "particleStateFile.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::fdm::readDEMState(lubricatedDEM& dem, const Time& runTime)
{
    const fileName state = runTime.timePath()/"particleState";
    if (continuesFromParticleState(runTime, state, "the particle list"))
    {
        Info<< "Continuing from " << state << nl;
        dem.readState(readParticleStateFile(state));
    }
}


void Foam::fdm::writeDEMState
(
    const lubricatedDEM& dem,
    const Time& runTime
)
{
    writeParticleStateFile
    (
        runTime.timePath(),
        runTime.timeName(),
        runTime,
        [&](Ostream& os) { dem.writeState(os); }
    );
}


// ************************************************************************* //
