// Unit test of layerMeanCorrection on a channel box: the correction is
// uniform in each layer of cells and wall-parallel, the mesh's own
// finite-volume Laplacian of it (nu laplacian(delta), walls at zero) is the
// layer mean of the residual in every cell, the face fluxes stay
// divergence-free, and a mesh that is not a channel stops naming the
// setting.

#include "layerMeanCorrection.H"
#include "fvc.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(layerMeanCorrection, meshLaplacianOfTheCorrectionIsTheLayerMeanResidual)
{
    unitTest::scratchCase sc("layerMeanCorrection");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(3, 6, 2), 1.0/6, unitTest::channelSides()
    );
    tmp<volVectorField> tU =
        unitTest::zeroField<vector>(*mesh, "U", dimVelocity, "fixedValue");
    volVectorField& U = tU.ref();
    surfaceScalarField phi("phi", fvc::flux(U));
    const scalar nu = 0.3;

    // A residual that varies within layers, and its layer means by hand
    const vectorField& C = mesh->C();
    vectorField r(C.size());
    forAll(r, c)
    {
        const scalar x = C[c].x(), y = C[c].y(), z = C[c].z();
        r[c] = vector(1 + y + 0.3*(x - 0.25), 5, -2*y*y + (z - 1.0/6));
    }
    // x and z centres are symmetric about 0.25 and 1/6: the variations
    // within a layer average to zero
    auto layerMean = [](const point& c)
    {
        return vector(1 + c.y(), 0, -2*sqr(c.y()));
    };

    const layerMeanCorrection lm(*mesh, "SIMPLEC layerMeanCorrection");
    EXPECT_EQ(lm.nLayers(), 6);
    lm.correct(r, nu, U, phi);

    const volVectorField lapU(nu*fvc::laplacian(U));
    scalar maxDiv = 0;
    const scalarField divPhi(fvc::div(phi)().primitiveField());
    forAll(C, c)
    {
        EXPECT_EQ(U[c].y(), 0) << c;
        EXPECT_NEAR(lapU[c].x(), layerMean(C[c]).x(), 1e-10) << c;
        EXPECT_NEAR(lapU[c].z(), layerMean(C[c]).z(), 1e-10) << c;
        maxDiv = max(maxDiv, mag(divPhi[c]));
        // Uniform in the layer: equal to the first cell of the same layer
        for (label d = 0; d < c; ++d)
        {
            if (mag(C[d].y() - C[c].y()) < 1e-9)
            {
                EXPECT_EQ(U[d], U[c]);
                break;
            }
        }
    }
    EXPECT_LT(maxDiv, 1e-12);
    EXPECT_GT(mag(U[0]), 1e-3);
}


TEST(layerMeanCorrection, aMeshThatIsNotAChannelStops)
{
    unitTest::scratchCase sc("layerMeanCorrectionBox");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(2, 2, 2), 0.5, wordList(6, "wall")
    );
    const std::string msg = unitTest::errorOf([&]
    {
        layerMeanCorrection(*mesh, "SIMPLEC layerMeanCorrection");
    });
    EXPECT_NE(msg.find("SIMPLEC layerMeanCorrection"), std::string::npos)
        << msg;
}
