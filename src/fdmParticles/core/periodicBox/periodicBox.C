/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "periodicBox.H"
#include "error.H"

#include <cmath>

Foam::fdm::periodicBox::periodicBox
(
    const point& minCorner,
    const point& maxCorner,
    const FixedList<bool, 3>& periodic
)
:
    min_(minCorner),
    span_(maxCorner - minCorner),
    periodic_(periodic)
{
    for (direction d = 0; d < 3; ++d)
    {
        if (!(span_[d] > 0))
        {
            FatalErrorInFunction
                << "Box from " << minCorner << " to " << maxCorner
                << " has a non-positive edge along direction " << label(d)
                << abort(FatalError);
        }
    }
}


Foam::point Foam::fdm::periodicBox::wrap(const point& p) const
{
    point w(p);
    for (direction d = 0; d < 3; ++d)
    {
        if (periodic_[d])
        {
            const scalar s = w[d] - min_[d];
            scalar r = s - span_[d]*std::floor(s/span_[d]);

            // floor() rounding can leave r == span for tiny negative s
            if (r >= span_[d])
            {
                r -= span_[d];
            }
            w[d] = min_[d] + r;
        }
    }
    return w;
}


Foam::vector Foam::fdm::periodicBox::minimumImage(const vector& d) const
{
    vector m(d);
    for (direction i = 0; i < 3; ++i)
    {
        if (periodic_[i])
        {
            m[i] -= span_[i]*std::round(m[i]/span_[i]);
        }
    }
    return m;
}


// ************************************************************************* //
