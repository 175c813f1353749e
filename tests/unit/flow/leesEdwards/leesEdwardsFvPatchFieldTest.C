// Unit test of the leesEdwards coupling on a unit periodic box sheared at
// gammaDot = 1 (offset s = t): at an offset of whole cells the neighbour
// of a face is exactly the cell that many cells along, at offset 0 the
// coupling is the cyclic one; the uniform shear u_x = y - 1/2 solves the
// Laplace problem to round-off at a fractional offset (the jump); the
// sheared sinusoid phi = sin(k (x - s y)), periodic in the sheared
// lattice, solves -lap phi = k^2 (1 + s^2) phi: second order at an offset
// of whole cells, within 2 % at a fractional one (the first-order
// interpolation along the sheared faces).

#include "shearedBox.H"
#include "fvm.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

//- The largest |a - b| after removing each field's mean (a periodic
//  Laplace problem fixes its solution up to a constant)
template<class Type>
scalar meanFreeDifference(const Field<Type>& a, const Field<Type>& b)
{
    return max(mag((a - average(a)) - (b - average(b))));
}

} // End anonymous namespace


TEST(leesEdwards, wholeCellOffsetTakesTheCellAlong)
{
    // s = 0.25 = 2 cells of 1/8; zero offset is the cyclic coupling
    for (const scalar t : {0.0, 0.25, 1.25})
    {
        shearedBox box("leesEdwardsWholeCells", 8, t);
        tmp<volScalarField> tpsi(box.field<scalar>("psi"));
        volScalarField& psi = tpsi.ref();
        forAll(psi, c)
        {
            psi[c] = c;     // every cell its own value
        }
        const label m = std::lround(8*(t - std::floor(t)));
        for (const word name : {"yMin", "yMax"})
        {
            const fvPatchScalarField& side = box.side(psi, name);
            const scalarField pnf(side.patchNeighbourField());
            const vectorField& Cf = side.patch().Cf();
            const bool upper = name == "yMax";
            forAll(pnf, f)
            {
                // The cell of the other side's row at x -+ m cells
                const scalar x = Cf[f].x() + (upper ? -m : m)/8.0;
                const scalar xw = x - std::floor(x);
                const label i = label(std::floor(8*xw));
                const label j = upper ? 0 : 7;
                const label k = label(std::floor(8*Cf[f].z()));
                EXPECT_NEAR(pnf[f], i + 8*(j + 8*k), 1e-9)
                    << name << " face " << f << " at t " << t;
            }
        }
    }
}


TEST(leesEdwards, uniformShearIsExactAtAFractionalOffset)
{
    SolverPerformance<vector>::debug = 0;
    shearedBox box("leesEdwardsShear", 8, 0.3 + 1.0/48);
    tmp<volVectorField> tU(box.field<vector>("U"));
    volVectorField& U = tU.ref();
    for (label outer = 0; outer < 3; ++outer)
    {
        fvVectorMatrix UEqn(fvm::laplacian(U));
        UEqn.solve();
    }
    vectorField exact(U.size(), Zero);
    forAll(exact, c)
    {
        exact[c].x() = box.mesh->C()[c].y() - 0.5;
    }
    EXPECT_LT(meanFreeDifference(U.primitiveField(), exact), 1e-10);
}


//- Largest and mean error of the sheared sinusoid at offset t on n^3 cells
std::pair<scalar, scalar> sinusoidErrors(const label n, const scalar t)
{
    const scalar k = constant::mathematical::twoPi;
    shearedBox box("leesEdwardsSinusoid", n, t);
    tmp<volScalarField> tpsi(box.field<scalar>("psi"));
    volScalarField& psi = tpsi.ref();
    const vectorField& C = box.mesh->C().primitiveField();
    const scalarField exact(Foam::sin(k*(C.component(0) - t*C.component(1))));
    for (label outer = 0; outer < 3; ++outer)
    {
        fvScalarMatrix eqn(-fvm::laplacian(psi));
        eqn.source() += k*k*(1 + t*t)*exact*box.mesh->V();
        eqn.solve();
    }
    const scalarField d
    (
        (psi.primitiveField() - average(psi.primitiveField()))
      - (exact - average(exact))
    );
    return {max(mag(d)), average(mag(d))};
}


TEST(leesEdwards, shearedSinusoidConvergesWithTheMesh)
{
    SolverPerformance<scalar>::debug = 0;
    // An offset of whole cells (t = 1/4: 2, 4, 8 cells) is exact
    // coupling: second order as the cyclic box, the error a quarter per
    // halving of the spacing
    const auto w8 = sinusoidErrors(8, 0.25);
    const auto w16 = sinusoidErrors(16, 0.25);
    const auto w32 = sinusoidErrors(32, 0.25);
    EXPECT_NEAR(w16.first/w8.first, 0.25, 0.02);
    EXPECT_NEAR(w32.first/w16.first, 0.25, 0.02);

    // A fractional offset (t = 0.3 + 1/48: 2.57, 5.13, 10.27 cells):
    // the linear interpolation along the sheared faces errs by
    // w(1 - w) Delta^2 phi_xx/2, a first-order flux error in the rows
    // next to them, so the largest error stays near those rows at
    // 1-2 % of the amplitude while the mean error falls with the bulk's
    const scalar t = 0.3 + 1.0/48;
    const auto f8 = sinusoidErrors(8, t);
    const auto f16 = sinusoidErrors(16, t);
    const auto f32 = sinusoidErrors(32, t);
    Info<< "sheared sinusoid at offset " << t << ", n = 8, 16, 32:"
        << " largest error " << f8.first << " " << f16.first << " "
        << f32.first << ", mean " << f8.second << " " << f16.second << " "
        << f32.second << endl;
    EXPECT_LT(f16.second, 0.3*f8.second);
    EXPECT_LT(f32.second, 0.6*f16.second);
    EXPECT_LT(f32.first, 0.02);
}
