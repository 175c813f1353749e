/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "leesEdwardsFvPatchField.H"
#include "boundBox.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
template<class Type2>
Foam::tmp<Foam::Field<Type2>>
Foam::leesEdwardsFvPatchField<Type>::shifted(const Field<Type2>& psi) const
{
    const labelUList& nbrCells =
        this->cyclicPatch().neighbFvPatch().faceCells();
    return side_.map
    (
        this->patch(), this->cyclicPatch().neighbFvPatch().Cf(),
        this->internalField().name()
    ).template interpolate<Type2>(UIndirectList<Type2>(psi, nbrCells));
}


template<class Type>
template<class Type2>
void Foam::leesEdwardsFvPatchField<Type>::addShifted
(
    Field<Type2>& result,
    const bool add,
    const scalarField& coeffs,
    const Field<Type2>& psi
) const
{
    const Field<Type2> pnf(shifted(psi));
    #if OPENFOAM >= 2106
    this->addToInternalField
    (
        result, !add, this->patch().faceCells(), coeffs, pnf
    );
    #else
    this->addToInternalField(result, !add, coeffs, pnf);
    #endif
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class Type>
Foam::leesEdwardsFvPatchField<Type>::leesEdwardsFvPatchField
(
    const fvPatch& p,
    const DimensionedField<Type, volMesh>& iF
)
:
    cyclicFvPatchField<Type>(p, iF),
    side_(0, true)
{}


template<class Type>
Foam::leesEdwardsFvPatchField<Type>::leesEdwardsFvPatchField
(
    const fvPatch& p,
    const DimensionedField<Type, volMesh>& iF,
    const scalar shearRate,
    const bool jumps
)
:
    cyclicFvPatchField<Type>(p, iF),
    side_(shearRate, jumps)
{
    this->evaluate(Pstream::commsTypes::blocking);
}


template<class Type>
Foam::leesEdwardsFvPatchField<Type>::leesEdwardsFvPatchField
(
    const fvPatch& p,
    const DimensionedField<Type, volMesh>& iF,
    const dictionary& dict
)
:
    cyclicFvPatchField<Type>(p, iF, dict),
    side_(dict.get<scalar>("shearRate"), true)
{
    // The cyclic constructor evaluated the unsheared coupling
    this->evaluate(Pstream::commsTypes::blocking);
}


template<class Type>
Foam::leesEdwardsFvPatchField<Type>::leesEdwardsFvPatchField
(
    const leesEdwardsFvPatchField<Type>& ptf,
    const fvPatch& p,
    const DimensionedField<Type, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    cyclicFvPatchField<Type>(ptf, p, iF, mapper),
    side_(ptf.side_)
{}


template<class Type>
Foam::leesEdwardsFvPatchField<Type>::leesEdwardsFvPatchField
(
    const leesEdwardsFvPatchField<Type>& ptf
)
:
    cyclicLduInterfaceField(),
    cyclicFvPatchField<Type>(ptf),
    side_(ptf.side_)
{}


template<class Type>
Foam::leesEdwardsFvPatchField<Type>::leesEdwardsFvPatchField
(
    const leesEdwardsFvPatchField<Type>& ptf,
    const DimensionedField<Type, volMesh>& iF
)
:
    cyclicFvPatchField<Type>(ptf, iF),
    side_(ptf.side_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::scalar Foam::leesEdwardsFvPatchField<Type>::offset() const
{
    return side_.offset(this->patch());
}


template<class Type>
Foam::tmp<Foam::Field<Type>>
Foam::leesEdwardsFvPatchField<Type>::patchNeighbourField() const
{
    return
        shifted(this->primitiveField())
      + side_.template jump<Type>(this->patch());
}


#if OPENFOAM >= 2106

template<class Type>
void Foam::leesEdwardsFvPatchField<Type>::updateInterfaceMatrix
(
    solveScalarField& result,
    const bool add,
    const lduAddressing&,
    const label,
    const solveScalarField& psiInternal,
    const scalarField& coeffs,
    const direction,
    const Pstream::commsTypes
) const
{
    addShifted(result, add, coeffs, psiInternal);
}


template<class Type>
void Foam::leesEdwardsFvPatchField<Type>::updateInterfaceMatrix
(
    Field<Type>& result,
    const bool add,
    const lduAddressing&,
    const label,
    const Field<Type>& psiInternal,
    const scalarField& coeffs,
    const Pstream::commsTypes
) const
{
    addShifted(result, add, coeffs, psiInternal);
}

#else

template<class Type>
void Foam::leesEdwardsFvPatchField<Type>::updateInterfaceMatrix
(
    solveScalarField& result,
    const bool add,
    const solveScalarField& psiInternal,
    const scalarField& coeffs,
    const direction,
    const Pstream::commsTypes
) const
{
    addShifted(result, add, coeffs, psiInternal);
}


template<class Type>
void Foam::leesEdwardsFvPatchField<Type>::updateInterfaceMatrix
(
    Field<Type>& result,
    const bool add,
    const Field<Type>& psiInternal,
    const scalarField& coeffs,
    const Pstream::commsTypes
) const
{
    addShifted(result, add, coeffs, psiInternal);
}

#endif


template<class Type>
void Foam::leesEdwardsFvPatchField<Type>::write(Ostream& os) const
{
    fvPatchField<Type>::write(os);
    os.writeEntry("shearRate", side_.shearRate());
}


// ************************************************************************* //
