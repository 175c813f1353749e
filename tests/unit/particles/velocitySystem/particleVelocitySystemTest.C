// Unit tests for Foam::fdm::particleVelocitySystem (thesis 1, eq 2.43),
// including its factorisation kept while the matrix stays the same

#include "particleVelocitySystem.H"
#include "rigidBodyMoments.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

using namespace Foam;

namespace
{

fdm::rigidBodyMoments someMoments(const scalar s)
{
    // Moments of four weighted points: SPD, with a first moment and an
    // anisotropic inertia like an off-centre lattice sphere
    fdm::rigidBodyMoments m;
    m.add(1.0*s, vector(0.5, 0.1, -0.2), 1);
    m.add(0.8*s, vector(-0.4, 0.3, 0.1), 1);
    m.add(0.6*s, vector(0.1, -0.5, 0.4), 1);
    m.add(0.9*s, vector(-0.2, 0.2, -0.6), 1);
    return m;
}

// A symmetric positive definite pair coupling between particles 0 and 1:
// k (e e^T) on the translational unknowns with the sign pattern
// [[1, -1], [-1, 1]] of a lubrication resistance
void addPairCoupling(fdm::particleVelocitySystem& sys, const scalar k)
{
    const vector e(0.6, 0.0, 0.8);
    for (direction a = 0; a < 3; ++a)
    {
        for (direction b = 0; b < 3; ++b)
        {
            const scalar v = k*e[a]*e[b];
            sys.addEntry(a, b, v);
            sys.addEntry(6 + a, 6 + b, v);
            sys.addEntry(a, 6 + b, -v);
            sys.addEntry(6 + a, b, -v);
        }
    }
}

} // namespace


TEST(particleVelocitySystem, recoversKnownVelocitiesOfACoupledSystem)
{
    // Reference: b = A u_ref computed by the system's own product; solving
    // A u = b must return u_ref to the solver tolerance.
    fdm::particleVelocitySystem sys(3);
    for (label i = 0; i < 3; ++i)
    {
        sys.addMass(i, someMoments(1 + i), 1/0.04);
    }
    addPairCoupling(sys, 250);

    const List<vector> Uref({vector(1, 2, 3), vector(-1, 0.5, 0),
                             vector(0, 0, -2)});
    const List<vector> Wref({vector(0.1, 0, 0), vector(0, -0.3, 0.2),
                             vector(1, 1, 1)});
    List<vector> f, t;
    sys.multiply(Uref, Wref, f, t);
    forAll(f, i)
    {
        sys.addRhs(i, f[i], t[i]);
    }

    List<vector> U(3, Zero), W(3, Zero);
    const auto info = sys.solve(1e-12, 100, U, W);
    EXPECT_TRUE(info.converged);
    EXPECT_GT(info.iterations, 0);
    forAll(U, i)
    {
        EXPECT_LT(mag(U[i] - Uref[i]), 1e-9);
        EXPECT_LT(mag(W[i] - Wref[i]), 1e-9);
    }
}


TEST(particleVelocitySystem, eliminatesPrescribedVelocities)
{
    // Particle 0 is held fixed, particle 1 is free; the pair coupling makes
    // the free particle feel the fixed one.  Reference as above: the
    // residual of the full system vanishes on the free rows.
    fdm::particleVelocitySystem sys(2);
    sys.addMass(0, someMoments(1), 10);
    sys.addMass(1, someMoments(2), 10);
    addPairCoupling(sys, 40);

    const List<vector> Uref({vector(0.2, 0, -0.1), vector(1, -2, 0.5)});
    const List<vector> Wref({vector(0, 0, 0), vector(0.3, 0.1, -0.2)});
    List<vector> f, t;
    sys.multiply(Uref, Wref, f, t);
    // Only the free particle's equations are known; the fixed particle's
    // force is whatever holds it (not given to the solver).
    sys.addRhs(1, f[1], t[1]);
    for (direction d = 0; d < 3; ++d)
    {
        sys.prescribe(0, d, Uref[0][d]);
        sys.prescribe(0, 3 + d, Wref[0][d]);
    }

    List<vector> U(2, Zero), W(2, Zero);
    const auto info = sys.solve(1e-12, 100, U, W);
    EXPECT_TRUE(info.converged);
    EXPECT_LT(mag(U[0] - Uref[0]), 1e-14);
    EXPECT_LT(mag(U[1] - Uref[1]), 1e-9);
    EXPECT_LT(mag(W[1] - Wref[1]), 1e-9);

    // Solving again from the solution does no iteration
    const auto again = sys.solve(1e-12, 100, U, W);
    EXPECT_EQ(again.iterations, 0);
}


TEST(particleVelocitySystem, solvesWhereTheIncompleteCholeskyBreaksDown)
{
    // Eight particles of unit pseudo-mass coupled on their translations by
    // stiff pair springs k (0.9 n n + 0.1 I), k from 1e2 to 1e5, on the
    // relative velocity: SPD (identity plus positive semi-definite terms)
    // but ill conditioned, like near-contact lubrication.  For this draw
    // Eigen's incomplete Cholesky with its default shift breaks down; the
    // system is still solved (reference: the residual of the known
    // velocities, as above).
    const label N = 8;
    fdm::particleVelocitySystem sys(N);
    uint64_t state = 74;
    auto next = [&state]()
    {
        state = state*6364136223846793005ULL + 1442695040888963407ULL;
        return double(state >> 11)/double(1ULL << 53);
    };
    for (label k = 0; k < 6*N; ++k)
    {
        sys.addEntry(k, k, 1);
    }
    for (label pair = 0; pair < 3*N; ++pair)
    {
        const label a = label(next()*N);
        const label b = label(next()*N);
        if (a == b)
        {
            continue;
        }
        vector n;
        for (direction d = 0; d < 3; ++d)
        {
            n[d] = 2*next() - 1;
        }
        n /= mag(n);
        const scalar k = std::pow(10.0, 2 + 3*next());
        for (direction r = 0; r < 3; ++r)
        {
            for (direction c = 0; c < 3; ++c)
            {
                const scalar v = k*(0.9*n[r]*n[c] + 0.1*(r == c));
                sys.addEntry(6*a + r, 6*a + c, v);
                sys.addEntry(6*b + r, 6*b + c, v);
                sys.addEntry(6*a + r, 6*b + c, -v);
                sys.addEntry(6*b + r, 6*a + c, -v);
            }
        }
    }

    List<vector> Uref(N), Wref(N);
    forAll(Uref, i)
    {
        for (direction d = 0; d < 3; ++d)
        {
            Uref[i][d] = next() - 0.5;
            Wref[i][d] = next() - 0.5;
        }
    }
    List<vector> f, t;
    sys.multiply(Uref, Wref, f, t);
    forAll(f, i)
    {
        sys.addRhs(i, f[i], t[i]);
    }

    List<vector> U(N, Zero), W(N, Zero);
    const auto info = sys.solve(1e-13, 1000, U, W);
    EXPECT_TRUE(info.converged);
    forAll(U, i)
    {
        EXPECT_LT(mag(U[i] - Uref[i]), 1e-6);
        EXPECT_LT(mag(W[i] - Wref[i]), 1e-6);
    }
}


TEST(particleVelocitySystem, keptFactorisationFollowsTheMatrix)
{
    // Outer iterations: the same matrix with another right-hand side (the
    // kept factorisation), then a changed matrix (made again); each solve
    // gives the velocities whose product is its right-hand side
    fdm::particleVelocitySystem sys(2);
    const auto assemble = [&](const scalar k, const List<vector>& Uref)
    {
        sys.clear();
        sys.addMass(0, someMoments(1), 10);
        sys.addMass(1, someMoments(2), 10);
        addPairCoupling(sys, k);
        const List<vector> Wref({vector(0.1, 0, 0.2), vector(0, -0.3, 0)});
        List<vector> f, t;
        sys.multiply(Uref, Wref, f, t);
        sys.addRhs(0, f[0], t[0]);
        sys.addRhs(1, f[1], t[1]);
    };
    const List<List<vector>> targets
    ({
        {vector(1, 0, 0), vector(0, 2, 0)},
        {vector(-0.5, 1, 0.3), vector(0.2, 0, -1)}
    });
    for (const scalar k : {40.0, 40.0, 400.0, 40.0})
    {
        for (const List<vector>& Uref : targets)
        {
            assemble(k, Uref);
            List<vector> U(2, Zero), W(2, Zero);
            EXPECT_TRUE(sys.solve(1e-13, 200, U, W).converged);
            EXPECT_LT(mag(U[0] - Uref[0]), 1e-10) << k;
            EXPECT_LT(mag(U[1] - Uref[1]), 1e-10) << k;
        }
    }
}


TEST(particleVelocitySystem, aStiffLoadDoesNotHideTheChangeOfTheOthers)
{
    // Particle 0 held by a stiff spring (a contact at the barrier floor)
    // with its large force on the right-hand side; particle 1 free.  From
    // a guess whose particle 1 is 1e-3 off, the residual is far below 1e-6
    // of the right-hand side: relative to it the guess passes unchanged,
    // relative to the loads without the spring (residualScale) particle 1
    // is solved
    fdm::particleVelocitySystem sys(2);
    sys.addMass(0, someMoments(1), 10);
    sys.addMass(1, someMoments(2), 10);
    for (direction d = 0; d < 3; ++d)
    {
        sys.addEntry(d, d, 1e10);
    }
    const List<vector> Uref({vector(1, 0, 0), vector(0.5, 0, 0)});
    const List<vector> Wref(2, Zero);
    List<vector> f, t;
    sys.multiply(Uref, Wref, f, t);
    sys.addRhs(0, f[0], t[0]);
    sys.addRhs(1, f[1], t[1]);
    const scalar flowLoads = Foam::sqrt(magSqr(f[1]) + magSqr(t[1]));

    const List<vector> guess({Uref[0], Uref[1] + vector(1e-3, 0, 0)});
    {
        List<vector> U(guess), W(Wref);
        EXPECT_EQ(sys.solve(1e-6, 100, U, W).iterations, 0);
        EXPECT_GT(mag(U[1] - Uref[1]), 9e-4);
    }
    List<vector> U(guess), W(Wref);
    const auto info = sys.solve(1e-6, 100, U, W, flowLoads);
    EXPECT_TRUE(info.converged);
    EXPECT_GT(info.iterations, 0);
    EXPECT_LT(mag(U[1] - Uref[1]), 1e-5);
    EXPECT_LT(mag(U[0] - Uref[0]), 1e-5);
}
