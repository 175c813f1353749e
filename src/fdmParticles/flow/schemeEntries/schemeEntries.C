/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "schemeEntries.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::fdm::isGaussLinear(ITstream& scheme)
{
    const bool linear =
        scheme.size() == 2
     && scheme[0].isWord() && scheme[0].wordToken() == "Gauss"
     && scheme[1].isWord() && scheme[1].wordToken() == "linear";
    scheme.rewind();
    return linear;
}


bool Foam::fdm::isUncorrectedLaplacian(ITstream& scheme)
{
    const bool uncorrected =
        scheme.size() >= 2
     && scheme.last().isWord()
     && (
            scheme.last().wordToken() == "uncorrected"
         || scheme.last().wordToken() == "orthogonal"
        );
    scheme.rewind();
    return uncorrected;
}


bool Foam::fdm::boundaryCoeffsFromValuesOnly(const volVectorField& U)
{
    for (const fvPatchVectorField& pU : U.boundaryField())
    {
        if
        (
            !pU.coupled()
         && pU.type() != "fixedValue"
         && pU.type() != "noSlip"
         && pU.type() != "empty"
        )
        {
            return false;
        }
    }
    return true;
}


// ************************************************************************* //
