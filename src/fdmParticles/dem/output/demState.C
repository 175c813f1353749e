/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demState.H"
#include "Time.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "fpTrapsOff.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::fdm::readDEMState(lubricatedDEM& dem, const Time& runTime)
{
    const fileName state = runTime.timePath()/"particleState";
    if (isFile(state))
    {
        Info<< "Continuing from " << state << nl;
        fdm::fpTrapsOff trapsOff;
        IFstream is(state);
        const dictionary dict(is);
        trapsOff.restore();
        dem.readState(dict);
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
    mkDir(runTime.timePath());
    const fileName file = runTime.timePath()/"particleState";
    {
        OFstream os(file + ".tmp");
        os.precision(17);
        IOobject io
        (
            "particleState",
            runTime.timeName(),
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        );
        io.writeHeader(os, "dictionary");
        dem.writeState(os);
    }
    mv(file + ".tmp", file);
}


// ************************************************************************* //
