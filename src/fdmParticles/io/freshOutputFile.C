/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "freshOutputFile.H"
#include "OSspecific.H"
#include "Ostream.H"
#include "messageStream.H"

Foam::fileName Foam::fdm::freshOutputFile
(
    const fileName& dir,
    const word& name,
    const word& ext
)
{
    const fileName first = dir/(name + '.' + ext);
    fileName path = first;
    for (label i = 1; exists(path, false); ++i)
    {
        path = dir/(name + '_' + Foam::name(i) + '.' + ext);
    }
    if (path != first)
    {
        Info<< first << " exists (an earlier run from this time):"
            << " left as it is, writing " << path.name() << endl;
    }
    return path;
}


// ************************************************************************* //
