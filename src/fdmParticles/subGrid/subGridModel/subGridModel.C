/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "subGridModel.H"
#include "checkKeywords.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(subGridModel, 0);
    defineRunTimeSelectionTable(subGridModel, dictionary);

    defineTypeNameAndDebug(noSubGrid, 0);
    addToRunTimeSelectionTable(subGridModel, noSubGrid, dictionary);
}


Foam::subGridModel::subGridModel(const fvMesh& mesh)
:
    mesh_(mesh)
{}


Foam::noSubGrid::noSubGrid
(
    const dictionary& dict,
    const fvMesh& mesh,
    const settings&,
    const scalarField&
)
:
    noPairInteraction<subGridModel>(mesh)
{
    fdm::checkKeywords(dict, {"model"}, "subGrid block, model none");
}


Foam::autoPtr<Foam::subGridModel> Foam::subGridModel::New
(
    const dictionary& particleProperties,
    const fvMesh& mesh,
    const settings& s,
    const scalarField& radii
)
{
    const dictionary dict(particleProperties.subOrEmptyDict("subGrid"));
    const word model(dict.getOrDefault<word>("model", "none"));

    fdm::checkChoice
    (
        particleProperties, "subGrid model", model,
        dictionaryConstructorTablePtr_->sortedToc()
    );
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(model);
    return cstrIter()(dict, mesh, s, radii);
}


// ************************************************************************* //
