// Unit test of the DEM time series: a stress.dat row holds the time, the
// strain gamma t, the volume fraction (by hand) and the system's counts and
// stresses, one column per header name; a second series of the same start
// goes to a fresh file; tracks follow the listed particles, and an unknown
// one or a zero interval stops.

#include "demSeries.H"
#include "IFstream.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "demTestSystem.H"
#include <gtest/gtest.h>
#include <sstream>

using namespace Foam;

namespace
{

//- The header's column names and the first data row of a series file
std::pair<wordList, scalarList> readSeries(const fileName& file)
{
    IFstream is(file);
    string line, header;
    while (is.getLine(line), line[0] == '#')
    {
        header = line;
    }
    std::istringstream h(header.substr(1)), r(line);
    wordList names;
    scalarList row;
    for (std::string w; h >> w;) { names.append(w); }
    for (scalar x; r >> x;) { row.append(x); }
    return {names, row};
}

} // End anonymous namespace


TEST(demSeries, rowHoldsTimeStrainFractionCountsAndStresses)
{
    unitTest::scratchCase sc("demSeries");
    const fdm::lubricatedDEM dem = unitTest::threeSpheres(200);
    {
        fdm::demSeries series(sc.runTime(), dem);
        series.append(dem);
        fdm::demSeries again(sc.runTime(), dem);
        again.append(dem);
    }
    const fileName dir = sc.path()/"postProcessing/lubricatedDEM/0";
    const auto first = readSeries(dir/"stress.dat");
    const wordList& names = first.first;
    const scalarList& row = first.second;
    ASSERT_EQ(row.size(), names.size());
    ASSERT_EQ(names.size(), 6 + 4*fdm::lubricatedInteraction::nStressParts);

    EXPECT_NEAR(row[0], 0.2, 1e-12);                       // time
    EXPECT_NEAR(row[1], 0.2, 1e-12);                       // strain
    const scalar phi = 4.0/3.0*constant::mathematical::pi
        *(1 + 1 + pow3(1.2))/pow3(16.0);
    EXPECT_NEAR(row[2], phi, 1e-10);
    EXPECT_EQ(row[3], dem.nInteractions());
    EXPECT_GT(row[3], 0);
    for (label p = 0; p < fdm::lubricatedInteraction::nStressParts; ++p)
    {
        EXPECT_NEAR(row[6 + 4*p + 3], dem.stress(p).xy(),
            1e-9*mag(dem.stress(p)) + VSMALL) << names[6 + 4*p + 3];
    }

    EXPECT_EQ(readSeries(dir/"stress_1.dat").second, row);
}


TEST(demSeries, tracksFollowTheListedParticles)
{
    unitTest::scratchCase sc("demTracks");
    const fdm::lubricatedDEM dem = unitTest::threeSpheres(10);
    {
        fdm::demTracks tracks
        (
            sc.runTime(), dem, unitTest::parse("track (2 0);")
        );
        tracks.append(dem);
    }
    const auto t =
        readSeries(sc.path()/"postProcessing/lubricatedDEM/0/tracks.dat");
    ASSERT_EQ(t.second.size(), 7);
    EXPECT_NEAR(t.second[1], dem.positions()[2].x(), 1e-10);
    EXPECT_NEAR(t.second[6], dem.positions()[0].z(), 1e-10);

    const std::string unknown = unitTest::errorOf([&]
    {
        fdm::demTracks(sc.runTime(), dem, unitTest::parse("track (3);"));
    });
    EXPECT_NE(unknown.find("particle 3 does not exist"), std::string::npos)
        << unknown;

    const std::string zero = unitTest::errorOf([&]
    {
        fdm::demSeries::readInterval(unitTest::parse("interval 0;"));
    });
    EXPECT_NE(zero.find("interval"), std::string::npos) << zero;
    EXPECT_EQ(fdm::demSeries::readInterval(unitTest::parse("")), 100);
}
