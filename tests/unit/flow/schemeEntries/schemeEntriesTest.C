// Unit test of fdm::isGaussLinear and fdm::isUncorrectedLaplacian on scheme
// entries, and of what fdmSuspensionFoam relies on when the Laplacian is
// uncorrected: its matrix is the same whatever the cell values of the field,
// so that it can be formed once per step, as long as the boundary
// conditions give their coefficients from the boundary values alone.

#include "schemeEntries.H"
#include "fvm.H"
#include "IStringStream.H"
#include "unitTestCase.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- A dictionary holding the entry "scheme" with the given text, read as
//  fvSchemes is (the ITstream constructors differ between OpenFOAM lines)
dictionary schemeDict(const std::string& text)
{
    IStringStream is("scheme " + text + ";");
    return dictionary(is);
}

} // End anonymous namespace


TEST(schemeEntries, gaussLinear)
{
    dictionary linear(schemeDict("Gauss linear"));
    dictionary leastSquares(schemeDict("leastSquares"));
    dictionary limited(schemeDict("cellLimited Gauss linear 1"));
    ITstream& linearEntry = linear.lookup("scheme");
    EXPECT_TRUE(fdm::isGaussLinear(linearEntry));
    EXPECT_FALSE(fdm::isGaussLinear(leastSquares.lookup("scheme")));
    EXPECT_FALSE(fdm::isGaussLinear(limited.lookup("scheme")));
    // The entry can be read again after the query
    word first, second;
    linearEntry >> first >> second;
    EXPECT_EQ(second, "linear");
}


TEST(schemeEntries, uncorrectedLaplacian)
{
    for (const char* text : {"Gauss linear uncorrected", "Gauss linear orthogonal"})
    {
        dictionary d(schemeDict(text));
        EXPECT_TRUE(fdm::isUncorrectedLaplacian(d.lookup("scheme"))) << text;
    }
    for
    (
        const char* text
      : {"Gauss linear corrected", "Gauss linear limited corrected 0.5",
         "Gauss linear limited 0", "uncorrected"}
    )
    {
        dictionary d(schemeDict(text));
        EXPECT_FALSE(fdm::isUncorrectedLaplacian(d.lookup("scheme"))) << text;
    }
}


TEST(schemeEntries, uncorrectedLaplacianIgnoresCellValues)
{
    unitTest::scratchCase sc("schemeEntries");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(4, 5, 3), 0.25, unitTest::channelSides()
    );
    ITstream& scheme = mesh->laplacianScheme("laplacian(nu,U)");
    ASSERT_TRUE(fdm::isUncorrectedLaplacian(scheme));

    const dimensionedScalar nu("nu", dimViscosity, 0.37);
    tmp<volVectorField> tU =
        unitTest::zeroField<vector>(*mesh, "U", dimVelocity, "fixedValue");
    volVectorField& U = tU.ref();
    forAll(U.boundaryField(), patchi)
    {
        if (!U.boundaryField()[patchi].coupled())
        {
            U.boundaryFieldRef()[patchi] == vector(1, 0, 0.5);
        }
    }
    const fvVectorMatrix first(-fvm::laplacian(nu, U));
    forAll(U, c)
    {
        U[c] = vector(mesh->C()[c].y(), -mesh->C()[c].x(), 3.0);
    }
    U.correctBoundaryConditions();
    const fvVectorMatrix second(-fvm::laplacian(nu, U));

    EXPECT_EQ(first.diag(), second.diag());
    EXPECT_EQ(first.upper(), second.upper());
    EXPECT_EQ(first.source(), second.source());
    forAll(first.internalCoeffs(), patchi)
    {
        EXPECT_EQ(first.internalCoeffs()[patchi], second.internalCoeffs()[patchi]);
        EXPECT_EQ(first.boundaryCoeffs()[patchi], second.boundaryCoeffs()[patchi]);
    }
    // The walls' values are in the matrix: it is not trivially empty
    EXPECT_GT(gMax(mag(first.boundaryCoeffs()[2])), 0);
}


TEST(schemeEntries, boundaryCoeffsFromValuesOnly)
{
    unitTest::scratchCase sc("schemeEntriesWalls");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(4, 5, 3), 0.25, unitTest::channelSides()
    );
    const dimensionedScalar nu("nu", dimViscosity, 0.37);
    tmp<volVectorField> tFixed =
        unitTest::zeroField<vector>(*mesh, "U", dimVelocity, "fixedValue");
    tmp<volVectorField> tSecondOrder = unitTest::zeroField<vector>
    (
        *mesh, "U", dimVelocity, "secondOrderWallVelocity"
    );
    EXPECT_TRUE(fdm::boundaryCoeffsFromValuesOnly(tFixed()));
    EXPECT_FALSE(fdm::boundaryCoeffsFromValuesOnly(tSecondOrder()));

    // Why: the second-order wall condition takes the cell values into the
    // Laplacian's boundary coefficients
    volVectorField& U = tSecondOrder.ref();
    const fvVectorMatrix first(-fvm::laplacian(nu, U));
    forAll(U, c)
    {
        U[c] = vector(mesh->C()[c].y(), 0, 0);
    }
    U.correctBoundaryConditions();
    const fvVectorMatrix second(-fvm::laplacian(nu, U));
    scalar change = 0;
    forAll(first.boundaryCoeffs(), patchi)
    {
        change = max
        (
            change,
            gMax(mag(first.boundaryCoeffs()[patchi]
              - second.boundaryCoeffs()[patchi]))
        );
    }
    EXPECT_GT(change, 0);
}
