/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demState.H"
#include "particleStateFile.H"
#include "Time.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::fdm::readDEMState(lubricatedDEM& dem, const Time& runTime)
{
    const fileName state = runTime.timePath()/"particleState";
    if (isFile(state))
    {
        Info<< "Continuing from " << state << nl;
        dem.readState(readParticleStateFile(state));
    }
    else if (runTime.value() != 0)
    {
        // Without it the spheres would restart from the list's positions
        FatalErrorInFunction
            << "Starting at time " << runTime.timeName() << " but " << state
            << " is missing." << nl << "    Copy it there from the run that"
            << " wrote this time, or start at time 0 from the particles that"
            << " the particle list holds" << exit(FatalError);
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
