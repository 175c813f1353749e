/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "incompleteWrites.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "Time.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

bool nonEmptyFile(const fileName& f)
{
    return isFile(f) && fileSize(f) > 0;
}

//- Rename dir/time to dir/time.incomplete (or .incomplete1, ...)
void setAside(const fileName& dir)
{
    if (!isDir(dir))
    {
        return;
    }
    fileName aside = dir + ".incomplete";
    for (label i = 1; exists(aside); ++i)
    {
        aside = dir + ".incomplete" + Foam::name(i);
    }
    mv(dir, aside);
}

} // namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::fdm::setAsideIncompleteWrites
(
    const argList& args,
    const wordList& fields
)
{
    const fileName globalCase = args.rootPath()/args.globalCaseName();
    const fileName controlDict = globalCase/"system"/"controlDict";
    if (!isFile(controlDict))
    {
        return;
    }
    IFstream is(controlDict);
    const dictionary control(is);
    if (control.getOrDefault<word>("startFrom", "startTime") != "latestTime")
    {
        return;
    }
    const bool particles =
        isFile(globalCase/"constant"/"particleProperties");

    while (true)
    {
        // Every rank looks at the same, globally newest time
        const instantList times = Time::findTimes(args.path(), "constant");
        const scalar mine = times.empty() ? -GREAT : times.last().value();
        scalar newest = mine;
        reduce(newest, maxOp<scalar>());
        if (newest <= 0)
        {
            return;
        }
        const bool hasIt = mag(newest - mine) <= SMALL*max(1, mag(newest));
        const word t = hasIt ? times.last().name() : word::null;

        bool whole = hasIt;
        for (const word& field : fields)
        {
            whole = whole && nonEmptyFile(args.path()/t/field);
        }
        if (particles && Pstream::master())
        {
            whole = whole && isFile(globalCase/t/"particleState");
        }
        reduce(whole, andOp<bool>());
        if (whole)
        {
            return;
        }

        Info<< "Time " << newest << " was not completely written (the run"
            << " writing it was stopped): set aside as <time>.incomplete;"
            << " starting from the time before it" << nl << endl;
        if (hasIt)
        {
            setAside(args.path()/t);
        }
        if (hasIt && Pstream::master() && globalCase != args.path())
        {
            setAside(globalCase/t);
        }
        // All ranks have renamed before any looks again
        reduce(whole, andOp<bool>());
    }
}


// ************************************************************************* //
