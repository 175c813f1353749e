/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "leesEdwardsShear.H"
#include "leesEdwardsFvPatchField.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::fdm::setLeesEdwardsShear(const fvMesh& mesh, periodicBox& box)
{
    // (shear rate, offset) of the patch on the ranks that hold it
    scalar rate = -GREAT, offset = -GREAT;
    if (mesh.foundObject<volVectorField>("U"))
    {
        const volVectorField& U = mesh.lookupObject<volVectorField>("U");
        for (const fvPatchVectorField& pf : U.boundaryField())
        {
            if (isA<leesEdwardsFvPatchField<vector>>(pf))
            {
                const auto& le =
                    refCast<const leesEdwardsFvPatchField<vector>>(pf);
                rate = le.shearRate();
                offset = le.offset();
            }
        }
    }
    reduce(rate, maxOp<scalar>());
    reduce(offset, maxOp<scalar>());
    if (rate == -GREAT)
    {
        return false;
    }
    box.setShearVelocity(rate*box.span().y());
    box.setShearOffset(offset);
    return true;
}


// ************************************************************************* //
