/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "secondOrderWallVelocityFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::secondOrderWallVelocityFvPatchVectorField::buildStencil() const
{
    if (secondCell_.size() == size())
    {
        return;
    }

    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const labelUList& faceCells = patch().faceCells();
    const vectorField nf(patch().nf());
    const vectorField& Cf = patch().Cf();
    const volVectorField& C = mesh.C();

    secondCell_.setSize(size(), -1);
    a_.setSize(size());
    b_.setSize(size());

    label nFallback = 0;
    forAll(faceCells, i)
    {
        const label c1 = faceCells[i];
        const scalar s1 = mag(nf[i] & (C[c1] - Cf[i]));

        const label opposite = mesh.cells()[c1].opposingFaceLabel
        (
            patch().start() + i,
            mesh.faces()
        );

        label c2 = -1;
        if (opposite >= 0 && mesh.isInternalFace(opposite))
        {
            const label own = mesh.faceOwner()[opposite];
            c2 = (own == c1 ? mesh.faceNeighbour()[opposite] : own);
        }

        if (c2 < 0)
        {
            // Two-point gradient (u_1 - u_w)/s1
            a_[i] = 1/s1;
            b_[i] = 0;
            ++nFallback;
            continue;
        }

        const scalar s2 = mag(nf[i] & (C[c2] - Cf[i]));
        secondCell_[i] = c2;
        a_[i] = s2/(s1*(s2 - s1));
        b_[i] = s1/(s2*(s2 - s1));
    }

    if (nFallback)
    {
        WarningInFunction
            << "Patch " << patch().name() << " of field "
            << internalField().name() << ": " << nFallback
            << " faces without an internal second cell along the normal"
            << " use the first-order two-point gradient" << endl;
    }
}


Foam::tmp<Foam::vectorField>
Foam::secondOrderWallVelocityFvPatchVectorField::secondCellValues() const
{
    buildStencil();
    const vectorField& iF = primitiveField();
    tmp<vectorField> tu2(new vectorField(size(), Zero));
    vectorField& u2 = tu2.ref();
    forAll(u2, i)
    {
        if (secondCell_[i] >= 0)
        {
            u2[i] = iF[secondCell_[i]];
        }
    }
    return tu2;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::secondOrderWallVelocityFvPatchVectorField::
secondOrderWallVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(p, iF)
{}


Foam::secondOrderWallVelocityFvPatchVectorField::
secondOrderWallVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    fixedValueFvPatchVectorField(p, iF, dict)
{}


Foam::secondOrderWallVelocityFvPatchVectorField::
secondOrderWallVelocityFvPatchVectorField
(
    const secondOrderWallVelocityFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchVectorField(ptf, p, iF, mapper)
{}


Foam::secondOrderWallVelocityFvPatchVectorField::
secondOrderWallVelocityFvPatchVectorField
(
    const secondOrderWallVelocityFvPatchVectorField& ptf
)
:
    fixedValueFvPatchVectorField(ptf)
{}


Foam::secondOrderWallVelocityFvPatchVectorField::
secondOrderWallVelocityFvPatchVectorField
(
    const secondOrderWallVelocityFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(ptf, iF)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::vectorField>
Foam::secondOrderWallVelocityFvPatchVectorField::snGrad() const
{
    // -du/ds (outward normal) = -a (u_1 - u_w) + b (u_2 - u_w);
    // b = 0 where there is no second cell (two-point gradient)
    buildStencil();
    const vectorField& uw = *this;
    return -a_*(patchInternalField() - uw) + b_*(secondCellValues() - uw);
}


Foam::tmp<Foam::vectorField>
Foam::secondOrderWallVelocityFvPatchVectorField::gradientInternalCoeffs()
const
{
    buildStencil();
    return -pTraits<vector>::one*a_;
}


Foam::tmp<Foam::vectorField>
Foam::secondOrderWallVelocityFvPatchVectorField::gradientBoundaryCoeffs()
const
{
    // snGrad = -a u_1 + [(a - b) u_w + b u_2]; b = 0 where no second cell
    buildStencil();
    const vectorField& uw = *this;
    const vectorField u2(secondCellValues());
    return (a_ - b_)*uw + b_*u2;
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        secondOrderWallVelocityFvPatchVectorField
    );
}

// ************************************************************************* //
