/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "ownedRowsSink.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::ownedRowsSink::ownedRowsSink(const label nParticles)
:
    owned_(nParticles, false),
    entries_(nParticles)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::ownedRowsSink::setOwners(const labelUList& owner)
{
    if (owner.size() != owned_.size())
    {
        owned_.setSize(owner.size());
        entries_ = particleSystemEntries(owner.size());
    }
    forAll(owner, p)
    {
        owned_[p] = owner[p] == Pstream::myProcNo();
    }
    clear();
}


void Foam::fdm::ownedRowsSink::clear()
{
    entries_.clear();
}


void Foam::fdm::ownedRowsSink::addEntry
(
    const label row,
    const label col,
    const scalar value
)
{
    if (owned_[row/nDof])
    {
        entries_.add(row, col, value);
    }
}


void Foam::fdm::ownedRowsSink::addRhs
(
    const label i,
    const vector& force,
    const vector& torque
)
{
    if (owned_[i])
    {
        entries_.addRhs(i, force, torque);
    }
}


void Foam::fdm::ownedRowsSink::prescribe
(
    const label i,
    const direction dof,
    const scalar value
)
{
    if (owned_[i])
    {
        entries_.prescribe(i, dof, value);
    }
}


// ************************************************************************* //
