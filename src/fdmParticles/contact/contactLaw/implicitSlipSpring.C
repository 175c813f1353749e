/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "implicitSlipSpring.H"
#include "tensor.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::implicitSlipSpring::implicitSlipSpring
(
    const label i,
    const label j,
    const vector& normal,
    const scalar armI,
    const scalar armJ,
    const scalar stiffnessTimesDt,
    const vector& wallVelocity
)
:
    i_(i),
    j_(j),
    n_(normal),
    armI_(armI),
    armJ_(armJ),
    k_(stiffnessTimesDt),
    wallVelocity_(wallVelocity)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdm::implicitSlipSpring::slipOperator(scalar B[3][12]) const
{
    // U_s = P U_i - l_i [n]x Omega_i - P U_j - l_j [n]x Omega_j, with
    // P = I - n n and [n]x v = n x v (Omega x n = -n x Omega)
    const tensor P = tensor::I - sqr(n_);
    const tensor N
    (
        0, -n_.z(), n_.y(),
        n_.z(), 0, -n_.x(),
        -n_.y(), n_.x(), 0
    );
    for (label r = 0; r < 3; ++r)
    {
        for (label c = 0; c < 3; ++c)
        {
            B[r][c] = P(r, c);
            B[r][3 + c] = -armI_*N(r, c);
            B[r][6 + c] = -P(r, c);
            B[r][9 + c] = -armJ_*N(r, c);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fdm::implicitSlipSpring::slip
(
    const UList<vector>& U,
    const UList<vector>& Omega
) const
{
    return
        j_ >= 0
      ? slipVelocity(n_, U[i_], Omega[i_], armI_, U[j_], Omega[j_], armJ_)
      : slipVelocity(n_, U[i_], Omega[i_], armI_, wallVelocity_, Zero, 0);
}


void Foam::fdm::implicitSlipSpring::addTo
(
    particleVelocitySystem& system,
    const scalar scale
) const
{
    scalar B[3][12];
    slipOperator(B);

    const label n = particleVelocitySystem::nDof;
    const label nCols = j_ >= 0 ? 12 : 6;
    auto global = [&](const label c)
    {
        return c < 6 ? n*i_ + c : n*j_ + c - 6;
    };
    for (label a = 0; a < nCols; ++a)
    {
        for (label b = 0; b < nCols; ++b)
        {
            scalar m = 0;
            for (label r = 0; r < 3; ++r)
            {
                m += B[r][a]*B[r][b];
            }
            if (m != 0)
            {
                system.addEntry(global(a), global(b), scale*k_*m);
            }
        }
    }

    if (j_ < 0)
    {
        // The wall part of -k dt B^T (B_i u_i - P U_w) is a known load
        const vector PUw = wallVelocity_ - (wallVelocity_ & n_)*n_;
        vector F(Zero), T(Zero);
        for (label c = 0; c < 3; ++c)
        {
            for (label r = 0; r < 3; ++r)
            {
                F[c] += B[r][c]*PUw[r];
                T[c] += B[r][3 + c]*PUw[r];
            }
        }
        system.addRhs(i_, scale*k_*F, scale*k_*T);
    }
}


Foam::fdm::contactForce Foam::fdm::implicitSlipSpring::force
(
    const UList<vector>& U,
    const UList<vector>& Omega
) const
{
    const vector Ft = -k_*slip(U, Omega);
    return contactForce{Ft, Ft, 0, false, false, 0};
}


// ************************************************************************* //
