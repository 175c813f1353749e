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
    periodic_(periodic),
    shearOffset_(0),
    shearVelocity_(0)
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


void Foam::fdm::periodicBox::requireShearable() const
{
    if (!periodic_[0] || !periodic_[1])
    {
        FatalErrorInFunction
            << "Lees-Edwards images need a box periodic in x and y"
            << abort(FatalError);
    }
}


void Foam::fdm::periodicBox::setShearOffset(const scalar s)
{
    requireShearable();
    shearOffset_ = s - span_[0]*std::floor(s/span_[0]);
}


void Foam::fdm::periodicBox::setShearVelocity(const scalar v)
{
    requireShearable();
    shearVelocity_ = v;
}


Foam::label Foam::fdm::periodicBox::periodsAlongY(const point& p) const
{
    return periodic_[1] ? label(std::floor((p[1] - min_[1])/span_[1])) : 0;
}


Foam::point Foam::fdm::periodicBox::wrap(const point& p) const
{
    point w(p);

    // Crossing the y faces of a sheared cell also shifts x (Lees-Edwards)
    w[0] -= shearOffset_*periodsAlongY(p);

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


Foam::vector Foam::fdm::periodicBox::wrapVelocity
(
    const point& p,
    const vector& U
) const
{
    return U - imageVelocity(periodsAlongY(p));
}


Foam::label Foam::fdm::periodicBox::minimumImagePeriodsY(const vector& d) const
{
    return periodic_[1] ? label(std::round(d[1]/span_[1])) : 0;
}


Foam::vector Foam::fdm::periodicBox::imageVelocity(const vector& d) const
{
    // minimumImage moves the far end down by the periods it removes
    return imageVelocity(-minimumImagePeriodsY(d));
}


Foam::vector Foam::fdm::periodicBox::minimumImage(const vector& d) const
{
    vector m(d);
    const label k = minimumImagePeriodsY(m);
    m[0] -= k*shearOffset_;
    m[1] -= k*span_[1];
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
