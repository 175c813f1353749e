/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "leesEdwardsShear.H"
#include "leesEdwardsFvPatchField.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- U's leesEdwards patch field on this rank, or nullptr
const Foam::leesEdwardsFvPatchField<Foam::vector>* shearedPatch
(
    const Foam::volVectorField& U
)
{
    for (const Foam::fvPatchVectorField& pf : U.boundaryField())
    {
        if (Foam::isA<Foam::leesEdwardsFvPatchField<Foam::vector>>(pf))
        {
            return &Foam::refCast
                <const Foam::leesEdwardsFvPatchField<Foam::vector>>(pf);
        }
    }
    return nullptr;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::fdm::setLeesEdwardsShear(const fvMesh& mesh, periodicBox& box)
{
    // (shear rate, offset) of the patch on the ranks that hold it
    scalar rate = -GREAT, offset = -GREAT;
    if (mesh.foundObject<volVectorField>("U"))
    {
        const auto* le =
            shearedPatch(mesh.lookupObject<volVectorField>("U"));
        if (le)
        {
            rate = le->shearRate();
            offset = le->offset();
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


Foam::scalar Foam::fdm::leesEdwardsShearRate(const fvMesh& mesh)
{
    const auto rateOf = [](const volVectorField& U)
    {
        const auto* le = shearedPatch(U);
        return le ? le->shearRate() : 0;
    };
    scalar rate = 0;
    if (mesh.foundObject<volVectorField>("U"))
    {
        rate = rateOf(mesh.lookupObject<volVectorField>("U"));
    }
    else
    {
        IOobject io
        (
            "U",
            mesh.time().findInstance
            (
                mesh.dbDir(), "U", IOobject::READ_IF_PRESENT
            ),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (io.typeHeaderOk<volVectorField>(true))
        {
            rate = rateOf(volVectorField(io, mesh));
        }
    }
    return returnReduce(rate, maxOp<scalar>());
}


// ************************************************************************* //
