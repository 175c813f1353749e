// Unit tests for the channel averages of the suspension rheology (thesis 1,
// eqs 2.70-2.76, 6.4-6.5, 6.18-6.19): exact sphere-slab volumes, profiles
// that conserve particle volume and stresslets, region averages and the
// core shear-rate regression.

#include "channelAverages.H"
#include "mathematicalConstants.H"
#include "unitTestHelpers.H"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

const scalar pi = constant::mathematical::pi;

scalar sphereVolume(scalar a)
{
    return 4.0/3.0*pi*a*a*a;
}

// Cap of height h of a sphere of radius a: pi h^2 (3a - h)/3
scalar capVolume(scalar a, scalar h)
{
    return pi*h*h*(3*a - h)/3;
}

// One sphere of radius 1 at (1, y, 1), velocity (2, 0, 0), stresslet
// S_xy = 3, no contacts
fdm::particleSample oneSphere(scalar y)
{
    fdm::particleSample s;
    s.position = List<point>(1, point(1, y, 1));
    s.velocity = List<vector>(1, vector(2, 0, 0));
    s.radius = scalarField(1, 1.0);
    s.hydrodynamic = List<symmTensor>(1, symmTensor(0, 3, 0, 0, 0, 0));
    return s;
}

// Random bidisperse spheres inside [0, L]^3 (walls at y = 0, L), with
// random velocities and stresslets
fdm::particleSample randomSample(label n, scalar L, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<scalar> u(0, 1);
    fdm::particleSample s;
    s.position.setSize(n);
    s.velocity.setSize(n);
    s.radius.setSize(n);
    s.hydrodynamic.setSize(n);
    s.contact.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar a = (i % 2) ? 1.4 : 1.0;
        s.radius[i] = a;
        s.position[i] = point(L*u(gen), a + (L - 2*a)*u(gen), L*u(gen));
        s.velocity[i] = vector(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5);
        for (direction c = 0; c < 6; ++c)
        {
            s.hydrodynamic[i][c] = u(gen) - 0.5;
            s.contact[i][c] = u(gen) - 0.5;
        }
    }
    return s;
}

} // End anonymous namespace


TEST(slabVolume, wholeSphereCapsAndHalves)
{
    const scalar a = 1.4;
    EXPECT_NEAR(fdm::slabVolume(0.3, a, -10, 10), sphereVolume(a), 1e-13);
    EXPECT_NEAR(fdm::slabVolume(0.3, a, 0.3, 10), sphereVolume(a)/2, 1e-13);
    // Cap of height 0.5 above the plane c + a - 0.5
    EXPECT_NEAR(fdm::slabVolume(0, a, a - 0.5, 5), capVolume(a, 0.5), 1e-13);
    EXPECT_NEAR(fdm::slabVolume(0, a, -5, -a + 0.2), capVolume(a, 0.2), 1e-13);
    EXPECT_EQ(fdm::slabVolume(0, a, 2, 3), 0);
}


TEST(channelAverages, profilesConserveVolumeAndStresslets)
{
    const scalar L = 10;
    const fdm::particleSample s = randomSample(40, L, 7);
    const label nBins = 13;
    const fdm::channelAverages avg(point(0, 0, 0), vector(L, L, L), 1, 0,
                                   nBins);
    const auto p = avg.binned(s);
    const scalar binVolume = L*L*L/nBins;

    scalar volume = 0;
    vector momentum(Zero);
    symmTensor SH(Zero), Sc(Zero);
    forAll(p.y, b)
    {
        EXPECT_NEAR(p.y[b], (b + 0.5)*L/nBins, 1e-12);
        volume += p.volumeFraction[b]*binVolume;
        momentum += p.velocity[b]*p.volumeFraction[b]*binVolume;
        SH += p.hydrodynamic[b]*binVolume;
        Sc += p.contact[b]*binVolume;
    }
    scalar volume0 = 0;
    vector momentum0(Zero);
    symmTensor SH0(Zero), Sc0(Zero);
    forAll(s.radius, i)
    {
        volume0 += sphereVolume(s.radius[i]);
        momentum0 += sphereVolume(s.radius[i])*s.velocity[i];
        SH0 += s.hydrodynamic[i];
        Sc0 += s.contact[i];
    }
    EXPECT_NEAR(volume, volume0, 1e-10*volume0);
    EXPECT_LT(mag(momentum - momentum0), 1e-10*volume0);
    EXPECT_LT(mag(SH - SH0), 1e-12*s.radius.size());
    EXPECT_LT(mag(Sc - Sc0), 1e-12*s.radius.size());
}


TEST(channelAverages, singleSphereProfileIsItsSlabVolumes)
{
    // One sphere of radius 1 centred at y = 2.5 in bins of width 1: the
    // bins [1,2], [2,3], [3,4] hold a cap of height 0.5, the middle slab
    // and another cap
    const fdm::particleSample s = oneSphere(2.5);
    const fdm::channelAverages avg(point(0, 0, 0), vector(2, 5, 3), 1, 0, 5);
    const auto p = avg.binned(s);
    const scalar area = 6;
    const scalar cap = capVolume(1, 0.5);
    EXPECT_EQ(p.volumeFraction[0], 0);
    EXPECT_NEAR(p.volumeFraction[1]*area, cap, 1e-13);
    EXPECT_NEAR(p.volumeFraction[2]*area, sphereVolume(1) - 2*cap, 1e-13);
    EXPECT_NEAR(p.volumeFraction[3]*area, cap, 1e-13);
    EXPECT_NEAR(p.velocity[2].x(), 2, 1e-14);
    EXPECT_EQ(mag(p.velocity[0]), 0);
    // The stresslet is spread by volume: 3 cap/V_p in bin 1
    EXPECT_NEAR(p.hydrodynamic[1].xy()*area, 3*cap/sphereVolume(1), 1e-13);
    EXPECT_EQ(mag(p.contact[1]), 0);    // no contacts given
}


TEST(channelAverages, leesEdwardsCellCountsTheImagesAcrossTheFaces)
{
    // The sphere of the test above moved to y = 4.5, across the sheared
    // face y = 5 of a Lees-Edwards cell at rate 0.4 (image velocity -+2
    // along x): bins [3,4] and [4,5] hold a cap of height 0.5 and the
    // middle slab, bin [0,1] the other cap as its image one period down,
    // slower by 2; the whole cell's volume fraction is the whole sphere's
    // and its shear rate the imposed one.  Between walls the cap across
    // is lost.
    const fdm::particleSample s = oneSphere(4.5);
    const scalar area = 6;
    const scalar cap = capVolume(1, 0.5);
    const fdm::channelAverages sheared
    (
        point(0, 0, 0), vector(2, 5, 3), 1, 0, 5, 0.4
    );
    const auto p = sheared.binned(s);
    EXPECT_NEAR(p.volumeFraction[3]*area, cap, 1e-13);
    EXPECT_NEAR(p.volumeFraction[4]*area, sphereVolume(1) - 2*cap, 1e-13);
    EXPECT_NEAR(p.volumeFraction[0]*area, cap, 1e-13);
    EXPECT_NEAR(p.velocity[4].x(), 2, 1e-14);
    EXPECT_NEAR(p.velocity[0].x(), 0, 1e-14);
    EXPECT_NEAR(p.hydrodynamic[0].xy()*area, 3*cap/sphereVolume(1), 1e-13);
    const auto r = sheared.averages(s, 0);
    EXPECT_NEAR(r.volumeFraction*area*5, sphereVolume(1), 1e-13);
    EXPECT_EQ(r.shearRate, 0.4);

    const fdm::channelAverages walls(point(0, 0, 0), vector(2, 5, 3), 1, 0, 5);
    EXPECT_NEAR
    (
        walls.averages(s, 0).volumeFraction*area*5, sphereVolume(1) - cap,
        1e-13
    );
}


TEST(channelAverages, regionAveragesAndShearRegression)
{
    const scalar L = 12, gammaDot = 0.37, layer = 2.5;
    fdm::particleSample s = randomSample(60, L, 11);
    // Linear flow of the centres: the regression returns its slope
    forAll(s.position, i)
    {
        s.velocity[i] = vector(gammaDot*s.position[i].y() - 1.1, 0.2, 0);
    }
    const fdm::channelAverages avg(point(0, 0, 0), vector(L, L, L), 1, 0, 4);

    const auto core = avg.averages(s, layer);
    EXPECT_NEAR(core.shearRate, gammaDot, 1e-12);

    label n = 0;
    scalar volume = 0;
    symmTensor SH(Zero);
    forAll(s.position, i)
    {
        const scalar y = s.position[i].y();
        volume += fdm::slabVolume(y, s.radius[i], layer, L - layer);
        if (y > layer && y < L - layer)
        {
            ++n;
            SH += s.hydrodynamic[i];
        }
    }
    const scalar V = L*L*(L - 2*layer);
    EXPECT_EQ(core.nParticles, n);
    EXPECT_NEAR(core.volumeFraction, volume/V, 1e-14);
    EXPECT_LT(mag(core.hydrodynamic - SH/V), 1e-14);

    // Layer 0: the whole domain, every particle
    const auto all = avg.averages(s, 0);
    scalar volume0 = 0;
    forAll(s.radius, i) { volume0 += sphereVolume(s.radius[i]); }
    EXPECT_EQ(all.nParticles, s.radius.size());
    EXPECT_NEAR(all.volumeFraction, volume0/(L*L*L), 1e-13);
}


TEST(channelAverages, stressComponentsFollowTheDirections)
{
    // xx xy xz yy yz zz
    const symmTensor t(1, 2, 3, 4, 5, 6);
    const fdm::channelAverages xy(point(0, 0, 0), vector(1, 1, 1), 1, 0, 1);
    EXPECT_EQ(xy.shear(t), 2);
    EXPECT_EQ(xy.firstDifference(t), 1 - 4);
    EXPECT_EQ(xy.secondDifference(t), 4 - 6);
    // Walls normal to z, flow along y: vorticity x
    const fdm::channelAverages zy(point(0, 0, 0), vector(1, 1, 1), 2, 1, 1);
    EXPECT_EQ(zy.shear(t), 5);
    EXPECT_EQ(zy.firstDifference(t), 4 - 6);
    EXPECT_EQ(zy.secondDifference(t), 6 - 1);
}


TEST(channelAverages, rejectsBadDirectionsAndLayers)
{
    FatalError.throwExceptions();
    EXPECT_THROW(fdm::channelAverages(point(0, 0, 0), vector(1, 1, 1), 1, 1, 4),
                 Foam::error);
    EXPECT_THROW(fdm::channelAverages(point(0, 0, 0), vector(1, 1, 1), 1, 0, 0),
                 Foam::error);
    const fdm::channelAverages avg(point(0, 0, 0), vector(1, 1, 1), 1, 0, 4);
    EXPECT_THROW(avg.averages(fdm::particleSample(), 0.5), Foam::error);
}


namespace
{

// Golden table of the channel averages, the sample included; the Python
// twin (fdmPost.rheology.CouetteSeries) is tested on it too.  Cell [0, 10]^3,
// walls normal to y, flow along x, 5 bins, wall layer 2.
std::string goldenChannelTable()
{
    return unitTest::projectFile("tests/golden/channelAverages.dat");
}

//- Rows "name index value" of the averages of sample s
std::vector<std::pair<std::string, std::vector<double>>> channelRows
(
    const fdm::particleSample& s
)
{
    const fdm::channelAverages avg
    (
        point::zero, vector(10, 10, 10), 1, 0, 5
    );
    const fdm::channelAverages::region core = avg.averages(s, 2);
    const fdm::channelAverages::profiles p = avg.binned(s);
    std::vector<std::pair<std::string, std::vector<double>>> rows;
    rows.push_back({"corePhi", {core.volumeFraction}});
    rows.push_back({"coreShearRate", {core.shearRate}});
    rows.push_back({"coreHydrodynamic", {}});
    rows.push_back({"coreContact", {}});
    for (direction c = 0; c < 6; ++c)
    {
        rows[2].second.push_back(core.hydrodynamic[c]);
        rows[3].second.push_back(core.contact[c]);
    }
    rows.push_back({"binPhi", {}});
    rows.push_back({"binVelocityFlow", {}});
    rows.push_back({"binHydrodynamic", {}});
    rows.push_back({"binContact", {}});
    forAll(p.y, b)
    {
        rows[4].second.push_back(p.volumeFraction[b]);
        rows[5].second.push_back(p.velocity[b].x());
        for (direction c = 0; c < 6; ++c)
        {
            rows[6].second.push_back(p.hydrodynamic[b][c]);
            rows[7].second.push_back(p.contact[b][c]);
        }
    }
    return rows;
}

} // namespace


TEST(channelAverages, matchesTheGoldenTable)
{
    // FDM_WRITE_GOLDEN=1 fdmUnitTests rewrites the table (sample and
    // averages) after a deliberate change of eqs 2.70-2.76, 6.4-6.5,
    // 6.18-6.19 (and the Python twin must follow)
    const fdm::particleSample s = randomSample(16, 10, 11);
    const auto rows = channelRows(s);
    if (unitTest::writingGolden())
    {
        std::ofstream os(goldenChannelTable());
        os.precision(17);
        os  << "# Channel averages (thesis 1 eqs 2.70-2.76, 6.4-6.5,"
            << " 6.18-6.19) of a sample of 16 spheres in [0, 10]^3, walls"
            << " normal to y,\n# flow x, 5 bins, wall layer 2; written by"
            << " tests/unit/rheology/channelAveragesTest.C"
            << " (FDM_WRITE_GOLDEN=1)\n"
            << "# particle: x y z ux uy uz a hydrodynamic(6) contact(6)\n";
        forAll(s.radius, i)
        {
            os  << "particle";
            for (direction c = 0; c < 3; ++c) { os << ' ' << s.position[i][c]; }
            for (direction c = 0; c < 3; ++c) { os << ' ' << s.velocity[i][c]; }
            os  << ' ' << s.radius[i];
            for (direction c = 0; c < 6; ++c)
            {
                os  << ' ' << s.hydrodynamic[i][c];
            }
            for (direction c = 0; c < 6; ++c) { os << ' ' << s.contact[i][c]; }
            os  << '\n';
        }
        os  << "# name values (tensors xx xy xz yy yz zz, bins in order)\n";
        for (const auto& r : rows)
        {
            os  << r.first;
            for (const double v : r.second) { os << ' ' << v; }
            os  << '\n';
        }
    }
    std::ifstream is(goldenChannelTable());
    ASSERT_TRUE(is.good()) << goldenChannelTable();
    std::string line;
    std::size_t i = 0;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#' || line.rfind("particle", 0) == 0)
        {
            continue;
        }
        std::istringstream ls(line);
        std::string name;
        ls >> name;
        ASSERT_LT(i, rows.size());
        EXPECT_EQ(name, rows[i].first);
        for (const double v : rows[i].second)
        {
            double g;
            ls >> g;
            EXPECT_NEAR(v, g, 1e-13*(std::abs(g) + 1)) << name;
        }
        ++i;
    }
    EXPECT_EQ(i, rows.size());
}
