/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "ranksWithinReach.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fdm::squaredDistanceToBox
(
    const point& p,
    const boundBox& box
)
{
    scalar d2 = 0;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar out =
            max(max(box.min()[d] - p[d], p[d] - box.max()[d]), scalar(0));
        d2 += out*out;
    }
    return d2;
}


Foam::List<Foam::labelList> Foam::fdm::ranksWithinReach
(
    const pointField& points,
    const scalarField& reach,
    const UList<boundBox>& rankBoxes,
    const UList<vector>& shifts,
    const label self
)
{
    List<labelList> ranks(points.size());
    DynamicList<label> found;
    forAll(points, i)
    {
        found.clear();
        const scalar r2 = sqr(reach[i]);
        forAll(rankBoxes, r)
        {
            if (r == self)
            {
                continue;
            }
            for (const vector& s : shifts)
            {
                if (squaredDistanceToBox(points[i] + s, rankBoxes[r]) <= r2)
                {
                    found.append(r);
                    break;
                }
            }
        }
        ranks[i] = found;
    }
    return ranks;
}


// ************************************************************************* //
