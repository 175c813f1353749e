// Unit tests for Foam::fdm::ownedRowsSink (issue 38): it keeps the rows of
// the particles this rank owns, exactly as the whole system has them, and
// nothing of the others

#include "ownedRowsSink.H"
#include "particleVelocitySystem.H"
#include "particleSystemFixtures.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace particleSystemFixtures;

TEST(ownedRowsSink, keepsTheRowsOfItsOwnParticles)
{
    fdm::particleVelocitySystem whole(nParticles);
    assemble(whole);
    whole.prescribe(1, 2, 0.5);
    whole.prescribe(2, 0, 0.25);

    // Particle 2 belongs to rank 1 (this rank is 0)
    const labelList owner({0, 0, 1, 0, 0});
    fdm::ownedRowsSink rows(nParticles);
    rows.setOwners(owner);
    assemble(rows);
    rows.prescribe(1, 2, 0.5);
    rows.prescribe(2, 0, 0.25);

    // The whole system's entries in owned rows, in the order added
    const fdm::particleSystemEntries& all = whole.entries();
    const fdm::particleSystemEntries& mine = rows.entries();
    label k = 0;
    forAll(all.rows, e)
    {
        if (all.rows[e]/6 == 2)
        {
            continue;
        }
        ASSERT_LT(k, mine.rows.size());
        EXPECT_EQ(mine.rows[k], all.rows[e]);
        EXPECT_EQ(mine.cols[k], all.cols[e]);
        EXPECT_EQ(mine.values[k], all.values[e]);
        ++k;
    }
    EXPECT_EQ(k, mine.rows.size());
    EXPECT_GT(k, 0);
    forAll(all.rhs, i)
    {
        EXPECT_EQ(mine.rhs[i], i/6 == 2 ? 0 : all.rhs[i]) << i;
        EXPECT_EQ(mine.prescribed[i], i/6 != 2 && all.prescribed[i]) << i;
    }
    EXPECT_TRUE(mine.prescribed[6 + 2]);

    // New owners start empty
    rows.setOwners(labelList(nParticles, 0));
    EXPECT_EQ(rows.entries().rows.size(), 0);
}
