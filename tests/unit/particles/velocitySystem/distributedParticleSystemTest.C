// Unit tests for Foam::fdm::distributedParticleSystem (issue 38) on one
// rank, against the whole-system solver particleVelocitySystem; the ranks
// together are tested by tests/cases/distributedParticleSystem.sh

#include "distributedParticleSystem.H"
#include "particleVelocitySystem.H"
#include "rigidBodyMoments.H"
#include "unitTestHelpers.H"
#include "particleSystemFixtures.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace particleSystemFixtures;


TEST(distributedParticleSystem, oneRankSolvesAsTheWholeSystem)
{
    fdm::particleVelocitySystem whole(nParticles);
    fdm::distributedParticleSystem parts(nParticles, labelList(), labelList());
    assemble(whole);
    assemble(parts);
    // Particle 2 held still in x and spun about z: eliminated in one,
    // projected out in the other
    whole.prescribe(2, 0, 0.25);
    whole.prescribe(2, 5, -1);
    parts.prescribe(2, 0, 0.25);
    parts.prescribe(2, 5, -1);

    List<vector> U1(nParticles, Zero), W1(nParticles, Zero);
    List<vector> U2(U1), W2(W1);
    const auto a = whole.solve(1e-12, 200, U1, W1);
    const auto b = parts.solve(1e-12, 200, U2, W2);
    EXPECT_TRUE(a.converged);
    EXPECT_TRUE(b.converged);
    EXPECT_GT(b.iterations, 0);
    EXPECT_LE(b.relativeResidual, 1e-12);
    EXPECT_EQ(U2[2].x(), 0.25);
    EXPECT_EQ(W2[2].z(), -1);
    for (label i = 0; i < nParticles; ++i)
    {
        EXPECT_LT(mag(U1[i] - U2[i]), 1e-9*mag(U1[i]) + 1e-12) << i;
        EXPECT_LT(mag(W1[i] - W2[i]), 1e-9*mag(W1[i]) + 1e-12) << i;
    }
}


TEST(distributedParticleSystem, stopsAtTheToleranceOfTheWholeSystem)
{
    // residualScale as particleVelocitySystem: the bound is tolerance
    // times the smaller of the scale and the right-hand side's norm, and
    // a solved guess takes no iteration
    fdm::distributedParticleSystem parts(nParticles, labelList(), labelList());
    assemble(parts);
    List<vector> U(nParticles, Zero), W(nParticles, Zero);
    const auto first = parts.solve(1e-3, 200, U, W, 1e-2);
    EXPECT_TRUE(first.converged);
    EXPECT_LE(first.relativeResidual, 1e-3);
    const auto again = parts.solve(1e-3, 200, U, W, 1e-2);
    EXPECT_EQ(again.iterations, 0);
}


TEST(distributedParticleSystem, dropsTheRowsOfOtherRanksParticles)
{
    // Entries and loads of rows beyond the owned particles are the
    // ghosts' owners' to add: with 3 of the 5 particles owned and no
    // columns beyond them, the rows kept are the 3-particle system's
    fdm::particleVelocitySystem three(3);
    fdm::distributedParticleSystem parts(3, labelList(), labelList());
    for (label i = 0; i < nParticles; ++i)
    {
        const scalar m = 25*(1 + 0.3*i);
        for (label d = 0; d < 6; ++d)
        {
            parts.addEntry(6*i + d, 6*i + d, m);
            parts.addRhs(i, vector(1, 2, 3), vector(4, 5, 6));
            if (i < 3)
            {
                three.addEntry(6*i + d, 6*i + d, m);
                three.addRhs(i, vector(1, 2, 3), vector(4, 5, 6));
            }
        }
    }
    List<vector> U1(3, Zero), W1(3, Zero), U2(3, Zero), W2(3, Zero);
    three.solve(1e-12, 50, U1, W1);
    parts.solve(1e-12, 50, U2, W2);
    forAll(U1, i)
    {
        EXPECT_LT(mag(U1[i] - U2[i]), 1e-12) << i;
        EXPECT_LT(mag(W1[i] - W2[i]), 1e-12) << i;
    }
}


TEST(distributedParticleSystem, aGhostBelongsToAnotherRank)
{
    const std::string message = unitTest::errorOf([]
    {
        fdm::distributedParticleSystem parts(2, labelList({0}), labelList({1}));
    });
    EXPECT_NE(message.find("belongs to another of the 1 ranks"),
              std::string::npos) << message;
}


TEST(distributedParticleSystem, aRankWithoutParticlesTakesPart)
{
    // A rank whose cells hold no centre owns no rows: it has nothing to
    // factorise and still joins every reduction of the solve
    fdm::distributedParticleSystem none(0, labelList(), labelList());
    List<vector> U, W;
    const auto info = none.solve(1e-10, 200, U, W, 1);
    EXPECT_TRUE(info.converged);
    EXPECT_EQ(info.iterations, 0);
}
