// Unit tests for Foam::fdm::particleSystemEntries: the entries of a
// particle system replayed into another, renumbered (the rows a rank
// solves by subdomain, fdm::ownedParticleSolve)

#include "particleSystemEntries.H"
#include "particleVelocitySystem.H"
#include "particleSystemFixtures.H"

#include <gtest/gtest.h>

using namespace Foam;

TEST(particleSystemEntries, replaysItsBlocksRenumbered)
{
    // Replayed in reverse order into another system, the same system: its
    // solution reversed; a particle left out takes its couplings with it
    using namespace particleSystemFixtures;
    fdm::particleVelocitySystem whole(nParticles), reversed(nParticles);
    assemble(whole);
    whole.prescribe(1, 2, -0.75);
    whole.entries().replay(reversed, labelList({4, 3, 2, 1, 0}));

    List<vector> U1(nParticles, Zero), W1(nParticles, Zero);
    List<vector> U2(U1), W2(W1);
    whole.solve(1e-12, 200, U1, W1);
    reversed.solve(1e-12, 200, U2, W2);
    EXPECT_NEAR(U2[3].z(), -0.75, 1e-12);
    for (label i = 0; i < nParticles; ++i)
    {
        EXPECT_LT(mag(U1[i] - U2[4 - i]), 1e-9*mag(U1[i]) + 1e-12) << i;
        EXPECT_LT(mag(W1[i] - W2[4 - i]), 1e-9*mag(W1[i]) + 1e-12) << i;
    }

    // The last particle left out: its row and its couplings are not added
    fdm::particleVelocitySystem four(nParticles - 1);
    whole.entries().replay(four, labelList({0, 1, 2, 3, -1}));
    for (label e = 0; e < four.entries().rows.size(); ++e)
    {
        EXPECT_LT(four.entries().rows[e], 24);
        EXPECT_LT(four.entries().cols[e], 24);
    }
    EXPECT_LT(four.entries().rows.size(), whole.entries().rows.size());
}
