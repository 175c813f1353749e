/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "implicitContactSpring.H"
#include "resistanceTensorForms.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::implicitContactSpring::implicitContactSpring
(
    const label i,
    const label j,
    const vector& normal,
    const scalar armI,
    const scalar armJ,
    const scalar normalStiffnessTimesDt,
    const scalar tangentialStiffnessTimesDt,
    const vector& knownVelocity
)
:
    i_(i),
    j_(j),
    n_(normal),
    armI_(armI),
    armJ_(armJ),
    kn_(normalStiffnessTimesDt),
    kt_(tangentialStiffnessTimesDt),
    knownVelocity_(knownVelocity)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdm::implicitContactSpring::operators(scalar B[4][12]) const
{
    // U_s = P U_i - l_i N Omega_i - P U_j - l_j N Omega_j, with
    // P = I - n n and N v = n x v = -eps_ijk n_k v_j (Omega x n = -n x Omega);
    // w = n.U_i - n.U_j
    const tensor P = axialForm(0, 1, n_);
    const tensor N = epsilonForm(-1, n_);
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
    for (label c = 0; c < 3; ++c)
    {
        B[3][c] = n_[c];
        B[3][3 + c] = 0;
        B[3][6 + c] = -n_[c];
        B[3][9 + c] = 0;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fdm::implicitContactSpring::partnerVelocity
(
    const UList<vector>& U
) const
{
    return j_ >= 0 ? U[j_] + knownVelocity_ : knownVelocity_;
}


Foam::vector Foam::fdm::implicitContactSpring::slip
(
    const UList<vector>& U,
    const UList<vector>& Omega
) const
{
    return
        j_ >= 0
      ? slipVelocity
        (
            n_, U[i_], Omega[i_], armI_, partnerVelocity(U), Omega[j_], armJ_
        )
      : slipVelocity(n_, U[i_], Omega[i_], armI_, knownVelocity_, Zero, 0);
}


Foam::scalar Foam::fdm::implicitContactSpring::approach
(
    const UList<vector>& U
) const
{
    return n_ & (U[i_] - partnerVelocity(U));
}


void Foam::fdm::implicitContactSpring::addTo
(
    particleSystemSink& system,
    const scalar scale
) const
{
    scalar B[4][12];
    operators(B);
    const scalar weight[4] = {kt_, kt_, kt_, kn_};

    const label n = particleSystemSink::nDof;
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
            for (label r = 0; r < 4; ++r)
            {
                m += weight[r]*B[r][a]*B[r][b];
            }
            if (m != 0)
            {
                system.addEntry(global(a), global(b), scale*m);
            }
        }
    }

    if (knownVelocity_ != vector::zero)
    {
        // The known part of the partner's velocity (a wall's, or the image
        // velocity of j) in -K B u is a load on both: rows y = B_j v
        scalar y[4];
        for (label r = 0; r < 4; ++r)
        {
            y[r] = 0;
            for (label c = 0; c < 3; ++c)
            {
                y[r] += B[r][6 + c]*knownVelocity_[c];
            }
        }
        vector load[4] = {Zero, Zero, Zero, Zero};
        for (label a = 0; a < nCols; ++a)
        {
            for (label r = 0; r < 4; ++r)
            {
                load[a/3][a % 3] -= weight[r]*B[r][a]*y[r];
            }
        }
        system.addRhs(i_, scale*load[0], scale*load[1]);
        if (j_ >= 0)
        {
            system.addRhs(j_, scale*load[2], scale*load[3]);
        }
    }
}


Foam::fdm::contactForce Foam::fdm::implicitContactSpring::force
(
    const UList<vector>& U,
    const UList<vector>& Omega
) const
{
    const vector Ft = -kt_*slip(U, Omega);
    return contactForce{Ft - kn_*approach(U)*n_, Ft, 0, false, false, 0};
}


// ************************************************************************* //
