/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "ownedParticleSolve.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::fdm::ownedParticleSolve::localNumbers
(
    const particleSystemEntries& rows,
    const labelUList& owner,
    DynamicList<label>& ghostOwner,
    DynamicList<label>& ghostIndex
) const
{
    const label me = Pstream::myProcNo();
    const label nDof = particleSystemSink::nDof;
    labelList local(owner.size(), -1), ownerIndex(owner.size());
    labelList counts(Pstream::nProcs(), 0);
    forAll(owner, p)
    {
        ownerIndex[p] = counts[owner[p]]++;
        local[p] = owner[p] == me ? ownerIndex[p] : -1;
    }
    forAll(rows.rows, e)
    {
        const label p = rows.rows[e]/nDof, q = rows.cols[e]/nDof;
        if (owner[p] == me && local[q] < 0)
        {
            local[q] = counts[me] + ghostOwner.size();
            ghostOwner.append(owner[q]);
            ghostIndex.append(ownerIndex[q]);
        }
    }
    return local;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fdm::particleVelocitySystem::solveInfo
Foam::fdm::ownedParticleSolve::solve
(
    const particleSystemEntries& rows,
    const labelUList& owner,
    const scalar tolerance,
    const label maxIterations,
    List<vector>& U,
    List<vector>& Omega,
    const scalar residualScale
)
{
    DynamicList<label> ghostOwner, ghostIndex;
    const labelList local(localNumbers(rows, owner, ghostOwner, ghostIndex));

    // Made anew on every rank when the owners or any rank's ghosts changed
    // (the constructor exchanges with all ranks)
    bool remake = !system_ || local != local_ || owner != owner_;
    reduce(remake, orOp<bool>());
    if (remake)
    {
        label nOwned = 0;
        forAll(owner, p)
        {
            nOwned += (owner[p] == Pstream::myProcNo());
        }
        system_.reset
        (
            new distributedParticleSystem(nOwned, ghostOwner, ghostIndex)
        );
        owner_ = owner;
        local_ = local;
    }
    system_->clear();
    rows.replay(*system_, local);

    const label nLocal = system_->nOwned() + system_->nGhosts();
    List<vector> u(nLocal), w(nLocal);
    forAll(local, p)
    {
        if (local[p] >= 0)
        {
            u[local[p]] = U[p];
            w[local[p]] = Omega[p];
        }
    }
    const particleVelocitySystem::solveInfo info =
        system_->solve(tolerance, maxIterations, u, w, residualScale);

    forAll(local, p)
    {
        if (local[p] >= 0 && local[p] < system_->nOwned())
        {
            U[p] = u[local[p]];
            Omega[p] = w[local[p]];
        }
    }
    return info;
}


// ************************************************************************* //
