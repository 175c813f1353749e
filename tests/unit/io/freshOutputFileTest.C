// Unit test of freshOutputFile: an existing time-series file is never
// chosen again, whatever number of earlier runs left files behind.

#include "freshOutputFile.H"
#include "OSspecific.H"
#include "OFstream.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(freshOutputFile, neverReturnsAnExistingFile)
{
    const fileName dir = fileName("freshOutputFileTest")/name(pid());
    rmDir(dir);
    ASSERT_TRUE(mkDir(dir));

    EXPECT_EQ(fdm::freshOutputFile(dir, "series"), dir/"series.dat");

    OFstream(dir/"series.dat")() << "run 1" << endl;
    EXPECT_EQ(fdm::freshOutputFile(dir, "series"), dir/"series_1.dat");

    OFstream(dir/"series_1.dat")() << "run 2" << endl;
    EXPECT_EQ(fdm::freshOutputFile(dir, "series"), dir/"series_2.dat");

    // Another extension is a different series
    EXPECT_EQ(fdm::freshOutputFile(dir, "series", "csv"), dir/"series.csv");

    rmDir(fileName("freshOutputFileTest"));
}
