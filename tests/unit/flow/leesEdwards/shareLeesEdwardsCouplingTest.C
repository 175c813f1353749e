// Unit test of shareLeesEdwardsCoupling on a unit periodic box sheared at
// gammaDot = 1 (offset s = t, fractional here): fields derived from the
// velocity (a product, as HbyA and rAU grad p are made) come with cyclic
// patch fields, whose neighbours across the sheared faces are the cells at
// offset 0; shared, their neighbours are U's shifted ones, with U's jump
// for a velocity and without it for others, and a tensor field (the
// velocity gradient) is shifted as a scalar is.

#include "shearedBox.H"
#include "shareLeesEdwardsCoupling.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- The neighbour values of field f across side yMin or yMax
template<class Type>
Field<Type> across
(
    const shearedBox& box,
    const GeometricField<Type, fvPatchField, volMesh>& f,
    const word& side
)
{
    const label patchi = box.mesh->boundaryMesh().findPatchID(side);
    return f.boundaryField()[patchi].patchNeighbourField();
}


//- Largest difference of the neighbour values of a and b, b's shifted by
//  -+bShift on yMin and yMax
scalar neighbourDifference
(
    const shearedBox& box,
    const volVectorField& a,
    const volVectorField& b,
    const vector& bShift = Zero
)
{
    scalar d = 0;
    for (const word side : {"yMin", "yMax"})
    {
        const scalar sign = side == "yMax" ? 1 : -1;
        d = max
        (
            d,
            max(mag(across(box, a, side) - (across(box, b, side) - sign*bShift)))
        );
    }
    return d;
}

} // End anonymous namespace


TEST(shareLeesEdwardsCoupling, derivedVectorsAreShiftedAsTheVelocity)
{
    shearedBox box("shareLeesEdwardsVectors", 8, 0.25 + 1.0/48);
    tmp<volVectorField> tU(box.field<vector>("U"));
    volVectorField& U = tU.ref();
    forAll(U, c)
    {
        U[c] = vector(c, 2*c % 7, 3*c % 5);
    }

    // A product has cyclic patch fields: unshifted, no jump
    tmp<volVectorField> tH(1.0*U);
    EXPECT_GT(neighbourDifference(box, tH(), U), 1.0);

    // Shared as a velocity: U's neighbours, jump included
    fdm::shareLeesEdwardsCoupling(tH.ref(), U, true);
    EXPECT_LT(neighbourDifference(box, tH(), U), 1e-12);

    // Shared as another vector (rAU grad p): shifted, without the jump
    // (U's +-gammaDot L_y = +-1 along x on the upper/lower side)
    const volVectorField G(fdm::shareLeesEdwardsCoupling(1.0*U, U));
    EXPECT_LT(neighbourDifference(box, G, U, vector(1, 0, 0)), 1e-12);
}


TEST(shareLeesEdwardsCoupling, tensorsAreShiftedAsScalars)
{
    shearedBox box("shareLeesEdwardsTensors", 8, 0.25 + 1.0/48);
    tmp<volVectorField> tU(box.field<vector>("U"));
    tmp<volScalarField> tpsi(box.field<scalar>("psi"));
    volScalarField& psi = tpsi.ref();
    forAll(psi, c)
    {
        psi[c] = c;
    }
    const volTensorField T
    (
        fdm::shareLeesEdwardsCoupling
        (
            psi*dimensionedTensor("I", dimless, tensor::I), tU()
        )
    );
    for (const word side : {"yMin", "yMax"})
    {
        EXPECT_LT
        (
            max(mag(across(box, T, side) - tensor::I*across(box, psi, side))),
            1e-12
        ) << side;
    }
}
