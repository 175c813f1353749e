// Unit test of the DEM's particle series (particles.h5 in the FDM format):
// the records hold the DEM's positions, lab velocities and spins; the
// lubrication and contact parts add up to the pair loads (with the body
// force), the contact part is equal and opposite on a touching pair, and
// the stresslets are the DEM's four parts regrouped.

#include "demParticleSeries.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "unitTestHDF5.H"
#include <gtest/gtest.h>
#include <vector>

using namespace Foam;

namespace
{

//- Two spheres touching through their asperities (gap below the
//  roughness 1e-2 a), sheared, with a weight on the second
fdm::lubricatedDEM touchingPair()
{
    fdm::lubricatedDEM dem
    (
        fdm::periodicBox(point::zero, point(16, 16, 16),
            FixedList<bool, 3>({true, true, true})),
        1.0,
        fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.4, 4)
    );
    dem.addParticle(point(4, 4, 4), 1, 1);
    dem.addParticle(point(4.3, 5.982429, 4), 1, 1);   // gap 0.005
    dem.bodyForce(1) = vector(0, -0.5, 0);
    for (label i = 0; i < 20; ++i)
    {
        dem.step(1e-3);
    }
    return dem;
}

} // End anonymous namespace


TEST(demParticleSeries, recordsSplitThePairLoadsAsTheFDMRecords)
{
    unitTest::scratchCase sc("demParticleSeries");
    const fdm::lubricatedDEM dem = touchingPair();
    ASSERT_GT(dem.nContacts(), 0);
    {
        fdm::demParticleSeries series
        (
            sc.runTime(),
            unitTest::parse
            (
                "particles ((bed (4 4 4) 1) (free (4.3 5.982429 4) 1));"
                " density 1;"
            )
        );
        series.append(dem);
        series.commit();
    }
    const fileName h5 = sc.path()/"postProcessing/particles.h5";
    const auto x = unitTest::readDataset(h5, "position");
    const auto U = unitTest::readDataset(h5, "velocity");
    const auto F = unitTest::readDataset(h5, "force");
    const auto Fc = unitTest::readDataset(h5, "contactForce");
    const auto S = unitTest::readDataset(h5, "stresslet");
    const auto s = unitTest::readDataset(h5, "dipoleTrace");
    const auto Sc = unitTest::readDataset(h5, "contactStresslet");
    ASSERT_EQ(x.size(), 6u);
    EXPECT_EQ(unitTest::readDataset(h5, "group"), std::vector<double>({0, 1}));

    EXPECT_GT(mag(dem.contactForces()[0]), 0);
    for (label i = 0; i < 2; ++i)
    {
        for (direction d = 0; d < 3; ++d)
        {
            EXPECT_EQ(x[3*i + d], dem.positions()[i][d]);
            EXPECT_EQ(U[3*i + d], dem.labVelocity(i)[d]);
            // lubrication + contact + weight = the DEM's force
            EXPECT_NEAR
            (
                F[3*i + d] + Fc[3*i + d] + dem.bodyForces()[i][d],
                dem.forces()[i][d], 1e-12*mag(dem.forces()[i])
            );
            EXPECT_NEAR(Fc[d], -Fc[3 + d], 1e-12*mag(dem.contactForces()[0]));
        }
        const symmTensor lubrication =
            dem.stresslets(fdm::lubricatedInteraction::normalLubrication)[i]
          + dem.stresslets(fdm::lubricatedInteraction::shearLubrication)[i];
        const symmTensor contact =
            dem.stresslets(fdm::lubricatedInteraction::normalContact)[i]
          + dem.stresslets(fdm::lubricatedInteraction::shearContact)[i];
        EXPECT_NEAR(s[i], tr(lubrication), 1e-14);
        EXPECT_NEAR(S[6*i] + S[6*i + 3] + S[6*i + 5], 0, 1e-14);
        for (direction c = 0; c < 6; ++c)
        {
            EXPECT_NEAR(S[6*i + c] + (c == 0 || c == 3 || c == 5)*s[i]/3,
                lubrication[c], 1e-14);
            EXPECT_EQ(Sc[6*i + c], contact[c]);
        }
    }
}
