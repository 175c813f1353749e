/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "hertzContact.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace fdm
{
    defineTypeNameAndDebug(hertzContact, 0);
    addToRunTimeSelectionTable(contactLaw, hertzContact, dictionary);

    defineTypeNameAndDebug(adhesiveHertzContact, 0);
    addToRunTimeSelectionTable(contactLaw, adhesiveHertzContact, dictionary);
}
}


Foam::fdm::adhesiveHertzContact::adhesiveHertzContact
(
    const dictionary& dict,
    const scales& s
)
:
    contactLaw(dict, s, {"adhesionForce", "adhesionNumber"}),
    adhesion_(0)
{
    const bool direct = dict.found("adhesionForce");
    const bool number = dict.found("adhesionNumber");
    if (direct == number)
    {
        FatalIOErrorInFunction(dict)
            << "Give the adhesion in " << dict.name() << " either as"
            << " adhesionForce [N] or as adhesionNumber G_adh = F_adh/(6 pi"
            << " eta a_1^2 shearRate), not " << (direct ? "both" : "neither")
            << exit(FatalIOError);
    }
    if (direct)
    {
        adhesion_ =
            readBounded(dict, "adhesionForce", 0, GREAT, "F_adh >= 0");
    }
    else
    {
        if (shearRate_ <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "adhesionNumber in " << dict.name() << " needs the"
                << " reference shearRate (give the stiffness as shearRate"
                << " and meanDeformation)" << exit(FatalIOError);
        }
        adhesion_ =
            readBounded(dict, "adhesionNumber", 0, GREAT, "G_adh >= 0")
           *6*constant::mathematical::pi*s.eta*sqr(s.a1)*shearRate_;
    }
}


// ************************************************************************* //
