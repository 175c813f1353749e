/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "contactModel.H"
#include "particleContacts.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::contactModel> Foam::contactModel::New
(
    const dictionary& particleProperties,
    const fvMesh& mesh,
    const scalarField& radii,
    const scalar eta,
    const scalar gapFloor
)
{
    if (!particleProperties.found("contact"))
    {
        return autoPtr<contactModel>(new noContacts(radii.size()));
    }
    return autoPtr<contactModel>
    (
        new particleContacts
        (
            particleProperties.subDict("contact"),
            mesh,
            fdm::contactLaw::scales{radii.empty() ? 1 : min(radii), eta},
            gapFloor,
            radii.size()
        )
    );
}


// ************************************************************************* //
