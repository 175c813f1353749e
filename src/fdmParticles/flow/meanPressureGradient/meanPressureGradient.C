/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "meanPressureGradient.H"
#include "checkKeywords.H"

Foam::meanPressureGradient::meanPressureGradient(const fvMesh& mesh)
:
    dict_
    (
        IOobject
        (
            "flowProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    value_("meanPressureGradient", dimAcceleration, dict_)
{
    fdm::checkKeywords(dict_, {"meanPressureGradient"});
    Info<< "Imposed mean pressure gradient (kinematic) "
        << value_.value() << nl << endl;
}


// ************************************************************************* //
