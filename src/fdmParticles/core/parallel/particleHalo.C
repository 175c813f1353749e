/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleHalo.H"
#include "ranksWithinReach.H"
#include "ListOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::fdm::particleHalo::reaches
(
    const label r,
    const label p,
    const point& x,
    const UList<vector>& shifts
) const
{
    for (const vector& s : shifts)
    {
        if (squaredDistanceToBox(x + s, rankBoxes_[r]) <= sqr(reach_[p]))
        {
            return true;
        }
    }
    return false;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::particleHalo::particleHalo
(
    const List<boundBox>& rankBoxes,
    const scalarField& reach
)
:
    rankBoxes_(rankBoxes),
    reach_(reach),
    held_(reach.size(), true)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::boundBox> Foam::fdm::particleHalo::gatherBoxes
(
    const boundBox& mine
)
{
    List<boundBox> boxes(Pstream::nProcs());
    boxes[Pstream::myProcNo()] = mine;
    Pstream::gatherList(boxes);
    Pstream::scatterList(boxes);
    return boxes;
}


void Foam::fdm::particleHalo::setOwners
(
    const labelList& owner,
    const pointField& positions,
    const UList<vector>& shifts
)
{
    if (!distributed())
    {
        return;
    }
    owner_ = owner;
    const label me = Pstream::myProcNo();
    owned_ = findIndices(owner_, me);
    forAll(held_, p)
    {
        held_[p] =
            owner_[p] == me
         || (held_[p] && reaches(me, p, positions[p], shifts));
    }
    const List<labelList> ranks
    (
        ranksWithinReach
        (
            pointField(UIndirectList<point>(positions, owned_)),
            scalarField(UIndirectList<scalar>(reach_, owned_)),
            rankBoxes_, shifts, me
        )
    );
    ghostRanks_ = List<labelList>(owner_.size());
    forAll(owned_, i)
    {
        ghostRanks_[owned_[i]] = ranks[i];
    }
}


void Foam::fdm::particleHalo::sendMoved
(
    particleState& s,
    const UList<vector>& shifts
)
{
    if (!distributed())
    {
        return;
    }
    const label me = Pstream::myProcNo();
    // An owner keeps its own particles in its lists (they reach its box
    // unless a step moved one further than its reach, which
    // fdmParticleCloud::buildStencils reports); the other ranks hold what
    // they receive
    List<DynamicList<label>> to(rankBoxes_.size());
    held_ = false;
    for (const label p : owned_)
    {
        held_[p] = true;
        forAll(rankBoxes_, r)
        {
            if (r != me && reaches(r, p, s.position[p], shifts))
            {
                to[r].append(p);
            }
        }
    }
    const labelList received
    (
        sendEntries(to, s.position, s.U, s.Omega, s.Uold)
    );
    UIndirectList<bool>(held_, received) = true;
}


void Foam::fdm::particleHalo::report() const
{
    if (!distributed())
    {
        return;
    }
    const label nOwned = owned_.size();
    const label nHeld = findIndices(held_, true).size();
    Info<< "    By subdomain: a rank owns "
        << returnReduce(nOwned, minOp<label>()) << " to "
        << returnReduce(nOwned, maxOp<label>()) << " particles and holds "
        << returnReduce(nHeld, minOp<label>()) << " to "
        << returnReduce(nHeld, maxOp<label>()) << " of " << held_.size()
        << " (its own and their ghosts)" << endl;
}


void Foam::fdm::particleHalo::sendToGhosts
(
    List<vector>& a,
    List<vector>& b
) const
{
    if (!distributed())
    {
        return;
    }
    List<DynamicList<label>> to(rankBoxes_.size());
    for (const label p : owned_)
    {
        for (const label r : ghostRanks_[p])
        {
            to[r].append(p);
        }
    }
    sendEntries(to, a, b);
}


// ************************************************************************* //
