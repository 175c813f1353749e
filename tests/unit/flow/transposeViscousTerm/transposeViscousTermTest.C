// Unit test of fdm::transposeViscousTerm: on a channel box (walls with a
// moving top, cyclic sides) and an arbitrary velocity field, the one-pass
// term equals OpenFOAM's fvc::div(nu*dev(T(fvc::grad(U)))) bit for bit,
// and a divergence scheme other than Gauss linear is OpenFOAM's own.

#include "transposeViscousTerm.H"
#include "fvc.H"
#include "unitTestCase.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- A velocity with every gradient component nonzero and moving walls
tmp<volVectorField> wavyVelocity(const fvMesh& mesh)
{
    tmp<volVectorField> tU =
        unitTest::zeroField<vector>(mesh, "U", dimVelocity, "fixedValue");
    volVectorField& U = tU.ref();
    forAll(U, c)
    {
        const point& x = mesh.C()[c];
        U[c] = vector
        (
            Foam::sin(2*x.y()) + 0.3*Foam::cos(x.x()*x.z()),
            0.2*Foam::sin(3*x.x())*x.y() + x.z(),
            x.y()*x.y() - 0.7*Foam::cos(2*x.z() + x.x())
        );
    }
    forAll(U.boundaryField(), patchi)
    {
        if (!U.boundaryField()[patchi].coupled())
        {
            const vectorField& Cf = mesh.Cf().boundaryField()[patchi];
            vectorField& Ub = U.boundaryFieldRef()[patchi];
            forAll(Ub, i)
            {
                Ub[i] = vector(Cf[i].y() + 0.1*Cf[i].x(), 0, -0.5*Cf[i].z());
            }
        }
    }
    U.correctBoundaryConditions();
    return tU;
}

} // End anonymous namespace


TEST(transposeViscousTerm, equalsOpenFOAMsExpressionBitForBit)
{
    unitTest::scratchCase sc("transposeViscousTerm");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(4, 5, 3), 0.25, unitTest::channelSides()
    );
    const volVectorField U(wavyVelocity(*mesh));
    const dimensionedScalar nu("nu", dimViscosity, 0.37);

    ASSERT_TRUE(fdm::transposeViscousTermIsLinear(*mesh));
    const volVectorField fused(fdm::transposeViscousTerm(nu, U));
    const volVectorField reference(fvc::div(nu*dev(T(fvc::grad(U)))));

    scalar largest = 0;
    forAll(fused, c)
    {
        for (direction d = 0; d < 3; ++d)
        {
            EXPECT_EQ(fused[c][d], reference[c][d]) << "cell " << c;
        }
        largest = max(largest, mag(reference[c]));
    }
    // The field is not trivially zero: the test compares something
    EXPECT_GT(largest, 0.1);
    EXPECT_EQ(fused.dimensions(), reference.dimensions());
}


TEST(transposeViscousTerm, otherSchemesAreOpenFOAMsOwn)
{
    // A gradient or a divergence scheme other than Gauss linear
    const std::vector<std::string> variants
    {
        "gradSchemes { default Gauss linear; grad(U) leastSquares; }"
        " divSchemes { default Gauss linear; }",
        "gradSchemes { default Gauss linear; }"
        " divSchemes { default none; div((nu*dev(T(grad(U))))) Gauss"
        " midPoint; }"
    };
    for (const std::string& schemes : variants)
    {
        unitTest::scratchCase sc("transposeViscousTermOther");
        sc.writeFile
        (
            "system/fvSchemes",
            "ddtSchemes { default steadyState; } " + schemes
          + " laplacianSchemes { default Gauss linear uncorrected; }"
            " interpolationSchemes { default linear; }"
            " snGradSchemes { default uncorrected; }"
        );
        autoPtr<fvMesh> mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(4, 5, 3), 0.25,
            unitTest::channelSides()
        );
        const volVectorField U(wavyVelocity(*mesh));
        const dimensionedScalar nu("nu", dimViscosity, 0.37);

        EXPECT_FALSE(fdm::transposeViscousTermIsLinear(*mesh)) << schemes;
        const volVectorField term(fdm::transposeViscousTerm(nu, U));
        const volVectorField reference
        (
            fvc::div(nu*dev(T(fvc::grad(U))))
        );
        forAll(term, c)
        {
            EXPECT_EQ(term[c], reference[c]) << "cell " << c << schemes;
        }
    }
}
