/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "readableDictionaries.H"
#include "fpTrapsOff.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "dictionary.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Read the FoamFile header, if any, and take its format: the data of a
//  field written in binary follow in binary (as IOobject::readHeader)
void readHeaderFormat(Foam::Istream& is)
{
    Foam::token first(is);
    if (first.isWord() && first.wordToken() == "FoamFile")
    {
        const Foam::dictionary header(is);
        is.format(header.getOrDefault<Foam::word>("format", "ascii"));
    }
    else
    {
        is.putBack(first);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::fdm::dictionariesReadAtStart()
{
    static const wordList files
    ({
        "system/controlDict", "system/fvSchemes", "system/fvSolution",
        "system/decomposeParDict", "constant/transportProperties",
        "constant/flowProperties"
    });
    return files;
}


void Foam::fdm::checkDictionariesReadable
(
    const fileName& dir,
    const wordList& files
)
{
    fpTrapsOff trapsOff;
    for (const word& rel : files)
    {
        const fileName file = dir/rel;
        if (!isFile(file))
        {
            continue;
        }
        IFstream is(file);
        const bool throwing = FatalIOError.throwing();
        FatalIOError.throwExceptions();
        try
        {
            readHeaderFormat(is);
            const dictionary dict(is);
        }
        catch (const IOerror& e)
        {
            FatalIOError.throwExceptions(throwing);
            trapsOff.restore();
            FatalIOErrorInFunction(is)
                << "Cannot read " << file << ": " << e.message().c_str()
                << nl << "    Allowed: OpenFOAM dictionary syntax with finite"
                << " numbers (magnitude below about 1.8e308); check the"
                << " entry named above" << exit(FatalIOError);
        }
        FatalIOError.throwExceptions(throwing);
    }
}


// ************************************************************************* //
