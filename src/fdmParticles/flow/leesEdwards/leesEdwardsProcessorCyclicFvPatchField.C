/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "leesEdwardsProcessorCyclicFvPatchField.H"
#include "processorCyclicFvPatch.H"

#if OPENFOAM >= 2106
    #define FDM_LDU_ARGS const lduAddressing&, const label,
#else
    #define FDM_LDU_ARGS
#endif

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
const Foam::fdm::leesEdwardsRowMap&
Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::map() const
{
    // The received value of face f is that of the cell opposite it, at the
    // same x and z: this side's faces are the row
    return side_.map
    (
        this->patch(), this->patch().Cf(), this->internalField().name()
    );
}


template<class Type>
template<class Type2>
void Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::sendInternal
(
    const Field<Type2>& psiInternal
) const
{
    // Buffered (MPI_Bsend): the sends of all interfaces go out before any
    // receive, as OpenFOAM's own processor patches do in blocking mode
    refCast<const processorCyclicFvPatch>(this->patch()).send
    (
        Pstream::commsTypes::blocking,
        Field<Type2>(psiInternal, this->patch().faceCells())
    );
    const_cast<leesEdwardsProcessorCyclicFvPatchField<Type>&>(*this)
        .updatedMatrix() = false;
}


template<class Type>
template<class Type2>
void Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::addReceivedShifted
(
    Field<Type2>& result,
    const bool add,
    const scalarField& coeffs
) const
{
    if (this->updatedMatrix())
    {
        return;
    }
    const Field<Type2> received
    (
        refCast<const processorCyclicFvPatch>(this->patch())
       .template receive<Type2>(Pstream::commsTypes::blocking, this->size())
    );
    const Field<Type2> pnf(map().template interpolate<Type2>(received));
    #if OPENFOAM >= 2106
    this->addToInternalField
    (
        result, !add, this->patch().faceCells(), coeffs, pnf
    );
    #else
    this->addToInternalField(result, !add, coeffs, pnf);
    #endif
    const_cast<leesEdwardsProcessorCyclicFvPatchField<Type>&>(*this)
        .updatedMatrix() = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class Type>
Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::
leesEdwardsProcessorCyclicFvPatchField
(
    const fvPatch& p,
    const DimensionedField<Type, volMesh>& iF
)
:
    processorCyclicFvPatchField<Type>(p, iF),
    side_(0, true)
{}


template<class Type>
Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::
leesEdwardsProcessorCyclicFvPatchField
(
    const fvPatch& p,
    const DimensionedField<Type, volMesh>& iF,
    const dictionary& dict
)
:
    processorCyclicFvPatchField<Type>(p, iF, dict),
    side_(dict.get<scalar>("shearRate"), dict.get<bool>("jumps"))
{}


template<class Type>
Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::
leesEdwardsProcessorCyclicFvPatchField
(
    const fvPatch& p,
    const DimensionedField<Type, volMesh>& iF,
    const Field<Type>& values,
    const scalar shearRate,
    const bool jumps
)
:
    processorCyclicFvPatchField<Type>(p, iF, values),
    side_(shearRate, jumps)
{
    // Written with it, so that reading does not take this field type for
    // the patch's own one
    this->patchType() = processorCyclicFvPatch::typeName;
}


template<class Type>
Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::
leesEdwardsProcessorCyclicFvPatchField
(
    const leesEdwardsProcessorCyclicFvPatchField<Type>& ptf,
    const fvPatch& p,
    const DimensionedField<Type, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    processorCyclicFvPatchField<Type>(ptf, p, iF, mapper),
    side_(ptf.side_)
{}


template<class Type>
Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::
leesEdwardsProcessorCyclicFvPatchField
(
    const leesEdwardsProcessorCyclicFvPatchField<Type>& ptf
)
:
    processorCyclicFvPatchField<Type>(ptf),
    side_(ptf.side_)
{}


template<class Type>
Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::
leesEdwardsProcessorCyclicFvPatchField
(
    const leesEdwardsProcessorCyclicFvPatchField<Type>& ptf,
    const DimensionedField<Type, volMesh>& iF
)
:
    processorCyclicFvPatchField<Type>(ptf, iF),
    side_(ptf.side_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::tmp<Foam::Field<Type>>
Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::neighbourValues
(
    const Field<Type>& received,
    const bool withJump
) const
{
    tmp<Field<Type>> tnbr(map().template interpolate<Type>(received));
    if (withJump)
    {
        tnbr.ref() += side_.template jump<Type>(this->patch());
    }
    return tnbr;
}


template<class Type>
void Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::evaluate
(
    const Pstream::commsTypes commsType
)
{
    processorCyclicFvPatchField<Type>::evaluate(commsType);
    if (Pstream::parRun())
    {
        const Field<Type> received(*this);
        Field<Type>::operator=(neighbourValues(received));
    }
}


template<class Type>
void Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::
initInterfaceMatrixUpdate
(
    solveScalarField&, const bool, FDM_LDU_ARGS
    const solveScalarField& psiInternal, const scalarField&,
    const direction, const Pstream::commsTypes
) const
{
    sendInternal(psiInternal);
}


template<class Type>
void Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::updateInterfaceMatrix
(
    solveScalarField& result, const bool add, FDM_LDU_ARGS
    const solveScalarField&, const scalarField& coeffs,
    const direction, const Pstream::commsTypes
) const
{
    addReceivedShifted(result, add, coeffs);
}


template<class Type>
void Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::
initInterfaceMatrixUpdate
(
    Field<Type>&, const bool, FDM_LDU_ARGS
    const Field<Type>& psiInternal, const scalarField&,
    const Pstream::commsTypes
) const
{
    sendInternal(psiInternal);
}


template<class Type>
void Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::updateInterfaceMatrix
(
    Field<Type>& result, const bool add, FDM_LDU_ARGS
    const Field<Type>&, const scalarField& coeffs,
    const Pstream::commsTypes
) const
{
    addReceivedShifted(result, add, coeffs);
}


template<class Type>
void Foam::leesEdwardsProcessorCyclicFvPatchField<Type>::write
(
    Ostream& os
) const
{
    processorCyclicFvPatchField<Type>::write(os);
    os.writeEntry("shearRate", side_.shearRate());
    os.writeEntry("jumps", side_.jumps());
}

#undef FDM_LDU_ARGS

// ************************************************************************* //
