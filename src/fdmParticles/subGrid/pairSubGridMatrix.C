/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "pairSubGridMatrix.H"
#include "particleVelocitySystem.H"
#include "error.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;
using Foam::label;

//- Levi-Civita symbol eps_ijk
inline scalar leviCivita(const label i, const label j, const label k)
{
    return scalar((i - j)*(j - k)*(k - i))/2;
}

} // namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::fdm::pairSubGridMatrix::resistanceFunctions
Foam::fdm::pairSubGridMatrix::expand
(
    const pairBaseFunctions& b,
    const scalar r
)
{
    // Relations of thesis section 3.3.3 (seed notes 8.5.2).  Index 0 is
    // particle 1, index 1 particle 2: f.XA[1][0] = X_21^A.
    resistanceFunctions f;
    const scalar r2 = r*r;

    // A: X_11 = -X_21, X_12 = X_21, X_22 = -X_21 (Y alike)
    f.XA[0][0] = -b.XA21;  f.XA[0][1] = b.XA21;
    f.XA[1][0] = b.XA21;   f.XA[1][1] = -b.XA21;
    f.YA[0][0] = -b.YA21;  f.YA[0][1] = b.YA21;
    f.YA[1][0] = b.YA21;   f.YA[1][1] = -b.YA21;

    // C: X as A; Y_12 = Y_21 = -Y_11 + r Y_21^B - r^2 Y_21^A,
    //    Y_22 = Y_11 - 2 r Y_21^B + r^2 Y_21^A
    f.XC[0][0] = -b.XC21;  f.XC[0][1] = b.XC21;
    f.XC[1][0] = b.XC21;   f.XC[1][1] = -b.XC21;
    f.YC[0][0] = b.YC11;
    f.YC[0][1] = -b.YC11 + r*b.YB21 - r2*b.YA21;
    f.YC[1][0] = -b.YC11 + r*b.YB21 - r2*b.YA21;
    f.YC[1][1] = b.YC11 - 2*r*b.YB21 + r2*b.YA21;

    // B (torque rows, U columns)
    f.YB[0][0] = -b.YB21 + r*b.YA21;
    f.YB[0][1] = b.YB21 - r*b.YA21;
    f.YB[1][0] = b.YB21;
    f.YB[1][1] = -b.YB21;

    // B~ (force rows, Omega columns), printed list of 3.3.3
    f.YBt[0][0] = b.YB21 - r*b.YA21;
    f.YBt[0][1] = -b.YB21;
    f.YBt[1][0] = -b.YB21 + r*b.YA21;
    f.YBt[1][1] = b.YB21;

    // P: X_11 = -X_12, X_22 = -X_21
    f.XP[0][0] = -b.XP12;  f.XP[0][1] = b.XP12;
    f.XP[1][0] = b.XP21;   f.XP[1][1] = -b.XP21;

    // G (stresslet rows, U columns)
    f.XG[0][0] = b.XG11;
    f.XG[0][1] = -b.XG11;
    f.XG[1][0] = -b.XG11 - r*b.XA21;
    f.XG[1][1] = b.XG11 + r*b.XA21;
    f.YG[0][0] = b.YG11;
    f.YG[0][1] = -b.YG11;
    f.YG[1][0] = -b.YG11 - 0.5*r*b.YA21;
    f.YG[1][1] = b.YG11 + 0.5*r*b.YA21;

    // G~ (force rows, E columns); the X lines are printed without tildes
    // in 3.3.3 (seed notes section 12, item 21)
    f.XGt[0][0] = b.XG11;
    f.XGt[0][1] = -b.XG11 - r*b.XA21;
    f.XGt[1][0] = -b.XG11;
    f.XGt[1][1] = b.XG11 + r*b.XA21;
    f.YGt[0][0] = b.YG11;
    f.YGt[0][1] = -b.YG11 - 0.5*r*b.YA21;
    f.YGt[1][0] = -b.YG11;
    f.YGt[1][1] = b.YG11 + 0.5*r*b.YA21;

    // H (stresslet rows, Omega columns); base Y_21^H (item 19)
    f.YH[0][0] = -b.YH21 - 0.5*r2*b.YA21 + 0.5*r*b.YB21;
    f.YH[0][1] = b.YH21 + 0.5*r2*b.YA21 + r*b.YG11 - 0.5*r*b.YB21;
    f.YH[1][0] = b.YH21;
    f.YH[1][1] = -b.YH21 - 0.5*r2*b.YA21 - r*b.YG11;

    // H~ (torque rows, E columns)
    f.YHt[0][0] = -b.YH21 - 0.5*r2*b.YA21 + 0.5*r*b.YB21;
    f.YHt[0][1] = b.YH21;
    f.YHt[1][0] = b.YH21 + 0.5*r2*b.YA21 + r*b.YG11 - 0.5*r*b.YB21;
    f.YHt[1][1] = -b.YH21 - 0.5*r2*b.YA21 - r*b.YG11;

    return f;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::pairSubGridMatrix::pairSubGridMatrix
(
    const pairBaseFunctions& base,
    const scalar r,
    const vector& d
)
:
    r_(r),
    d_(d),
    f_(expand(base, r))
{
    const scalar magD = mag(d);
    if (magD < VSMALL || r <= 0)
    {
        FatalErrorInFunction
            << "Degenerate pair geometry: r = " << r << ", d = " << d
            << exit(FatalError);
    }
    d_ /= magD;

    // Appendix A forms; row block a, column block b; per particle the
    // unknowns are (U, Omega)
    for (label a = 0; a < 2; ++a)
    {
        for (label b = 0; b < 2; ++b)
        {
            for (label i = 0; i < 3; ++i)
            {
                for (label j = 0; j < 3; ++j)
                {
                    const scalar dd = d_[i]*d_[j];
                    const scalar perp = (i == j ? 1 : 0) - dd;
                    scalar epsD = 0;
                    for (label k = 0; k < 3; ++k)
                    {
                        epsD += leviCivita(i, j, k)*d_[k];
                    }

                    // Force row, U column: A
                    R_[6*a + i][6*b + j] =
                        f_.XA[a][b]*dd + f_.YA[a][b]*perp;
                    // Force row, Omega column: B~
                    R_[6*a + i][6*b + 3 + j] = f_.YBt[a][b]*epsD;
                    // Torque row, U column: B
                    R_[6*a + 3 + i][6*b + j] = f_.YB[a][b]*epsD;
                    // Torque row, Omega column: C
                    R_[6*a + 3 + i][6*b + 3 + j] =
                        f_.XC[a][b]*dd + f_.YC[a][b]*perp;
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::pairSubGridMatrix::forceTorque
(
    const vector& U1, const vector& W1,
    const vector& U2, const vector& W2,
    vector& F1, vector& T1,
    vector& F2, vector& T2
) const
{
    scalar u[nDof];
    for (label k = 0; k < 3; ++k)
    {
        u[k] = U1[k];
        u[3 + k] = W1[k];
        u[6 + k] = U2[k];
        u[9 + k] = W2[k];
    }

    vector* out[4] = {&F1, &T1, &F2, &T2};
    for (label i = 0; i < nDof; ++i)
    {
        scalar s = 0;
        for (label j = 0; j < nDof; ++j)
        {
            s += R_[i][j]*u[j];
        }
        (*out[i/3])[i % 3] = -s;
    }
}


Foam::symmTensor Foam::fdm::pairSubGridMatrix::G
(
    const label a,
    const label b,
    const vector& U
) const
{
    // G_ijk U_k = X^G (U.d)(d d - I/3) + Y^G (d U + U d - 2 (U.d) d d)
    const scalar Ud = U & d_;
    return
        f_.XG[a][b]*Ud*(sqr(d_) - symmTensor::I/3)
      + f_.YG[a][b]*(twoSymm(d_*U) - 2*Ud*sqr(d_));
}


Foam::symmTensor Foam::fdm::pairSubGridMatrix::H
(
    const label a,
    const label b,
    const vector& W
) const
{
    // H_ijk W_k = Y^H (d_i eps_jkm W_k d_m + d_j eps_ikm W_k d_m)
    //           = Y^H (d (W x d) + (W x d) d)
    return f_.YH[a][b]*twoSymm(d_*(W ^ d_));
}


Foam::symmTensor Foam::fdm::pairSubGridMatrix::stresslet
(
    const label a,
    const vector& U1, const vector& W1,
    const vector& U2, const vector& W2
) const
{
    return -(G(a, 0, U1) + G(a, 1, U2) + H(a, 0, W1) + H(a, 1, W2));
}


Foam::scalar Foam::fdm::pairSubGridMatrix::dipoleTrace
(
    const label a,
    const vector& U1,
    const vector& U2
) const
{
    return -(f_.XP[a][0]*(U1 & d_) + f_.XP[a][1]*(U2 & d_));
}


Foam::vector Foam::fdm::pairSubGridMatrix::strainForce
(
    const label a,
    const label b,
    const symmTensor& E
) const
{
    // G~_ijk E_jk = X~^G (d.E.d - tr(E)/3) d + 2 Y~^G (E.d - (d.E.d) d)
    const vector Ed = E & d_;
    const scalar dEd = d_ & Ed;
    return
        f_.XGt[a][b]*(dEd - tr(E)/3)*d_
      + 2*f_.YGt[a][b]*(Ed - dEd*d_);
}


Foam::vector Foam::fdm::pairSubGridMatrix::strainTorque
(
    const label a,
    const label b,
    const symmTensor& E
) const
{
    // H~_ijk E_jk = Y~^H (d_j eps_kim + d_k eps_jim) d_m E_jk
    //             = 2 Y~^H d x (E.d)
    return 2*f_.YHt[a][b]*(d_ ^ (E & d_));
}


void Foam::fdm::pairSubGridMatrix::addTo
(
    particleVelocitySystem& sys,
    const label p,
    const label q,
    const scalar scale
) const
{
    if (p == q)
    {
        FatalErrorInFunction
            << "A pair needs two different particles, got " << p << " twice"
            << exit(FatalError);
    }

    const label n = particleVelocitySystem::nDof;
    const label offset[2] = {n*p, n*q};

    for (label i = 0; i < nDof; ++i)
    {
        for (label j = 0; j < nDof; ++j)
        {
            if (R_[i][j] != 0)
            {
                sys.addEntry
                (
                    offset[i/n] + i % n,
                    offset[j/n] + j % n,
                    scale*R_[i][j]
                );
            }
        }
    }
}


// ************************************************************************* //
