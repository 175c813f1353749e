// Unit test of the particle series' metadata: the run's description and
// the units read back as HDF5 attributes, and the XDMF companion: one grid
// per record at its time, every dataset it points to present in the file;
// the description both solvers share.

#include "particleHDF5Metadata.H"
#include "particleHDF5Writer.H"
#include "IFstream.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <hdf5.h>
#include <gtest/gtest.h>
#include <map>
#include <regex>

using namespace Foam;

namespace
{

std::string stringAttribute(const hid_t object, const char* name)
{
    const hid_t a = H5Aopen(object, name, H5P_DEFAULT);
    const hid_t type = H5Aget_type(a);
    std::string s(H5Tget_size(type), '\0');
    H5Aread(a, type, &s[0]);
    H5Tclose(type);
    H5Aclose(a);
    return s.c_str();
}

} // End anonymous namespace


TEST(particleHDF5Metadata, descriptionAndUnitsAreAttributes)
{
    unitTest::scratchCase sc("particleHDF5Metadata");
    const fileName h5 = sc.path()/"particles.h5";
    particleHDF5Metadata::description d;
    d.text.push_back({"solver", "fdmSuspensionFoam"});
    d.numbers.push_back({"viscosity", {0.25}});
    d.numbers.push_back({"boxMax", {1, 2, 3}});
    {
        const List<vector> v(1, vector(1, 2, 3));
        const List<symmTensor> S(1, symmTensor::zero);
        const List<scalar> s(1, 0.0);
        particleHDF5Writer w(h5, scalarField(1, 1.0), labelList(1, 0), 0, d);
        w.append(0, {v, v, v, v, v, S, s, v, v, S});
    }

    const hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    EXPECT_EQ(stringAttribute(f, "solver"), "fdmSuspensionFoam");
    const hid_t a = H5Aopen(f, "boxMax", H5P_DEFAULT);
    double box[3];
    H5Aread(a, H5T_NATIVE_DOUBLE, box);
    H5Aclose(a);
    EXPECT_EQ(box[2], 3.0);

    const hid_t ds = H5Dopen2(f, "stresslet", H5P_DEFAULT);
    EXPECT_EQ(stringAttribute(ds, "units"), "N m");
    EXPECT_EQ(stringAttribute(ds, "components"), "xx xy xz yy yz zz");
    H5Dclose(ds);
    H5Fclose(f);
}


TEST(particleHDF5Metadata, xdmfHasAGridPerRecordOverExistingDatasets)
{
    unitTest::scratchCase sc("particleHDF5MetadataXDMF");
    const fileName h5 = sc.path()/"particles.h5";
    {
        const List<vector> v(2, vector(1, 2, 3));
        const List<symmTensor> S(2, symmTensor::zero);
        const List<scalar> s(2, 0.0);
        particleHDF5Writer w(h5, scalarField(2, 1.0), labelList(2, 0), 0);
        w.append(0.5, {v, v, v, v, v, S, s, v, v, S});
        w.append(0.75, {v, v, v, v, v, S, s, v, v, S});
    }
    particleHDF5Metadata::writeXDMF(h5, scalarList({0.5, 0.75}), 2);
    EXPECT_FALSE(isFile(sc.path()/"particles.xmf.tmp"));

    IFstream is(sc.path()/"particles.xmf");
    ASSERT_TRUE(is.good());
    std::string xml, line;
    while (is.getLine(line), is.good())
    {
        xml += line + "\n";
    }
    const std::regex time("<Time Value=\"([0-9.]+)\"");
    std::vector<std::string> times;
    for (std::sregex_iterator i(xml.begin(), xml.end(), time), e; i != e; ++i)
    {
        times.push_back((*i)[1]);
    }
    EXPECT_EQ(times, std::vector<std::string>({"0.5", "0.75"}));
    EXPECT_NE(xml.find("NumberOfElements=\"2\""), std::string::npos);

    const hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const std::regex ref("particles\\.h5:/([A-Za-z]+)");
    label nRefs = 0;
    for (std::sregex_iterator i(xml.begin(), xml.end(), ref), e; i != e; ++i)
    {
        EXPECT_GT(H5Lexists(f, (*i)[1].str().c_str(), H5P_DEFAULT), 0)
            << (*i)[1];
        ++nRefs;
    }
    H5Fclose(f);
    EXPECT_GT(nRefs, 10);
}


TEST(particleHDF5Metadata, runDescriptionHasTheCommonEntries)
{
    const dictionary props
    (
        unitTest::parse("density 2; particles ((a (1 1 1) 1));")
    );
    const particleHDF5Metadata::description d =
        particleHDF5Metadata::runDescription
        (
            "solverX", "/case", wordList({"a", "b"}), props, 0.5, 2,
            boundBox(point(0, 1, 2), point(3, 4, 5)),
            FixedList<bool, 3>({true, false, true})
        );
    std::map<std::string, std::string> text(d.text.begin(), d.text.end());
    std::map<std::string, std::vector<double>> numbers
    (
        d.numbers.begin(), d.numbers.end()
    );
    EXPECT_EQ(text["solver"], "solverX");
    EXPECT_EQ(text["groupNames"], "a\nb\n");
    // The inline particle list is left out, the other entries kept
    EXPECT_EQ(text["particleProperties"].find("particles"), std::string::npos);
    EXPECT_NE(text["particleProperties"].find("density"), std::string::npos);
    EXPECT_EQ(numbers["viscosity"], std::vector<double>({0.5}));
    EXPECT_EQ(numbers["shearRate"], std::vector<double>({2}));
    EXPECT_EQ(numbers["boxMin"], std::vector<double>({0, 1, 2}));
    EXPECT_EQ(numbers["boxMax"], std::vector<double>({3, 4, 5}));
    EXPECT_EQ(numbers["periodic"], std::vector<double>({1, 0, 1}));
}
