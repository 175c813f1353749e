/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "leesEdwardsProcessorCyclicFvPatchField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"

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
