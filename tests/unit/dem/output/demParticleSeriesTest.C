// Unit test of the DEM's particle series (particles.h5 in the FDM format):
// the records hold the DEM's positions, lab velocities and spins; the
// lubrication and contact parts add up to the pair loads (with the body
// force), the contact part is equal and opposite on a touching pair, and
// the stresslets are the DEM's four parts regrouped.

#include "demParticleSeries.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <hdf5.h>
#include <gtest/gtest.h>
#include <vector>

using namespace Foam;

namespace
{

std::vector<double> readSeries(const fileName& h5, const char* name)
{
    const hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t ds = H5Dopen2(f, name, H5P_DEFAULT);
    const hid_t space = H5Dget_space(ds);
    std::vector<double> v(H5Sget_simple_extent_npoints(space));
    H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Sclose(space);
    H5Dclose(ds);
    H5Fclose(f);
    return v;
}

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
    const auto x = readSeries(h5, "position");
    const auto U = readSeries(h5, "velocity");
    const auto F = readSeries(h5, "force");
    const auto Fc = readSeries(h5, "contactForce");
    const auto S = readSeries(h5, "stresslet");
    const auto s = readSeries(h5, "dipoleTrace");
    const auto Sc = readSeries(h5, "contactStresslet");
    ASSERT_EQ(x.size(), 6u);
    EXPECT_EQ(readSeries(h5, "group"), std::vector<double>({0, 1}));

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
            dem.stresslets(fdm::lubricatedDEM::normalLubrication)[i]
          + dem.stresslets(fdm::lubricatedDEM::shearLubrication)[i];
        const symmTensor contact =
            dem.stresslets(fdm::lubricatedDEM::normalContact)[i]
          + dem.stresslets(fdm::lubricatedDEM::shearContact)[i];
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
