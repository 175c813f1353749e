// Unit tests for Foam::fdm::ownedParticleSolve (issue 38) on one rank: the
// whole system solved by its owner gives the whole system's velocities and
// keeps its distributed system while the owners stay; the ranks together
// are tested by tests/cases/subGridSqueeze.sh (parallelParticleSolve distributed)

#include "ownedParticleSolve.H"
#include "ownedRowsSink.H"
#include "particleVelocitySystem.H"
#include "particleSystemFixtures.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace particleSystemFixtures;

TEST(ownedParticleSolve, oneOwnerSolvesAsTheWholeSystem)
{
    fdm::particleVelocitySystem whole(nParticles);
    assemble(whole);
    whole.prescribe(3, 4, 0.5);

    List<vector> U1(nParticles, Zero), W1(nParticles, Zero);
    List<vector> U2(U1), W2(W1);
    const auto a = whole.solve(1e-12, 200, U1, W1);
    // Assembled as the cloud does: into the rows this rank owns
    const labelList owner(nParticles, 0);
    fdm::ownedRowsSink rows(nParticles);
    rows.setOwners(owner);
    assemble(rows);
    rows.prescribe(3, 4, 0.5);
    fdm::ownedParticleSolve owned;
    const auto b = owned.solve(rows.entries(), owner, 1e-12, 200, U2, W2);
    EXPECT_TRUE(a.converged);
    EXPECT_TRUE(b.converged);
    EXPECT_EQ(owned.nGhosts(), 0);
    EXPECT_EQ(W2[3].y(), 0.5);
    for (label i = 0; i < nParticles; ++i)
    {
        EXPECT_LT(mag(U1[i] - U2[i]), 1e-9*mag(U1[i]) + 1e-12) << i;
        EXPECT_LT(mag(W1[i] - W2[i]), 1e-9*mag(W1[i]) + 1e-12) << i;
    }

    // Solved again from its solution: nothing left to do
    const auto again =
        owned.solve(whole.entries(), owner, 1e-12, 200, U2, W2);
    EXPECT_EQ(again.iterations, 0);
}
