// Unit test of the HDF5 calls behind the particle series: a segment's
// records and times, a copy of its first records, and what the segment
// list of a master file says (virtual series, plain series of an earlier
// version, unreadable).

#include "particleHDF5Files.H"
#include "OFstream.H"
#include "unitTestCase.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- A segment of N particles with a record at each time; every value of a
//  record is its time
void writeSegment(const fileName& path, const scalarList& times)
{
    const label N = 2;
    const scalarField radius(N, 1.0);
    const labelList group(N, 0);
    const long long seg =
        particleHDF5Files::createSegment(path, radius, group);
    for (const scalar t : times)
    {
        const std::vector<double> values(6*N, t);
        std::array<const double*, particleHDF5Files::nSeries> data;
        data.fill(values.data());
        particleHDF5Files::appendSeriesRecord(seg, t, data);
    }
    particleHDF5Files::closeSegment(seg);
}

} // End anonymous namespace


TEST(particleHDF5Files, segmentTimesAndACopyOfItsFirstRecords)
{
    unitTest::scratchCase sc("particleHDF5Files");
    const fileName seg = sc.path()/"segment0.h5";
    writeSegment(seg, {0.5, 0.75, 1.0});

    scalarList times;
    ASSERT_TRUE(particleHDF5Files::readTimes(seg, times));
    EXPECT_EQ(times, scalarList({0.5, 0.75, 1.0}));

    particleHDF5Files::copyRecords(seg, sc.path()/"copy.h5", 2);
    ASSERT_TRUE(particleHDF5Files::readTimes(sc.path()/"copy.h5", times));
    EXPECT_EQ(times, scalarList({0.5, 0.75}));

    EXPECT_FALSE
    (
        particleHDF5Files::readTimes(sc.path()/"missing.h5", times)
    );
}


TEST(particleHDF5Files, segmentListSaysWhatTheMasterIs)
{
    unitTest::scratchCase sc("particleHDF5FilesList");
    writeSegment(sc.path()/"segment0.h5", {0.1});
    writeSegment(sc.path()/"segment1.h5", {0.2, 0.3});
    const fileName master = sc.path()/"particles.h5";
    particleHDF5Files::writeVirtualSeries
    (
        master, scalarField(2, 1.0), labelList(2, 0),
        List<fileName>({"segment0.h5", "segment1.h5"}), labelList({1, 2}),
        particleHDF5Metadata::description()
    );

    wordList segments;
    EXPECT_EQ
    (
        particleHDF5Files::readSegmentList(master, segments),
        particleHDF5Files::virtualSeries
    );
    EXPECT_EQ(segments, wordList({"segment0.h5", "segment1.h5"}));
    scalarList times;
    ASSERT_TRUE(particleHDF5Files::readTimes(master, times));
    EXPECT_EQ(times, scalarList({0.1, 0.2, 0.3}));

    // A segment on its own is the plain series of an earlier version
    EXPECT_EQ
    (
        particleHDF5Files::readSegmentList(sc.path()/"segment1.h5", segments),
        particleHDF5Files::plainSeries
    );

    OFstream(sc.path()/"garbage.h5")() << "not HDF5" << endl;
    EXPECT_EQ
    (
        particleHDF5Files::readSegmentList(sc.path()/"garbage.h5", segments),
        particleHDF5Files::unreadable
    );
}
