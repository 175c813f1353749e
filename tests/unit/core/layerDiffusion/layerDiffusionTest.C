// Unit tests for the layer-averaged diffusion solve (Poiseuille and Couette
// profiles between two walls)

#include "layerDiffusion.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

// n uniform layers of thickness H/n between walls at 0 and H
scalarField layerCentres(const label n, const scalar H)
{
    scalarField y(n);
    forAll(y, k)
    {
        y[k] = (k + 0.5)*H/n;
    }
    return y;
}

} // namespace


TEST(layerDiffusion, uniformForceGivesThePoiseuilleParabola)
{
    // nu u'' = -G, u(0) = u(H) = 0: u = G y (H - y)/(2 nu).  The
    // finite-volume scheme is exact for a quadratic in the interior; at the
    // half-cell next to a wall the one-sided difference gives a second-order
    // error of G h^2/(8 nu)-size.
    const scalar H = 2, nu = 0.5, G = 3;
    for (const label n : {10, 20, 40})
    {
        const scalarField y(layerCentres(n, H));
        const scalarField u =
            fdm::solveLayerDiffusion(y, 0, H, nu, scalarField(n, -G));
        const scalar h = H/n;
        forAll(y, k)
        {
            const scalar exact = G*y[k]*(H - y[k])/(2*nu);
            EXPECT_NEAR(u[k], exact, G*h*h/nu) << "n " << n << " k " << k;
        }
    }
}


TEST(layerDiffusion, residualOfTheDiscreteOperatorVanishes)
{
    // Non-uniform layers: the solution satisfies the three-point scheme
    // it is defined by, for an arbitrary right-hand side
    const scalarField y({0.1, 0.3, 0.35, 0.9, 1.4, 1.9});
    const scalar yLow = 0, yHigh = 2, nu = 1.7;
    const scalarField r({1, -2, 0.5, 3, -1, 0.25});
    const scalarField u = fdm::solveLayerDiffusion(y, yLow, yHigh, nu, r);
    const label n = y.size();
    for (label k = 0; k < n; ++k)
    {
        const scalar uBelow = k == 0 ? 0 : u[k - 1];
        const scalar uAbove = k == n - 1 ? 0 : u[k + 1];
        const scalar yBelow = k == 0 ? yLow : y[k - 1];
        const scalar yAbove = k == n - 1 ? yHigh : y[k + 1];
        const scalar fBelow = k == 0 ? yLow : 0.5*(y[k - 1] + y[k]);
        const scalar fAbove = k == n - 1 ? yHigh : 0.5*(y[k] + y[k + 1]);
        const scalar lhs =
            nu*((uAbove - u[k])/(yAbove - y[k]) - (u[k] - uBelow)/(y[k] - yBelow))
           /(fAbove - fBelow);
        EXPECT_NEAR(lhs, r[k], 1e-12);
    }
}


TEST(layerDiffusion, zeroRightHandSideGivesZero)
{
    const scalarField y(layerCentres(7, 1));
    const scalarField u =
        fdm::solveLayerDiffusion(y, 0, 1, 2, scalarField(7, 0));
    forAll(u, k)
    {
        EXPECT_EQ(u[k], 0);
    }
}
