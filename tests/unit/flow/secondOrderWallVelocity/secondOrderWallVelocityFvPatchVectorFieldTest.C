// Unit test of the secondOrderWallVelocity condition on a channel box:
// the wall-normal gradient of a quadratic profile is exact, the matrix
// coefficients reproduce that gradient, and the discrete plane Poiseuille
// problem solved with it gives the exact parabola at the cell centres
// (the stock two-point wall shifts it by G Delta^2/(8 nu)).

#include "secondOrderWallVelocityFvPatchVectorField.H"
#include "fvm.H"
#include "fvc.H"
#include "unitTestCase.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const scalar uWall = 0.3;

//- The parabola u_x = uWall + y (1 - y): du/dy = 1 at y = 0, -1 at y = 1
scalar parabola(const scalar y) { return uWall + y*(1 - y); }

struct channel
{
    unitTest::scratchCase sc;
    autoPtr<fvMesh> mesh;
    tmp<volVectorField> tU;

    channel(const word& name, const word& wallType)
    :
        sc(name)
    {
        sc.writeFile
        (
            "system/fvSolution",
            "solvers { U { solver PBiCGStab; preconditioner diagonal;"
            " tolerance 1e-15; relTol 0; } }"
        );
        mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(2, 8, 2), 0.125,
            unitTest::channelSides()
        );
        tU = unitTest::zeroField<vector>(*mesh, "U", dimVelocity, wallType);
        for (const word side : {"yMin", "yMax"})
        {
            tU.ref().boundaryFieldRef()[mesh->boundaryMesh().findPatchID(side)]
                == vector(uWall, 0, 0);
        }
    }

    const fvPatchVectorField& wall(const word& side) const
    {
        return tU().boundaryField()[mesh->boundaryMesh().findPatchID(side)];
    }
};

} // End anonymous namespace


TEST(secondOrderWallVelocity, quadraticProfileGradientIsExact)
{
    channel ch("secondOrderWallVelocity", "secondOrderWallVelocity");
    volVectorField& U = ch.tU.ref();
    forAll(U, c)
    {
        U[c] = vector(parabola(ch.mesh->C()[c].y()), 0, 0);
    }
    U.correctBoundaryConditions();

    // Along the outward normal: -du/dy at y = 0, +du/dy at y = 1
    for (const word side : {"yMin", "yMax"})
    {
        const fvPatchVectorField& w = ch.wall(side);
        const vectorField sn(w.snGrad());
        const vectorField coeffs
        (
            cmptMultiply(w.gradientInternalCoeffs(), w.patchInternalField())
          + w.gradientBoundaryCoeffs()
        );
        forAll(sn, f)
        {
            EXPECT_NEAR(sn[f].x(), -1, 1e-12) << side;
            EXPECT_NEAR(coeffs[f].x(), sn[f].x(), 1e-12) << side;
        }
    }
}


TEST(secondOrderWallVelocity, poiseuilleSolutionIsTheExactParabola)
{
    // nu u'' = -2 nu: the parabola above with nu = 1
    SolverPerformance<scalar>::debug = 0;
    SolverPerformance<vector>::debug = 0;
    for (const word type : {"secondOrderWallVelocity", "fixedValue"})
    {
        channel ch("secondOrderWallVelocitySolve", type);
        volVectorField& U = ch.tU.ref();
        const dimensionedVector G("G", dimVelocity/dimArea, vector(-2, 0, 0));
        for (label outer = 0; outer < 40; ++outer)
        {
            fvVectorMatrix UEqn(fvm::laplacian(U) == G);
            UEqn.solve();
        }
        scalar err = 0;
        forAll(U, c)
        {
            err = max(err, mag(U[c].x() - parabola(ch.mesh->C()[c].y())));
        }
        if (type == "fixedValue")
        {
            // G Delta^2/(8 nu) = 2/64/8: the stock wall's shift
            EXPECT_NEAR(err, 2*0.125*0.125/8, 1e-9);
        }
        else
        {
            EXPECT_LT(err, 1e-10);
        }
    }
}
