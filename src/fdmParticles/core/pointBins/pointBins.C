/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "pointBins.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::fdm::pointBins::binCoord
(
    const scalar x,
    const direction d
) const
{
    const label b = label(std::floor((x - bounds_.min()[d])/binSize_));
    return min(max(b, label(0)), nBins_[d] - 1);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::pointBins::pointBins(const pointField& points, const scalar binSize)
:
    points_(points),
    bounds_(points, false),
    binSize_(binSize),
    nBins_({1, 1, 1})
{
    if (points.empty())
    {
        binStart_.setSize(2, 0);
        return;
    }

    for (direction d = 0; d < 3; ++d)
    {
        nBins_[d] = 1 + label(bounds_.span()[d]/binSize_);
    }
    const label nTotal = nBins_[0]*nBins_[1]*nBins_[2];

    // Counting sort of the points by bin
    labelList binOf(points.size());
    binStart_.setSize(nTotal + 1, 0);
    forAll(points, i)
    {
        const point& p = points[i];
        binOf[i] =
            binCoord(p.x(), 0)
          + nBins_[0]*(binCoord(p.y(), 1) + nBins_[1]*binCoord(p.z(), 2));
        ++binStart_[binOf[i] + 1];
    }
    for (label b = 0; b < nTotal; ++b)
    {
        binStart_[b + 1] += binStart_[b];
    }
    labelList fill(SubList<label>(binStart_, nTotal));
    binPoints_.setSize(points.size());
    forAll(points, i)
    {
        binPoints_[fill[binOf[i]]++] = i;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fdm::pointBins::mayOverlap(const point& x, const scalar R) const
{
    if (points_.empty())
    {
        return false;
    }
    for (direction d = 0; d < 3; ++d)
    {
        if (x[d] + R < bounds_.min()[d] || x[d] - R > bounds_.max()[d])
        {
            return false;
        }
    }
    return true;
}


void Foam::fdm::pointBins::findInSphere
(
    const point& x,
    const scalar R,
    DynamicList<label>& found
) const
{
    if (!mayOverlap(x, R))
    {
        return;
    }

    FixedList<label, 3> lo, hi;
    for (direction d = 0; d < 3; ++d)
    {
        lo[d] = binCoord(x[d] - R, d);
        hi[d] = binCoord(x[d] + R, d);
    }

    const scalar R2 = R*R;
    for (label k = lo[2]; k <= hi[2]; ++k)
    {
        for (label j = lo[1]; j <= hi[1]; ++j)
        {
            for (label i = lo[0]; i <= hi[0]; ++i)
            {
                const label b = i + nBins_[0]*(j + nBins_[1]*k);
                for (label e = binStart_[b]; e < binStart_[b + 1]; ++e)
                {
                    const label pi = binPoints_[e];
                    if (magSqr(points_[pi] - x) <= R2)
                    {
                        found.append(pi);
                    }
                }
            }
        }
    }
}


// ************************************************************************* //
