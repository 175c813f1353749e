/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "wallSubGridMatrix.H"
#include "resistanceTensorForms.H"
#include "particleSystemSink.H"
#include "error.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::fdm::wallSubGridMatrix::resistanceFunctions
Foam::fdm::wallSubGridMatrix::expand
(
    const wallBaseFunctions& b,
    const scalar a,
    const scalar epsilon
)
{
    resistanceFunctions f;
    f.XA = b.XA;
    f.YA = b.YA;
    f.YB = b.YB;
    f.YBt = -b.YB;
    f.XC = b.XC;
    f.YC = b.YC;
    f.XG = b.XG;
    f.XP = b.XP;

    // Eq 3.19: no SG correction for the ambient shear part of (3.17)
    const scalar h = (1 + epsilon)*a;
    f.YG = h*b.YA + 0.5*b.YB;
    f.YH = -h*b.YB - 0.5*b.YC;

    return f;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::wallSubGridMatrix::wallSubGridMatrix
(
    const wallBaseFunctions& base,
    const scalar a,
    const scalar epsilon,
    const vector& d
)
:
    d_(d),
    f_(expand(base, a, epsilon))
{
    const scalar magD = mag(d);
    if (magD < VSMALL || a <= 0)
    {
        FatalErrorInFunction
            << "Degenerate particle-wall geometry: a = " << a
            << ", d = " << d << exit(FatalError);
    }
    d_ /= magD;

    // Appendix A (11) forms: force row A, B~; torque row B, C
    setBlock(R_, 0, 0, axialForm(f_.XA, f_.YA, d_));
    setBlock(R_, 0, 3, epsilonForm(f_.YBt, d_));
    setBlock(R_, 3, 0, epsilonForm(f_.YB, d_));
    setBlock(R_, 3, 3, axialForm(f_.XC, f_.YC, d_));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::wallSubGridMatrix::forceTorque
(
    const vector& U,
    const vector& W,
    const vector& Uw,
    vector& F,
    vector& T
) const
{
    const vector Ur(U - Uw);
    scalar u[nDof];
    for (label k = 0; k < 3; ++k)
    {
        u[k] = Ur[k];
        u[3 + k] = W[k];
    }
    for (label i = 0; i < 3; ++i)
    {
        scalar sF = 0, sT = 0;
        for (label j = 0; j < nDof; ++j)
        {
            sF += R_[i][j]*u[j];
            sT += R_[3 + i][j]*u[j];
        }
        F[i] = -sF;
        T[i] = -sT;
    }
}


Foam::symmTensor Foam::fdm::wallSubGridMatrix::stresslet
(
    const vector& U,
    const vector& W,
    const vector& Uw
) const
{
    return -(contractG(f_.XG, f_.YG, d_, U - Uw) + contractH(f_.YH, d_, W));
}


Foam::scalar Foam::fdm::wallSubGridMatrix::dipoleTrace
(
    const vector& U,
    const vector& Uw
) const
{
    return -f_.XP*((U - Uw) & d_);
}


Foam::vector Foam::fdm::wallSubGridMatrix::strainForce
(
    const symmTensor& E
) const
{
    // X^G~ = X^G, Y^G~ = Y^G (reciprocity; verified for the FDM matrix in
    // section 3.4)
    return strainContractG(f_.XG, f_.YG, d_, E);
}


Foam::vector Foam::fdm::wallSubGridMatrix::strainTorque
(
    const symmTensor& E
) const
{
    // Y^H~ = Y^H
    return strainContractH(f_.YH, d_, E);
}


void Foam::fdm::wallSubGridMatrix::addTo
(
    particleSystemSink& sys,
    const label p,
    const vector& Uw,
    const scalar scale
) const
{
    const label o = particleSystemSink::nDof*p;
    for (label i = 0; i < nDof; ++i)
    {
        for (label j = 0; j < nDof; ++j)
        {
            if (R_[i][j] != 0)
            {
                sys.addEntry(o + i, o + j, scale*R_[i][j]);
            }
        }
    }

    // The wall-velocity part of -eta R (u - Uw) is a known force
    vector F(Zero), T(Zero);
    for (label i = 0; i < 3; ++i)
    {
        for (label j = 0; j < 3; ++j)
        {
            F[i] += R_[i][j]*Uw[j];
            T[i] += R_[3 + i][j]*Uw[j];
        }
    }
    sys.addRhs(p, scale*F, scale*T);
}


// ************************************************************************* //
