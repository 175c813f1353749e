/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "pairSubGridMatrix.H"
#include "resistanceTensorForms.H"
#include "particleSystemSink.H"
#include "error.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::fdm::pairSubGridMatrix::resistanceFunctions
Foam::fdm::pairSubGridMatrix::expand
(
    const pairBaseFunctions& b,
    const scalar r
)
{
    // Relations of thesis section 3.3.3.  Index 0 is
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
    // in 3.3.3 (pairSubGridMatrix.H: the reading of the relations)
    f.XGt[0][0] = b.XG11;
    f.XGt[0][1] = -b.XG11 - r*b.XA21;
    f.XGt[1][0] = -b.XG11;
    f.XGt[1][1] = b.XG11 + r*b.XA21;
    f.YGt[0][0] = b.YG11;
    f.YGt[0][1] = -b.YG11 - 0.5*r*b.YA21;
    f.YGt[1][0] = -b.YG11;
    f.YGt[1][1] = b.YG11 + 0.5*r*b.YA21;

    // H (stresslet rows, Omega columns); base Y_21^H
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
            // Force row: A (U column), B~ (Omega column); torque row: B, C
            setBlock(R_, 6*a, 6*b, axialForm(f_.XA[a][b], f_.YA[a][b], d_));
            setBlock(R_, 6*a, 6*b + 3, epsilonForm(f_.YBt[a][b], d_));
            setBlock(R_, 6*a + 3, 6*b, epsilonForm(f_.YB[a][b], d_));
            setBlock
            (
                R_, 6*a + 3, 6*b + 3, axialForm(f_.XC[a][b], f_.YC[a][b], d_)
            );
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
    return contractG(f_.XG[a][b], f_.YG[a][b], d_, U);
}


Foam::symmTensor Foam::fdm::pairSubGridMatrix::H
(
    const label a,
    const label b,
    const vector& W
) const
{
    return contractH(f_.YH[a][b], d_, W);
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
    return strainContractG(f_.XGt[a][b], f_.YGt[a][b], d_, E);
}


Foam::vector Foam::fdm::pairSubGridMatrix::strainTorque
(
    const label a,
    const label b,
    const symmTensor& E
) const
{
    return strainContractH(f_.YHt[a][b], d_, E);
}


void Foam::fdm::pairSubGridMatrix::addTo
(
    particleSystemSink& sys,
    const label p,
    const label q,
    const scalar scale,
    const vector& qImageVelocity
) const
{
    if (p == q)
    {
        FatalErrorInFunction
            << "A pair needs two different particles, got " << p << " twice"
            << exit(FatalError);
    }

    const label n = particleSystemSink::nDof;
    const label offset[2] = {n*p, n*q};

    if (qImageVelocity != vector::zero)
    {
        vector F1, T1, F2, T2;
        forceTorque(Zero, Zero, qImageVelocity, Zero, F1, T1, F2, T2);
        sys.addRhs(p, scale*F1, scale*T1);
        sys.addRhs(q, scale*F2, scale*T2);
    }

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
