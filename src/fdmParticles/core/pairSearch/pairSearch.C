/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "pairSearch.H"
#include "labelList.H"
#include "boolList.H"
#include "UIndirectList.H"
#include "ListOps.H"
#include "Pair.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Particles binned in cells of at least binSize per direction (linked
//  lists head/next); the bin index of a position outside the box along a
//  non-periodic direction is clamped to the end bins
class binGrid
{
    const fdm::periodicBox& box_;
    FixedList<label, 3> nBins_;
    labelList head_;
    labelList next_;
    List<FixedList<label, 3>> coords_;

    label index(const label i, const label j, const label k) const
    {
        return i + nBins_[0]*(j + nBins_[1]*k);
    }

    label coord(const point& x, const direction d) const
    {
        const label b =
            label((x[d] - box_.min()[d])/box_.span()[d]*nBins_[d]);
        return min(max(b, label(0)), nBins_[d] - 1);
    }

    //- Bin of coordinates c, wrapped across periodic directions; -1 when
    //  outside along an open one
    label wrapped(FixedList<label, 3> c) const
    {
        for (direction d = 0; d < 3; ++d)
        {
            if (c[d] < 0 || c[d] >= nBins_[d])
            {
                if (!box_.periodic(d))
                {
                    return -1;
                }
                c[d] = ((c[d] % nBins_[d]) + nBins_[d]) % nBins_[d];
            }
        }
        return index(c[0], c[1], c[2]);
    }

public:

    binGrid
    (
        const fdm::periodicBox& box,
        const UList<point>& positions,
        const UList<bool>& among,
        const scalar binSize
    )
    :
        box_(box),
        next_(positions.size(), -1),
        coords_(positions.size())
    {
        for (direction d = 0; d < 3; ++d)
        {
            nBins_[d] = max(label(1), label(box.span()[d]/binSize));
        }
        head_.setSize(nBins_[0]*nBins_[1]*nBins_[2], -1);
        forAll(positions, p)
        {
            if (among.size() && !among[p])
            {
                continue;
            }
            for (direction d = 0; d < 3; ++d)
            {
                coords_[p][d] = coord(positions[p], d);
            }
            const label b = index(coords_[p][0], coords_[p][1], coords_[p][2]);
            next_[p] = head_[b];
            head_[b] = p;
        }
    }

    label head(const label bin) const { return head_[bin]; }
    label next(const label p) const { return next_[p]; }

    //- Neighbour bins of p's bin, wrapped across periodic directions,
    //  sorted and unique (with fewer than three bins a wrap revisits one)
    void neighbours(const label p, DynamicList<label>& bins) const
    {
        bins.clear();
        for (label dk = -1; dk <= 1; ++dk)
        for (label dj = -1; dj <= 1; ++dj)
        {
            // Across the y faces of a Lees-Edwards cell the neighbour row
            // is the image shifted by the offset: its particles near x sit
            // near x - k s in the row, so the x stencil moves by that many
            // bins and widens by one to cover the fraction.
            const label row = coords_[p][1] + dj;
            const label k = (row < 0) ? -1 : (row >= nBins_[1]) ? 1 : 0;
            label iLow = -1;
            label iHigh = 1;
            if (k != 0 && box_.shearOffset() != 0)
            {
                const scalar shift =
                    -k*box_.shearOffset()/box_.span()[0]*nBins_[0];
                iLow = label(std::floor(shift)) - 1;
                iHigh = iLow + 3;
            }
            for (label di = iLow; di <= iHigh; ++di)
            {
                const label b = wrapped
                (
                    FixedList<label, 3>
                    ({coords_[p][0] + di, row, coords_[p][2] + dk})
                );
                if (b >= 0)
                {
                    bins.append(b);
                }
            }
        }
        std::sort(bins.begin(), bins.end());
        const auto last = std::unique(bins.begin(), bins.end());
        bins.setSize(last - bins.begin());
    }
};

//- Whether the surfaces of p and q are closer than cutoff
bool withinReach
(
    const fdm::periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii,
    const scalar cutoff,
    const label p,
    const label q
)
{
    const vector d = box.minimumImage(positions[q] - positions[p]);
    const scalar reach = radii[p] + radii[q] + cutoff;
    return magSqr(d) < sqr(reach);
}

} // namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::fdm::findNearPairs
(
    const periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii,
    const scalar cutoff,
    DynamicList<labelPair>& pairs
)
{
    findNearPairs
    (
        box, positions, radii, cutoff, identity(positions.size()), pairs
    );
}


void Foam::fdm::findNearPairs
(
    const periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii,
    const scalar cutoff,
    const labelUList& from,
    DynamicList<labelPair>& pairs
)
{
    findNearPairs
    (
        box, positions, radii, cutoff, from, UList<bool>::null(), pairs
    );
}


void Foam::fdm::findNearPairs
(
    const periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii,
    const scalar cutoff,
    const labelUList& from,
    const UList<bool>& among,
    DynamicList<labelPair>& pairs
)
{
    pairs.clear();
    const label n = positions.size();
    if (n < 2)
    {
        return;
    }
    boolList searched(n, false);
    UIndirectList<bool>(searched, from) = true;

    const binGrid grid(box, positions, among, 2*max(radii) + cutoff);
    DynamicList<label> neighbourBins(27);
    for (const label p : from)
    {
        grid.neighbours(p, neighbourBins);
        for (const label b : neighbourBins)
        {
            for (label q = grid.head(b); q != -1; q = grid.next(q))
            {
                // A pair of two searched particles is found from the
                // first
                if (q == p || (searched[q] && q < p))
                {
                    continue;
                }
                if (withinReach(box, positions, radii, cutoff, p, q))
                {
                    pairs.append(labelPair(min(p, q), max(p, q)));
                }
            }
        }
    }

    // By first, then second (Pair's operator<)
    std::sort(pairs.begin(), pairs.end());
}


void Foam::fdm::selectNearPairs
(
    const periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii,
    const scalar cutoff,
    const UList<labelPair>& near,
    DynamicList<labelPair>& pairs
)
{
    pairs.clear();
    for (const labelPair& pq : near)
    {
        if (withinReach(box, positions, radii, cutoff, pq.first(), pq.second()))
        {
            pairs.append(pq);
        }
    }
}


Foam::scalar Foam::fdm::smallestSurfaceGap
(
    const periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii,
    const scalar cutoff,
    const UList<labelPair>& near
)
{
    scalar smallest = cutoff;
    DynamicList<labelPair> pairs;
    selectNearPairs(box, positions, radii, cutoff, near, pairs);
    for (const labelPair& p : pairs)
    {
        const label i = p.first();
        const label j = p.second();
        const vector d = box.minimumImage(positions[j] - positions[i]);
        smallest = min(smallest, mag(d) - radii[i] - radii[j]);
    }
    forAll(positions, i)
    {
        for (direction d = 0; d < 3; ++d)
        {
            if (!box.periodic(d))
            {
                const scalar x = positions[i][d] - box.min()[d];
                smallest = min(smallest, x - radii[i]);
                smallest = min(smallest, box.span()[d] - x - radii[i]);
            }
        }
    }
    return smallest;
}


// ************************************************************************* //
