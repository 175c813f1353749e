/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "pairSearch.H"
#include "labelList.H"
#include "Pair.H"
#include <algorithm>
#include <cmath>

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
    pairs.clear();
    const label n = positions.size();
    if (n < 2)
    {
        return;
    }

    const scalar binSize = 2*max(radii) + cutoff;

    // Bins per direction; the bin index of a position outside the box along
    // a non-periodic direction is clamped to the end bins.
    FixedList<label, 3> nBins;
    for (direction d = 0; d < 3; ++d)
    {
        nBins[d] = max(label(1), label(box.span()[d]/binSize));
    }

    auto binCoord = [&](const point& x, const direction d)
    {
        const label b = label((x[d] - box.min()[d])/box.span()[d]*nBins[d]);
        return min(max(b, label(0)), nBins[d] - 1);
    };
    auto binIndex = [&](const label i, const label j, const label k)
    {
        return i + nBins[0]*(j + nBins[1]*k);
    };

    const label nTotal = nBins[0]*nBins[1]*nBins[2];
    labelList head(nTotal, -1);
    labelList next(n, -1);
    List<FixedList<label, 3>> coords(n);

    for (label p = 0; p < n; ++p)
    {
        for (direction d = 0; d < 3; ++d)
        {
            coords[p][d] = binCoord(positions[p], d);
        }
        const label b = binIndex(coords[p][0], coords[p][1], coords[p][2]);
        next[p] = head[b];
        head[b] = p;
    }

    DynamicList<label> neighbourBins(27);

    for (label p = 0; p < n; ++p)
    {
        // Neighbour bins of p's bin, wrapped across periodic directions and
        // made unique (with fewer than three bins a wrap revisits a bin).
        neighbourBins.clear();
        for (label dk = -1; dk <= 1; ++dk)
        for (label dj = -1; dj <= 1; ++dj)
        {
            // Across the y faces of a Lees-Edwards cell the neighbour row
            // is the image shifted by the offset: its particles near x sit
            // near x - k s in the row, so the x stencil moves by that many
            // bins and widens by one to cover the fraction.
            const label row = coords[p][1] + dj;
            const label k = (row < 0) ? -1 : (row >= nBins[1]) ? 1 : 0;
            label iLow = -1;
            label iHigh = 1;
            if (k != 0 && box.shearOffset() != 0)
            {
                const scalar shift =
                    -k*box.shearOffset()/box.span()[0]*nBins[0];
                iLow = label(std::floor(shift)) - 1;
                iHigh = iLow + 3;
            }
        for (label di = iLow; di <= iHigh; ++di)
        {
            FixedList<label, 3> c({coords[p][0] + di, row,
                                   coords[p][2] + dk});
            bool valid = true;
            for (direction d = 0; d < 3; ++d)
            {
                if (c[d] < 0 || c[d] >= nBins[d])
                {
                    if (box.periodic(d))
                    {
                        c[d] = ((c[d] % nBins[d]) + nBins[d]) % nBins[d];
                    }
                    else
                    {
                        valid = false;
                    }
                }
            }
            if (valid)
            {
                neighbourBins.append(binIndex(c[0], c[1], c[2]));
            }
        }
        }
        std::sort(neighbourBins.begin(), neighbourBins.end());
        const auto last =
            std::unique(neighbourBins.begin(), neighbourBins.end());
        neighbourBins.setSize(last - neighbourBins.begin());

        for (const label b : neighbourBins)
        {
            for (label q = head[b]; q != -1; q = next[q])
            {
                if (q <= p)
                {
                    continue;
                }
                const vector d =
                    box.minimumImage(positions[q] - positions[p]);
                const scalar reach = radii[p] + radii[q] + cutoff;
                if (magSqr(d) < sqr(reach))
                {
                    pairs.append(labelPair(p, q));
                }
            }
        }
    }

    std::sort
    (
        pairs.begin(),
        pairs.end(),
        [](const labelPair& x, const labelPair& y)
        {
            return x.first() < y.first()
                || (x.first() == y.first() && x.second() < y.second());
        }
    );
}


Foam::scalar Foam::fdm::smallestSurfaceGap
(
    const periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii,
    const scalar cutoff
)
{
    scalar smallest = cutoff;
    DynamicList<labelPair> pairs;
    findNearPairs(box, positions, radii, cutoff, pairs);
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
