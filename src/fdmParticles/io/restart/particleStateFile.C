/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleStateFile.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOobject.H"
#include "fpTrapsOff.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::fdm::writeParticleStateFile
(
    const fileName& dir,
    const word& timeName,
    const objectRegistry& db,
    const std::function<void(Ostream&)>& writeEntries
)
{
    mkDir(dir);
    const fileName tmp = dir/"particleState.tmp";
    {
        OFstream os(tmp);
        os.precision(17);
        IOobject io
        (
            "particleState",
            timeName,
            db,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        );
        io.writeHeader(os, "dictionary");
        writeEntries(os);
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


Foam::dictionary Foam::fdm::readParticleStateFile(const fileName& file)
{
    fpTrapsOff trapsOff;
    IFstream is(file);
    return dictionary(is);
}


bool Foam::fdm::continuesFromParticleState
(
    const Time& runTime,
    const fileName& file,
    const string& listName
)
{
    if (isFile(file))
    {
        return true;
    }
    if (runTime.value() != 0)
    {
        FatalErrorInFunction
            << "Starting at time " << runTime.timeName() << " but " << file
            << " is missing." << nl
            << "    The particle state of a restart is read from the case"
            << " directory (also in parallel runs): copy it there from the"
            << " run that wrote this time, or start at time 0 from the"
            << " particles of " << listName << exit(FatalError);
    }
    return false;
}


// ************************************************************************* //
