/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleHDF5Writer.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "error.H"

#include <hdf5.h>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

void check(const herr_t status, const char* what, const fileName& path)
{
    if (status < 0)
    {
        FatalErrorInFunction
            << "HDF5 error while " << what << " in " << path
            << exit(FatalError);
    }
}

// Create an extendible dataset of shape (0, tail...) chunked per record
void createSeries(hid_t file, const char* name, std::vector<hsize_t> tail)
{
    std::vector<hsize_t> dims{0}, maxDims{H5S_UNLIMITED}, chunk{1};
    for (const hsize_t t : tail)
    {
        dims.push_back(t);
        maxDims.push_back(t);
        chunk.push_back(t);
    }
    const hid_t space =
        H5Screate_simple(int(dims.size()), dims.data(), maxDims.data());
    const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(plist, int(chunk.size()), chunk.data());
    const hid_t ds = H5Dcreate2(file, name, H5T_NATIVE_DOUBLE, space,
        H5P_DEFAULT, plist, H5P_DEFAULT);
    H5Dclose(ds);
    H5Pclose(plist);
    H5Sclose(space);
}

// Append one record (row of the first axis) to a dataset
void appendRecord(hid_t file, const char* name, const double* data)
{
    const hid_t ds = H5Dopen2(file, name, H5P_DEFAULT);
    hid_t space = H5Dget_space(ds);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(rank);
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    H5Sclose(space);

    std::vector<hsize_t> newDims(dims), start(rank, 0), count(dims);
    newDims[0] += 1;
    start[0] = dims[0];
    count[0] = 1;
    H5Dset_extent(ds, newDims.data());

    space = H5Dget_space(ds);
    H5Sselect_hyperslab(space, H5S_SELECT_SET, start.data(), nullptr,
        count.data(), nullptr);
    const hid_t mem = H5Screate_simple(rank, count.data(), nullptr);
    H5Dwrite(ds, H5T_NATIVE_DOUBLE, mem, space, H5P_DEFAULT, data);
    H5Sclose(mem);
    H5Sclose(space);
    H5Dclose(ds);
}

// Shrink the first axis of a dataset to n records
void truncateSeries(hid_t file, const char* name, const hsize_t n)
{
    const hid_t ds = H5Dopen2(file, name, H5P_DEFAULT);
    const hid_t space = H5Dget_space(ds);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(rank);
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    H5Sclose(space);
    dims[0] = n;
    H5Dset_extent(ds, dims.data());
    H5Dclose(ds);
}

//- The per-record series and the shape of one record per particle:
//  vectors (3), the stresslet as symmTensor components xx xy xz yy yz zz
//  (6) and the trace of the force dipole (scalar)
struct seriesShape
{
    const char* name;
    hsize_t components;
};

const seriesShape series[] =
{
    {"position", 3}, {"velocity", 3}, {"angularVelocity", 3},
    {"force", 3}, {"torque", 3}, {"stresslet", 6}, {"dipoleTrace", 1},
    {"contactForce", 3}, {"contactTorque", 3}, {"contactStresslet", 6}
};

std::vector<hsize_t> recordShape(const hsize_t n, const seriesShape& s)
{
    return s.components == 1
        ? std::vector<hsize_t>{n} : std::vector<hsize_t>{n, s.components};
}

} // namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleHDF5Writer::particleHDF5Writer
(
    const fileName& path,
    const scalarField& radius,
    const labelList& group,
    const scalar startTime
)
:
    path_(path),
    nParticles_(radius.size()),
    file_(-1)
{
    if (!Pstream::master())
    {
        return;
    }
    mkDir(path.path());

    if (isFile(path))
    {
        // Continue an existing series: keep the records before startTime
        const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
        check(f < 0 ? -1 : 0, "opening", path);
        file_ = f;

        const hid_t ds = H5Dopen2(f, "time", H5P_DEFAULT);
        const hid_t space = H5Dget_space(ds);
        hsize_t n = 0;
        H5Sget_simple_extent_dims(space, &n, nullptr);
        std::vector<double> t(n);
        if (n)
        {
            H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                t.data());
        }
        H5Sclose(space);
        H5Dclose(ds);

        hsize_t keep = 0;
        while (keep < n && t[keep] < startTime - 1e-12*(1 + mag(startTime)))
        {
            ++keep;
        }
        truncateSeries(f, "time", keep);
        for (const seriesShape& s : series)
        {
            if (H5Lexists(f, s.name, H5P_DEFAULT) > 0)
            {
                truncateSeries(f, s.name, keep);
            }
            else if (keep == 0)
            {
                // A file from an older version without this series
                createSeries(f, s.name, recordShape(nParticles_, s));
            }
            else
            {
                FatalErrorInFunction
                    << path << " has records but no series '" << s.name
                    << "' (written by an older version): move it away to "
                    << "start a new series"
                    << exit(FatalError);
            }
        }
        return;
    }

    const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT,
        H5P_DEFAULT);
    check(f < 0 ? -1 : 0, "creating", path);
    file_ = f;

    const hsize_t n = nParticles_;
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    hid_t ds = H5Dcreate2(f, "radius", H5T_NATIVE_DOUBLE, space,
        H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (n)
    {
        H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
            radius.cdata());
    }
    H5Dclose(ds);
    std::vector<int> g(group.begin(), group.end());
    ds = H5Dcreate2(f, "group", H5T_NATIVE_INT, space, H5P_DEFAULT,
        H5P_DEFAULT, H5P_DEFAULT);
    if (n)
    {
        H5Dwrite(ds, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, g.data());
    }
    H5Dclose(ds);
    H5Sclose(space);

    createSeries(f, "time", {});
    for (const seriesShape& s : series)
    {
        createSeries(f, s.name, recordShape(n, s));
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::particleHDF5Writer::~particleHDF5Writer()
{
    if (file_ >= 0)
    {
        H5Fclose(hid_t(file_));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleHDF5Writer::appendVectors
(
    const char* name,
    const List<vector>& v
)
{
    // Foam::vector is three contiguous doubles
    appendRecord(hid_t(file_), name,
        reinterpret_cast<const double*>(v.cdata()));
}


void Foam::particleHDF5Writer::appendSymmTensors
(
    const char* name,
    const List<symmTensor>& s
)
{
    // Foam::symmTensor is six contiguous doubles (xx xy xz yy yz zz)
    appendRecord(hid_t(file_), name,
        reinterpret_cast<const double*>(s.cdata()));
}


void Foam::particleHDF5Writer::append(const scalar time, const record& r)
{
    if (file_ < 0)
    {
        return;
    }
    appendRecord(hid_t(file_), "time", &time);
    appendVectors("position", r.position);
    appendVectors("velocity", r.velocity);
    appendVectors("angularVelocity", r.angularVelocity);
    appendVectors("force", r.force);
    appendVectors("torque", r.torque);
    appendSymmTensors("stresslet", r.stresslet);
    appendRecord(hid_t(file_), "dipoleTrace", r.dipoleTrace.cdata());
    appendVectors("contactForce", r.contactForce);
    appendVectors("contactTorque", r.contactTorque);
    appendSymmTensors("contactStresslet", r.contactStresslet);
    H5Fflush(hid_t(file_), H5F_SCOPE_LOCAL);
}


// ************************************************************************* //
