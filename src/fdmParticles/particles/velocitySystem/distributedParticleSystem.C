/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "distributedParticleSystemOperators.H"
#include "exchangeWithRanks.H"
#include "PstreamBuffers.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::distributedParticleSystem::distributedParticleSystem
(
    const label nOwned,
    const labelUList& ghostOwner,
    const labelUList& ghostIndex
)
:
    nOwned_(nOwned),
    nGhosts_(ghostOwner.size()),
    sendTo_(Pstream::nProcs()),
    receiveFrom_(Pstream::nProcs()),
    entries_(nOwned)
{
    // Group the ghosts by owner: which of its particles each owner sends
    List<DynamicList<label>> requests(Pstream::nProcs());
    List<DynamicList<label>> ghosts(Pstream::nProcs());
    forAll(ghostOwner, g)
    {
        const label r = ghostOwner[g];
        if (r < 0 || r >= Pstream::nProcs() || r == Pstream::myProcNo())
        {
            FatalErrorInFunction
                << "Ghost " << g << " is owned by rank " << r << ": a ghost"
                << " belongs to another of the " << Pstream::nProcs()
                << " ranks" << exit(FatalError);
        }
        requests[r].append(ghostIndex[g]);
        ghosts[r].append(nOwned + g);
    }
    forAll(ghosts, r)
    {
        receiveFrom_[r].transfer(ghosts[r]);
    }
    // Every rank hears from every other once (empty lists included), so
    // that each knows what it sends without knowing who asks
    exchangeWithRanks
    (
        [&](const label r, Ostream& os) { os << labelList(requests[r]); },
        [&](const label r, Istream& is)
        {
            is >> sendTo_[r];
            for (const label i : sendTo_[r])
            {
                if (i < 0 || i >= nOwned_)
                {
                    FatalErrorInFunction
                        << "Rank " << r << " asks for particle " << i
                        << " of rank " << Pstream::myProcNo() << ", which"
                        << " owns " << nOwned_ << exit(FatalError);
                }
            }
        }
    );
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::fdm::distributedParticleSystem::~distributedParticleSystem()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdm::distributedParticleSystem::exchange(scalar* x) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(sendTo_, r)
    {
        if (sendTo_[r].size())
        {
            List<scalar> values(nDof*sendTo_[r].size());
            forAll(sendTo_[r], k)
            {
                for (label d = 0; d < nDof; ++d)
                {
                    values[nDof*k + d] = x[nDof*sendTo_[r][k] + d];
                }
            }
            UOPstream os(r, buffers);
            os << values;
        }
    }
    buffers.finishedSends();
    forAll(receiveFrom_, r)
    {
        if (receiveFrom_[r].size())
        {
            UIPstream is(r, buffers);
            List<scalar> values;
            is >> values;
            forAll(receiveFrom_[r], k)
            {
                for (label d = 0; d < nDof; ++d)
                {
                    x[nDof*receiveFrom_[r][k] + d] = values[nDof*k + d];
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::distributedParticleSystem::clear()
{
    entries_.clear();
}


void Foam::fdm::distributedParticleSystem::addEntry
(
    const label row,
    const label col,
    const scalar value
)
{
    if (row < nDof*nOwned_)
    {
        entries_.add(row, col, value);
    }
}


void Foam::fdm::distributedParticleSystem::addRhs
(
    const label i,
    const vector& force,
    const vector& torque
)
{
    if (i < nOwned_)
    {
        entries_.addRhs(i, force, torque);
    }
}


void Foam::fdm::distributedParticleSystem::prescribe
(
    const label i,
    const direction dof,
    const scalar value
)
{
    if (i < nOwned_)
    {
        entries_.prescribe(i, dof, value);
    }
}


// ************************************************************************* //
