/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "layerDiffusion.H"
#include "error.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalarField Foam::fdm::solveLayerDiffusion
(
    const scalarField& y,
    const scalar yLow,
    const scalar yHigh,
    const scalar nu,
    const scalarField& r
)
{
    const label n = y.size();
    if (n == 0 || r.size() != n || !(nu > 0))
    {
        FatalErrorInFunction
            << n << " layers, " << r.size() << " right-hand sides, nu "
            << nu << abort(FatalError);
    }
    for (label k = 0; k < n; ++k)
    {
        const scalar below = k == 0 ? yLow : y[k - 1];
        const scalar above = k == n - 1 ? yHigh : y[k + 1];
        if (!(below < y[k] && y[k] < above))
        {
            FatalErrorInFunction
                << "layer centres must ascend strictly between the walls "
                << yLow << " and " << yHigh << ": layer " << k << " at "
                << y[k] << abort(FatalError);
        }
    }

    // Per layer k: thickness h (face to face, faces half-way between
    // centres) and the face coefficients nu/d below and above (d: centre to
    // centre, or centre to wall)
    scalarField lower(n, 0), diag(n, 0), upper(n, 0), rhs(n, 0);
    for (label k = 0; k < n; ++k)
    {
        const scalar faceBelow = k == 0 ? yLow : 0.5*(y[k - 1] + y[k]);
        const scalar faceAbove = k == n - 1 ? yHigh : 0.5*(y[k] + y[k + 1]);
        const scalar h = faceAbove - faceBelow;
        const scalar cBelow =
            nu/(k == 0 ? y[0] - yLow : y[k] - y[k - 1]);
        const scalar cAbove =
            nu/(k == n - 1 ? yHigh - y[k] : y[k + 1] - y[k]);
        // h nu d2u/dy2 ~ cAbove (u_{k+1} - u_k) - cBelow (u_k - u_{k-1})
        diag[k] = -(cBelow + cAbove);
        lower[k] = k == 0 ? 0 : cBelow;
        upper[k] = k == n - 1 ? 0 : cAbove;
        rhs[k] = h*r[k];
    }

    // Thomas algorithm: forward elimination, back substitution
    for (label k = 1; k < n; ++k)
    {
        const scalar m = lower[k]/diag[k - 1];
        diag[k] -= m*upper[k - 1];
        rhs[k] -= m*rhs[k - 1];
    }
    scalarField u(n);
    u[n - 1] = rhs[n - 1]/diag[n - 1];
    for (label k = n - 2; k >= 0; --k)
    {
        u[k] = (rhs[k] - upper[k]*u[k + 1])/diag[k];
    }
    return u;
}


// ************************************************************************* //
