/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "leesEdwardsProcessorCyclicFvPatchField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * * Specialisations  * * * * * * * * * * * * * //

template<>
Foam::vector Foam::leesEdwardsProcessorCyclicFvPatchField<Foam::vector>::jump()
const
{
    if (!jumps_)
    {
        return Zero;
    }
    // As leesEdwardsFvPatchField: seen from the upper side the image one
    // period up is faster by gammaDot L_y, from the lower side slower
    const scalar du =
        shearRate_*patch().boundaryMesh().mesh().bounds().span().y();
    return vector(upperSide() ? du : -du, 0, 0);
}


namespace Foam
{
    typedef leesEdwardsProcessorCyclicFvPatchField<scalar>
        leesEdwardsProcessorCyclicFvPatchScalarField;
    typedef leesEdwardsProcessorCyclicFvPatchField<vector>
        leesEdwardsProcessorCyclicFvPatchVectorField;
    typedef leesEdwardsProcessorCyclicFvPatchField<tensor>
        leesEdwardsProcessorCyclicFvPatchTensorField;

    makeTemplatePatchTypeField(scalar, leesEdwardsProcessorCyclic);
    makeTemplatePatchTypeField(vector, leesEdwardsProcessorCyclic);
    makeTemplatePatchTypeField(tensor, leesEdwardsProcessorCyclic);
}


// ************************************************************************* //
