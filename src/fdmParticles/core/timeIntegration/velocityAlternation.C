/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "velocityAlternation.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::velocityAlternation::velocityAlternation()
:
    older_(),
    stepsAbove_(0),
    warned_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fdm::velocityAlternation::check
(
    const UList<vector>& U,
    const UList<vector>& Uold,
    const scalar dt,
    const scalar limit,
    const boolList& moved,
    const bool shared,
    scalar& zigzag
)
{
    zigzag = -1;
    if (older_.size() == U.size())
    {
        scalar sumSqr = 0, count = 0;
        forAll(U, p)
        {
            if (moved.empty() || moved[p])
            {
                sumSqr += magSqr(0.25*dt*(U[p] - 2*Uold[p] + older_[p]));
                count += 1;
            }
        }
        if (shared)
        {
            reduce(sumSqr, sumOp<scalar>());
            reduce(count, sumOp<scalar>());
        }
        zigzag = count > 0 ? Foam::sqrt(sumSqr/count) : 0;
    }
    older_ = Uold;

    stepsAbove_ = zigzag > limit ? stepsAbove_ + 1 : 0;
    if (!warned_ && stepsAbove_ >= stepsInARow)
    {
        warned_ = true;
        return true;
    }
    return false;
}


// ************************************************************************* //
