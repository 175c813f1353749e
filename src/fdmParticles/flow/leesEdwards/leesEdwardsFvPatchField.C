/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "leesEdwardsFvPatchField.H"
#include "boundBox.H"
#include "processorCyclicPolyPatch.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
bool Foam::leesEdwardsFvPatchField<Type>::upperSide() const
{
    return this->size() && sum(this->patch().Sf()).y() > 0;
}


template<class Type>
Type Foam::leesEdwardsFvPatchField<Type>::jump() const
{
    return Zero;
}


template<class Type>
void Foam::leesEdwardsFvPatchField<Type>::updateMap() const
{
    const label timeIndex = this->db().time().timeIndex();
    if (mapTimeIndex_ == timeIndex && first_.size() == this->size())
    {
        return;
    }
    mapTimeIndex_ = timeIndex;

    const fvPatch& nbr = this->cyclicPatch().neighbFvPatch();
    const vectorField& nbrCf = nbr.Cf();
    const boundBox& box = this->patch().boundaryMesh().mesh().bounds();
    const scalar Lx = box.span().x();
    const scalar tol = 1e-6*Lx;

    // The neighbour side's faces in rows of equal z, each sorted along x
    labelList order(identity(nbr.size()));
    std::sort
    (
        order.begin(), order.end(),
        [&](const label a, const label b)
        {
            return mag(nbrCf[a].z() - nbrCf[b].z()) > tol
                ? nbrCf[a].z() < nbrCf[b].z()
                : nbrCf[a].x() < nbrCf[b].x();
        }
    );
    DynamicList<label> rowStart;
    forAll(order, i)
    {
        if (!i || mag(nbrCf[order[i]].z() - nbrCf[order[i - 1]].z()) > tol)
        {
            rowStart.append(i);
        }
    }
    rowStart.append(order.size());

    const scalar s = (upperSide() ? -1 : 1)*offset();
    const vectorField& Cf = this->patch().Cf();
    first_.setSize(this->size());
    second_.setSize(this->size());
    weight_.setSize(this->size());
    forAll(Cf, f)
    {
        // The row of this face's z
        label r = 0;
        while
        (
            r + 1 < rowStart.size() - 1
         && nbrCf[order[rowStart[r]]].z() < Cf[f].z() - tol
        )
        {
            ++r;
        }
        const label begin = rowStart[r];
        const label n = rowStart[r + 1] - begin;
        const scalar x0 = nbrCf[order[begin]].x();
        const scalar dx = n > 1 ? nbrCf[order[begin + 1]].x() - x0 : Lx;
        if
        (
            mag(nbrCf[order[begin]].z() - Cf[f].z()) > tol
         || mag(n*dx - Lx) > tol
        )
        {
            FatalErrorInFunction
                << "Patch " << this->patch().name() << " of field "
                << this->internalField().name() << ": the face at "
                << Cf[f] << " has no whole row of " << nbr.name()
                << " faces along x at its z (a Lees-Edwards row must lie"
                << " on one processor, with uniform spacing: decompose"
                << " along z only)" << exit(FatalError);
        }
        // Position along the row in spacings from its first face, periodic
        scalar p = (Cf[f].x() + s - x0)/dx;
        p -= n*std::floor(p/n);
        const label k = min(label(std::floor(p)), n - 1);
        first_[f] = order[begin + k];
        second_[f] = order[begin + (k + 1) % n];
        weight_[f] = 1 - (p - k);
    }
}


template<class Type>
template<class Type2>
Foam::tmp<Foam::Field<Type2>>
Foam::leesEdwardsFvPatchField<Type>::shifted(const Field<Type2>& psi) const
{
    updateMap();
    const labelUList& nbrCells =
        this->cyclicPatch().neighbFvPatch().faceCells();
    tmp<Field<Type2>> tpnf(new Field<Type2>(this->size()));
    Field<Type2>& pnf = tpnf.ref();
    forAll(pnf, f)
    {
        pnf[f] =
            weight_[f]*psi[nbrCells[first_[f]]]
          + (1 - weight_[f])*psi[nbrCells[second_[f]]];
    }
    return tpnf;
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
    shearRate_(0),
    jumps_(true),
    mapTimeIndex_(-1)
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
    shearRate_(shearRate),
    jumps_(jumps),
    mapTimeIndex_(-1)
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
    shearRate_(dict.get<scalar>("shearRate")),
    jumps_(true),
    mapTimeIndex_(-1)
{
    // A decomposition across the sheared faces turns part of them into
    // processorCyclic patches, which would couple them unsheared
    for (const polyPatch& pp : p.patch().boundaryMesh())
    {
        const auto* proc = isA<processorCyclicPolyPatch>(pp);
        if (proc && proc->referPatchID() == p.index())
        {
            FatalIOErrorInFunction(dict)
                << "Patch " << p.name() << " of field "
                << iF.name() << ": its faces are split between"
                << " processors (" << pp.name() << "); a Lees-Edwards"
                << " boundary needs whole x rows on each processor:"
                << " decompose along z only (decomposeParDict coeffs.n"
                << " (1 1 N))" << exit(FatalIOError);
        }
    }
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
    shearRate_(ptf.shearRate_),
    jumps_(ptf.jumps_),
    mapTimeIndex_(-1)
{}


template<class Type>
Foam::leesEdwardsFvPatchField<Type>::leesEdwardsFvPatchField
(
    const leesEdwardsFvPatchField<Type>& ptf
)
:
    cyclicLduInterfaceField(),
    cyclicFvPatchField<Type>(ptf),
    shearRate_(ptf.shearRate_),
    jumps_(ptf.jumps_),
    mapTimeIndex_(-1)
{}


template<class Type>
Foam::leesEdwardsFvPatchField<Type>::leesEdwardsFvPatchField
(
    const leesEdwardsFvPatchField<Type>& ptf,
    const DimensionedField<Type, volMesh>& iF
)
:
    cyclicFvPatchField<Type>(ptf, iF),
    shearRate_(ptf.shearRate_),
    jumps_(ptf.jumps_),
    mapTimeIndex_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::scalar Foam::leesEdwardsFvPatchField<Type>::offset() const
{
    const boundBox& box = this->patch().boundaryMesh().mesh().bounds();
    const scalar Lx = box.span().x();
    const scalar s =
        shearRate_*box.span().y()*this->db().time().value();
    return s - Lx*std::floor(s/Lx);
}


template<class Type>
Foam::tmp<Foam::Field<Type>>
Foam::leesEdwardsFvPatchField<Type>::patchNeighbourField() const
{
    return shifted(this->primitiveField()) + jump();
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
    os.writeEntry("shearRate", shearRate_);
}


// ************************************************************************* //
