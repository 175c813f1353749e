/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleHDF5Files.H"
#include <algorithm>
#include "error.H"

#include <hdf5.h>
#include <string>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The series and the shape of one record per particle: vectors (3), the
//  stresslets as symmTensor components xx xy xz yy yz zz (6), the trace
//  of the force dipole (1)
struct seriesShape
{
    const char* name;
    hsize_t components;
};

const seriesShape series[Foam::particleHDF5Files::nSeries] =
{
    {"position", 3}, {"velocity", 3}, {"angularVelocity", 3},
    {"force", 3}, {"torque", 3}, {"stresslet", 6}, {"dipoleTrace", 1},
    {"contactForce", 3}, {"contactTorque", 3}, {"contactStresslet", 6}
};

//- Shape of n records of a series of N particles
std::vector<hsize_t> shape(const hsize_t n, const hsize_t N, const hsize_t c)
{
    std::vector<hsize_t> dims{n};
    if (c > 0)
    {
        dims.push_back(N);
    }
    if (c > 1)
    {
        dims.push_back(c);
    }
    return dims;
}

void check(const bool ok, const char* what, const std::string& path)
{
    if (!ok)
    {
        FatalErrorInFunction
            << "HDF5 error while " << what << " " << path.c_str()
            << " (disk full or file damaged?)" << exit(FatalError);
    }
}

//- HDF5 calls on files that may be damaged, without its error stack
class quiet
{
    H5E_auto2_t func_;
    void* data_;
public:
    quiet() { H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
              H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }
    ~quiet() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
};

hid_t openReadOnly(const fileName& path)
{
    quiet q;
    return H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
}

std::vector<double> readAll(hid_t f, const char* name)
{
    const hid_t ds = H5Dopen2(f, name, H5P_DEFAULT);
    if (ds < 0)
    {
        return {};
    }
    const hid_t space = H5Dget_space(ds);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    std::vector<double> v(n > 0 ? n : 0);
    if (!v.empty())
    {
        H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
            v.data());
    }
    H5Sclose(space);
    H5Dclose(ds);
    return v;
}

void writeStatic
(
    hid_t f,
    const scalarField& radius,
    const labelList& group
)
{
    const hsize_t n = radius.size();
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    hid_t ds = H5Dcreate2(f, "radius", H5T_NATIVE_DOUBLE, space,
        H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
        radius.cdata());
    H5Dclose(ds);
    const std::vector<int> g(group.begin(), group.end());
    ds = H5Dcreate2(f, "group", H5T_NATIVE_INT, space, H5P_DEFAULT,
        H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(ds, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, g.data());
    H5Dclose(ds);
    H5Sclose(space);
}

//- An extendible series of n records chunked one record at a time,
//  holding data when given
void createSeries
(
    hid_t f,
    const char* name,
    const std::vector<hsize_t>& dims,
    const double* data = nullptr
)
{
    std::vector<hsize_t> maxDims(dims), chunk(dims);
    maxDims[0] = H5S_UNLIMITED;
    chunk[0] = 1;
    const hid_t space =
        H5Screate_simple(int(dims.size()), dims.data(), maxDims.data());
    const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(plist, int(chunk.size()), chunk.data());
    const hid_t ds = H5Dcreate2(f, name, H5T_NATIVE_DOUBLE, space,
        H5P_DEFAULT, plist, H5P_DEFAULT);
    if (data && dims[0] > 0)
    {
        H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
    }
    H5Dclose(ds);
    H5Pclose(plist);
    H5Sclose(space);
}

//- Append one record (row of the first axis) to a series
bool appendRow(hid_t f, const char* name, const double* data)
{
    const hid_t ds = H5Dopen2(f, name, H5P_DEFAULT);
    hid_t space = H5Dget_space(ds);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(rank);
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    H5Sclose(space);

    std::vector<hsize_t> newDims(dims), start(rank, 0), count(dims);
    newDims[0] += 1;
    start[0] = dims[0];
    count[0] = 1;
    herr_t status = H5Dset_extent(ds, newDims.data());

    space = H5Dget_space(ds);
    H5Sselect_hyperslab(space, H5S_SELECT_SET, start.data(), nullptr,
        count.data(), nullptr);
    const hid_t mem = H5Screate_simple(rank, count.data(), nullptr);
    status = std::min(status,
        H5Dwrite(ds, H5T_NATIVE_DOUBLE, mem, space, H5P_DEFAULT, data));
    H5Sclose(mem);
    H5Sclose(space);
    H5Dclose(ds);
    return status >= 0;
}

//- The "segments" attribute: names one a line
void writeSegmentAttribute(hid_t f, const UList<fileName>& segments)
{
    std::string text;
    for (const fileName& seg : segments)
    {
        text += seg + "\n";
    }
    particleHDF5Metadata::writeText(f, "segments", text);
}

} // namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::label Foam::particleHDF5Files::readSegmentList
(
    const fileName& path,
    wordList& segments
)
{
    segments.clear();
    const hid_t f = openReadOnly(path);
    if (f < 0)
    {
        return unreadable;
    }
    if (H5Aexists(f, "segments") <= 0)
    {
        H5Fclose(f);
        return plainSeries;
    }
    const hid_t a = H5Aopen(f, "segments", H5P_DEFAULT);
    const hid_t type = H5Aget_type(a);
    std::string text(H5Tget_size(type), '\0');
    H5Aread(a, type, &text[0]);
    H5Tclose(type);
    H5Aclose(a);
    H5Fclose(f);

    std::string::size_type start = 0, end = 0;
    while ((end = text.find('\n', start)) != std::string::npos)
    {
        segments.append(fileName(text.substr(start, end - start)).name());
        start = end + 1;
    }
    return virtualSeries;
}


bool Foam::particleHDF5Files::readTimes
(
    const fileName& path,
    scalarList& times
)
{
    times.clear();
    const hid_t f = openReadOnly(path);
    if (f < 0)
    {
        return false;
    }
    const std::vector<double> t = readAll(f, "time");
    H5Fclose(f);
    // Element-wise: List lost its iterator-range constructor in v2312
    times.resize(label(t.size()));
    std::copy(t.begin(), t.end(), times.begin());
    return true;
}


void Foam::particleHDF5Files::copyRecords
(
    const fileName& src,
    const fileName& dst,
    const label n
)
{
    const hid_t in = openReadOnly(src);
    check(in >= 0, "opening", src);
    const std::vector<double> radius = readAll(in, "radius");
    const hsize_t N = radius.size();

    const hid_t out = H5Fcreate(dst.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT,
        H5P_DEFAULT);
    check(out >= 0, "creating", dst);
    H5Ocopy(in, "radius", out, "radius", H5P_DEFAULT, H5P_DEFAULT);
    H5Ocopy(in, "group", out, "group", H5P_DEFAULT, H5P_DEFAULT);

    createSeries(out, "time", {hsize_t(n)}, readAll(in, "time").data());
    for (const seriesShape& s : series)
    {
        createSeries(out, s.name, shape(n, N, s.components),
            readAll(in, s.name).data());
    }
    H5Fclose(in);
    check(H5Fclose(out) >= 0, "writing", dst);
}


long long Foam::particleHDF5Files::createSegment
(
    const fileName& path,
    const scalarField& radius,
    const labelList& group
)
{
    const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT,
        H5P_DEFAULT);
    check(f >= 0, "creating", path);
    writeStatic(f, radius, group);
    createSeries(f, "time", {0});
    for (const seriesShape& s : series)
    {
        createSeries(f, s.name, shape(0, radius.size(), s.components));
    }
    particleHDF5Metadata::writeUnits(f);
    check(H5Fflush(f, H5F_SCOPE_LOCAL) >= 0, "writing", path);
    return f;
}


void Foam::particleHDF5Files::appendSeriesRecord
(
    const long long segment,
    const double time,
    const std::array<const double*, nSeries>& data
)
{
    const hid_t f = segment;
    bool ok = appendRow(f, "time", &time);
    for (int i = 0; i < nSeries; ++i)
    {
        ok = appendRow(f, series[i].name, data[i]) && ok;
    }
    ok = H5Fflush(f, H5F_SCOPE_LOCAL) >= 0 && ok;
    check(ok, "appending a record to", "the particle time series");
}


void Foam::particleHDF5Files::closeSegment(const long long segment)
{
    check(H5Fclose(hid_t(segment)) >= 0, "closing", "a particle segment");
}


void Foam::particleHDF5Files::writeVirtualSeries
(
    const fileName& path,
    const scalarField& radius,
    const labelList& group,
    const UList<fileName>& segments,
    const UList<label>& records,
    const particleHDF5Metadata::description& description
)
{
    const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_libver_bounds(fapl, H5F_LIBVER_LATEST, H5F_LIBVER_LATEST);
    const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT,
        fapl);
    H5Pclose(fapl);
    check(f >= 0, "creating", path);
    writeStatic(f, radius, group);
    writeSegmentAttribute(f, segments);

    hsize_t total = 0;
    for (const label r : records)
    {
        total += r;
    }

    const hsize_t N = radius.size();
    std::vector<seriesShape> all{{"time", 0}};
    all.insert(all.end(), std::begin(series), std::end(series));
    for (const seriesShape& s : all)
    {
        const std::vector<hsize_t> dims = shape(total, N, s.components);
        const hid_t vspace =
            H5Screate_simple(int(dims.size()), dims.data(), nullptr);
        const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
        hsize_t offset = 0;
        forAll(segments, k)
        {
            std::vector<hsize_t> start(dims.size(), 0);
            std::vector<hsize_t> count(shape(records[k], N, s.components));
            start[0] = offset;
            H5Sselect_hyperslab(vspace, H5S_SELECT_SET, start.data(),
                nullptr, count.data(), nullptr);
            const hid_t src =
                H5Screate_simple(int(count.size()), count.data(), nullptr);
            H5Pset_virtual(dcpl, vspace, segments[k].c_str(), s.name, src);
            H5Sclose(src);
            offset += records[k];
        }
        H5Sselect_all(vspace);
        const hid_t ds = H5Dcreate2(f, s.name, H5T_NATIVE_DOUBLE, vspace,
            H5P_DEFAULT, dcpl, H5P_DEFAULT);
        check(ds >= 0, "creating the virtual series in", path);
        H5Dclose(ds);
        H5Pclose(dcpl);
        H5Sclose(vspace);
    }
    particleHDF5Metadata::writeUnits(f);
    particleHDF5Metadata::writeDescription(f, description);
    check(H5Fclose(f) >= 0, "writing", path);
}


// ************************************************************************* //
