/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The leesEdwards patch fields of scalars (the pressure, continuous
    across the sheared faces), vectors (the velocity, which jumps by
    gammaDot L_y along x) and tensors (the velocity gradient, continuous).

\*---------------------------------------------------------------------------*/

#include "leesEdwardsFvPatchField.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    typedef leesEdwardsFvPatchField<scalar> leesEdwardsFvPatchScalarField;
    typedef leesEdwardsFvPatchField<vector> leesEdwardsFvPatchVectorField;
    typedef leesEdwardsFvPatchField<tensor> leesEdwardsFvPatchTensorField;

    makeTemplatePatchTypeField(scalar, leesEdwards);
    makeTemplatePatchTypeField(vector, leesEdwards);
    makeTemplatePatchTypeField(tensor, leesEdwards);
}


// ************************************************************************* //
