/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleHalo.H"
#include "ranksWithinReach.H"
#include "ListOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::fdm::particleHalo::owned() const
{
    return findIndices(owner_, Pstream::myProcNo());
}


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
    const labelList mine(owned());
    forAll(held_, p)
    {
        held_[p] =
            owner_[p] == me
         || (held_[p] && reaches(me, p, positions[p], shifts));
    }
    ghostRanks_.setSize(owner_.size());
    for (labelList& ranks : ghostRanks_)
    {
        ranks.clear();
    }
    const List<labelList> ranks
    (
        ranksWithinReach
        (
            pointField(UIndirectList<point>(positions, mine)),
            scalarField(UIndirectList<scalar>(reach_, mine)),
            rankBoxes_, shifts, me
        )
    );
    forAll(mine, i)
    {
        ghostRanks_[mine[i]] = ranks[i];
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
    const labelList mine(owned());
    // An owner keeps its own particles in its lists (they reach its box
    // unless a step moved one further than its reach, which
    // fdmParticleCloud::buildStencils reports); the other ranks hold what
    // they receive
    List<DynamicList<label>> to(rankBoxes_.size());
    held_ = false;
    for (const label p : mine)
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
    exchangeWithRanks
    (
        [&](const label r, Ostream& os)
        {
            os << labelList(to[r]);
            haloIO::writeSelected(os, to[r], s.position);
            haloIO::writeSelected(os, to[r], s.U);
            haloIO::writeSelected(os, to[r], s.Omega);
            haloIO::writeSelected(os, to[r], s.Uold);
        },
        [&](const label, Istream& is)
        {
            const labelList received(is);
            haloIO::readSelected(is, received, s.position);
            haloIO::readSelected(is, received, s.U);
            haloIO::readSelected(is, received, s.Omega);
            haloIO::readSelected(is, received, s.Uold);
            UIndirectList<bool>(held_, received) = true;
        }
    );
}


void Foam::fdm::particleHalo::report() const
{
    if (!distributed())
    {
        return;
    }
    const label owned = this->owned().size();
    const label held = findIndices(held_, true).size();
    Info<< "    By subdomain: a rank owns "
        << returnReduce(owned, minOp<label>()) << " to "
        << returnReduce(owned, maxOp<label>()) << " particles and holds "
        << returnReduce(held, minOp<label>()) << " to "
        << returnReduce(held, maxOp<label>()) << " of " << held_.size()
        << " (its own and their ghosts)" << endl;
}


void Foam::fdm::particleHalo::sendToGhosts
(
    List<vector>& a,
    List<vector>& b
) const
{
    if (!distributed() || !Pstream::parRun())
    {
        return;
    }
    List<DynamicList<label>> to(Pstream::nProcs());
    forAll(ghostRanks_, p)
    {
        for (const label r : ghostRanks_[p])
        {
            to[r].append(p);
        }
    }
    exchangeWithRanks
    (
        [&](const label r, Ostream& os)
        {
            os << labelList(to[r]);
            haloIO::writeSelected(os, to[r], a);
            haloIO::writeSelected(os, to[r], b);
        },
        [&](const label, Istream& is)
        {
            const labelList received(is);
            haloIO::readSelected(is, received, a);
            haloIO::readSelected(is, received, b);
        }
    );
}


// ************************************************************************* //
