/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "leesEdwardsRowMap.H"
#include "DynamicList.H"
#include "error.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fdm::leesEdwardsOffset
(
    const scalar shearRate,
    const boundBox& box,
    const scalar t
)
{
    const scalar Lx = box.span().x();
    const scalar s = shearRate*box.span().y()*t;
    return s - Lx*std::floor(s/Lx);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::leesEdwardsRowMap::leesEdwardsRowMap
(
    const vectorField& rowCf,
    const vectorField& Cf,
    const scalar shift,
    const scalar Lx,
    const string& where
)
:
    first_(Cf.size()),
    second_(Cf.size()),
    weight_(Cf.size())
{
    const scalar tol = 1e-6*Lx;

    // The row faces in rows of equal z, each sorted along x
    labelList order(identity(rowCf.size()));
    std::sort
    (
        order.begin(), order.end(),
        [&](const label a, const label b)
        {
            return mag(rowCf[a].z() - rowCf[b].z()) > tol
                ? rowCf[a].z() < rowCf[b].z()
                : rowCf[a].x() < rowCf[b].x();
        }
    );
    DynamicList<label> rowStart;
    forAll(order, i)
    {
        if (!i || mag(rowCf[order[i]].z() - rowCf[order[i - 1]].z()) > tol)
        {
            rowStart.append(i);
        }
    }
    rowStart.append(order.size());

    forAll(Cf, f)
    {
        // The row of this point's z
        label r = 0;
        while
        (
            r + 1 < rowStart.size() - 1
         && rowCf[order[rowStart[r]]].z() < Cf[f].z() - tol
        )
        {
            ++r;
        }
        const label begin = rowStart[r];
        const label n = rowStart[r + 1] - begin;
        const scalar x0 = n > 0 ? rowCf[order[begin]].x() : 0;
        const scalar dx = n > 1 ? rowCf[order[begin + 1]].x() - x0 : Lx;
        if
        (
            n < 1
         || mag(rowCf[order[begin]].z() - Cf[f].z()) > tol
         || mag(n*dx - Lx) > tol
        )
        {
            FatalErrorInFunction
                << where << ": the face at " << Cf[f] << " has no whole"
                << " row of faces along x at its z (each row of the"
                << " sheared faces must lie on one processor, uniformly"
                << " spaced: decompose along y and z, not along x)"
                << exit(FatalError);
        }
        // Position along the row in spacings from its first face, periodic
        scalar p = (Cf[f].x() + shift - x0)/dx;
        p -= n*std::floor(p/n);
        const label k = min(label(std::floor(p)), n - 1);
        first_[f] = order[begin + k];
        second_[f] = order[begin + (k + 1) % n];
        weight_[f] = 1 - (p - k);
    }
}


// ************************************************************************* //
