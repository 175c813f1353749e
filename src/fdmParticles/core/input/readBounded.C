/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "readBounded.H"
#include "OStringStream.H"
#include "vector.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fdm::readBounded
(
    const dictionary& dict,
    const word& key,
    const scalar lo,
    const scalar hi,
    const string& meaning
)
{
    if (!dict.found(key))
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword " << key << " in " << dict.name() << ": "
            << meaning << exit(FatalIOError);
    }
    const scalar x = dict.get<scalar>(key);
    if (!(x >= lo && x < hi))
    {
        // lo = VSMALL stands for "> 0", hi = GREAT for no upper bound
        OStringStream range;
        range << (lo == VSMALL ? "0 < " : "") << key;
        if (lo != VSMALL)
        {
            range << " >= " << lo;
        }
        if (hi != GREAT)
        {
            range << " < " << hi;
        }
        FatalIOErrorInFunction(dict)
            << key << ' ' << x << " in " << dict.name()
            << ": allowed values are " << range.str().c_str()
            << " (" << meaning << ")" << exit(FatalIOError);
    }
    return x;
}


Foam::scalar Foam::fdm::readBoundedOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const scalar lo,
    const scalar hi,
    const string& meaning
)
{
    return dict.found(key) ? readBounded(dict, key, lo, hi, meaning) : deflt;
}


Foam::label Foam::fdm::axisIndex(const word& name)
{
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (name == vector::componentNames[d])
        {
            return d;
        }
    }
    return -1;
}


// ************************************************************************* //
