/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "ranksHoldingPoints.H"
#include "pointBins.H"
#include "sumOverRanks.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::fdm::ranksHoldingPoints
(
    const pointField& points,
    const pointField& cellCentres,
    const pointBins& cellBins,
    const scalar delta,
    const UList<bool>& candidates
)
{
    labelList rank(points.size(), -1);
    DynamicList<label> near;
    forAll(points, p)
    {
        if (candidates.size() && !candidates[p])
        {
            continue;
        }
        // A cube of side delta holds the point when no coordinate is more
        // than delta/2 from its centre (a hair more: a point on a face)
        near.clear();
        cellBins.findInSphere(points[p], 0.87*delta, near);
        for (const label c : near)
        {
            const vector d = points[p] - cellCentres[c];
            if (cmptMax(cmptMag(d)) <= 0.5*delta*(1 + 1e-12))
            {
                rank[p] = Pstream::myProcNo();
                break;
            }
        }
    }
    maxOverRanks(rank);
    return rank;
}


// ************************************************************************* //
