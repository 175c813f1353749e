// Unit tests for Foam::fdm::andersonAcceleration

#include "andersonAcceleration.H"

#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <cmath>
#include <vector>

using namespace Foam;

namespace
{

// Linear fixed-point map G(x) = x - omega (A x - b), A = tridiag(-1, 2, -1)
// (1D Laplacian, n points): plain iteration contracts by
// 1 - omega lambda_min(A), close to 1 for large n -- the situation of the
// under-relaxed outer loop.
void applyMap(const scalarField& x, scalarField& g, const scalar omega)
{
    const label n = x.size();
    g.setSize(n);
    forAll(x, i)
    {
        const scalar left = i > 0 ? x[i - 1] : 0;
        const scalar right = i < n - 1 ? x[i + 1] : 0;
        const scalar Ax = 2*x[i] - left - right;
        g[i] = x[i] - omega*(Ax - 1.0);
    }
}

// Exact solution of A x = 1 with zero end values: x_i = (i+1)(n-i)/2
scalar errorOf(const scalarField& x)
{
    const label n = x.size();
    scalar e = 0;
    forAll(x, i)
    {
        e = max(e, mag(x[i] - 0.5*(i + 1)*(n - i)));
    }
    return e;
}

label iterationsToConverge
(
    const label depth,
    const label n,
    const bool restartOnGrowth = false
)
{
    fdm::andersonAcceleration aa
    (
        depth, [](List<scalar>&) {}, restartOnGrowth
    );
    scalarField x(n, Zero), g;
    for (label k = 1; k <= 20000; ++k)
    {
        applyMap(x, g, 0.45);
        if (depth > 0)
        {
            aa.update(x, g);
        }
        x = g;
        if (errorOf(x) < 1e-8*0.125*n*n)
        {
            return k;
        }
    }
    return -1;
}

} // namespace


TEST(andersonAcceleration, reachesTheFixedPointOfASlowLinearMap)
{
    // Reference: the exact solution of the linear system.  Plain
    // iteration needs O(n^2 log(1/tol)) steps, Anderson far fewer.
    const label n = 40;
    const label plain = iterationsToConverge(0, n);
    const label accelerated = iterationsToConverge(8, n);
    ASSERT_GT(plain, 0);
    ASSERT_GT(accelerated, 0);
    EXPECT_LT(accelerated, plain/10);

    // Restarted whenever the residual more than doubles, still far ahead
    // of plain iteration
    const label restarted = iterationsToConverge(8, n, true);
    ASSERT_GT(restarted, 0);
    EXPECT_LT(restarted, plain/10);
}


TEST(andersonAcceleration, restartsWhenTheResidualMoreThanDoubles)
{
    // Residuals f = g - x of norms 1, 0.5, 0.9 (grown by less than twice:
    // the history kept), then 2 (more than twice 0.9): that update drops
    // the history and returns the plain iterate; without restarts the
    // history is kept and the iterate extrapolated.
    for (const bool restart : {true, false})
    {
        fdm::andersonAcceleration aa(4, [](List<scalar>&) {}, restart);
        scalarField x(3, 0.0), g(3, 1.0);
        aa.update(x, g);
        x = scalarField(3, 1.0);
        g = scalarField(3, 1.5);
        aa.update(x, g);
        ASSERT_EQ(aa.size(), 1);
        x = scalarField(3, 1.5);
        g = scalarField(3, 2.4);
        aa.update(x, g);
        ASSERT_EQ(aa.size(), 2);
        x = scalarField(3, 2.4);
        g = scalarField(3, 4.4);
        aa.update(x, g);
        if (restart)
        {
            EXPECT_EQ(aa.size(), 0);
            EXPECT_DOUBLE_EQ(g[0], 4.4);
        }
        else
        {
            EXPECT_EQ(aa.size(), 3);
            EXPECT_GT(mag(g[0] - 4.4), 0.1);
        }
    }
}


TEST(andersonAcceleration, firstUpdateLeavesThePlainIterate)
{
    fdm::andersonAcceleration aa(3);
    const scalarField x(4, 1.0);
    scalarField g(4, 2.0);
    aa.update(x, g);
    for (const scalar v : g)
    {
        EXPECT_DOUBLE_EQ(v, 2.0);
    }
    EXPECT_EQ(aa.size(), 0);
}


TEST(andersonAcceleration, matchesAFullLeastSquaresSolveEveryIteration)
{
    // Reference: Walker & Ni's type-II update written out directly, the
    // least-squares problem min |f_k - dF gamma| solved from scratch (QR)
    // with the last m differences, rounded to single precision as the
    // update stores them, at every iteration.  The incremental
    // Gram matrix, the dropping of the oldest difference at full depth and
    // the reset must give the same iterates; n = 2500 spans several of the
    // blocks in which the update sums its dot products, the last partial.
    for (const label n : {30, 2500})
    {
        const label depth = 4;
        fdm::andersonAcceleration aa(depth);
        scalarField x(n, Zero), g;
        scalarField xr(n, Zero), gr;
        std::vector<Eigen::VectorXd> dF, dG;
        Eigen::VectorXd fPrev, gPrev;
        auto vec = [](const scalarField& v)
        {
            return Eigen::Map<const Eigen::VectorXd>(v.cdata(), v.size());
        };
        for (label k = 0; k < 25; ++k)
        {
            if (k == 12)
            {
                aa.reset();     // a new time step: history forgotten
                dF.clear();
                dG.clear();
                fPrev.resize(0);
            }
            applyMap(x, g, 0.45);
            aa.update(x, g);
            x = g;

            applyMap(xr, gr, 0.45);
            const Eigen::VectorXd gk = vec(gr), fk = gk - vec(xr);
            if (fPrev.size())
            {
                dF.push_back((fk - fPrev).cast<float>().cast<double>());
                dG.push_back((gk - gPrev).cast<float>().cast<double>());
                if (label(dF.size()) > depth)
                {
                    dF.erase(dF.begin());
                    dG.erase(dG.begin());
                }
            }
            fPrev = fk;
            gPrev = gk;
            Eigen::VectorXd next = gk;
            if (!dF.empty())
            {
                Eigen::MatrixXd F(n, dF.size()), G(n, dG.size());
                for (size_t i = 0; i < dF.size(); ++i)
                {
                    F.col(i) = dF[i];
                    G.col(i) = dG[i];
                }
                next -= G*F.colPivHouseholderQr().solve(fk);
            }
            forAll(xr, i) { xr[i] = next(i); }

            scalar diff = 0, scale = 0;
            forAll(x, i)
            {
                diff = max(diff, mag(x[i] - xr[i]));
                scale = max(scale, mag(xr[i]));
            }
            EXPECT_LT(diff, 1e-9*scale) << "n " << n << ", iteration " << k;
        }
        EXPECT_EQ(aa.size(), depth);
    }
}
