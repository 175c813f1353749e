/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleHDF5Metadata.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "OStringStream.H"

#include <hdf5.h>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

struct datasetUnits
{
    const char* name;
    const char* units;
    //- Components per particle in the XDMF companion (0: not shown there)
    int components;
};

const datasetUnits units[] =
{
    {"time", "s", 0},
    {"radius", "m", 1},
    {"group", "1 (index into the root attribute groupNames)", 0},
    {"position", "m", 3},
    {"velocity", "m/s", 3},
    {"angularVelocity", "1/s", 3},
    {"force", "N", 3},
    {"torque", "N m", 3},
    {"stresslet", "N m", 6},
    {"dipoleTrace", "N m", 1},
    {"contactForce", "N", 3},
    {"contactTorque", "N m", 3},
    {"contactStresslet", "N m", 6}
};

} // namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::particleHDF5Metadata::writeText
(
    const long long object,
    const char* name,
    const std::string& text
)
{
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, text.size() + 1);
    const hid_t space = H5Screate(H5S_SCALAR);
    if (H5Aexists(hid_t(object), name) > 0)
    {
        H5Adelete(hid_t(object), name);
    }
    const hid_t a = H5Acreate2(hid_t(object), name, type, space,
        H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, type, text.c_str());
    H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
}


Foam::particleHDF5Metadata::description
Foam::particleHDF5Metadata::runDescription
(
    const std::string& solver,
    const fileName& caseDir,
    const wordList& groupNames,
    const dictionary& particleProperties,
    const scalar viscosity,
    const scalar shearRate,
    const boundBox& cell,
    const FixedList<bool, 3>& periodic
)
{
    std::string groups;
    for (const word& g : groupNames)
    {
        groups += g + "\n";
    }
    dictionary parameters(particleProperties);
    parameters.remove("particles");
    OStringStream entries;
    parameters.write(entries, false);
    auto numbers = [](const vector& v)
    {
        return std::vector<double>{v.x(), v.y(), v.z()};
    };

    description d;
    d.text =
    {
        {"solver", solver},
        {"openfoamApi", std::to_string(OPENFOAM)},
        {"case", caseDir},
        {"groupNames", groups},
        {"particleProperties", entries.str()}
    };
    d.numbers =
    {
        {"viscosity", {viscosity}},
        {"shearRate", {shearRate}},
        {"boxMin", numbers(cell.min())},
        {"boxMax", numbers(cell.max())},
        {
            "periodic",
            {double(periodic[0]), double(periodic[1]), double(periodic[2])}
        }
    };
    return d;
}


void Foam::particleHDF5Metadata::writeUnits(const long long file)
{
    const hid_t f = file;
    for (const datasetUnits& u : units)
    {
        if (H5Lexists(f, u.name, H5P_DEFAULT) <= 0)
        {
            continue;
        }
        const hid_t ds = H5Dopen2(f, u.name, H5P_DEFAULT);
        writeText(ds, "units", u.units);
        if (u.components == 6)
        {
            writeText(ds, "components", "xx xy xz yy yz zz");
        }
        H5Dclose(ds);
    }
}


void Foam::particleHDF5Metadata::writeDescription
(
    const long long file,
    const description& d
)
{
    const hid_t f = file;
    for (const auto& t : d.text)
    {
        writeText(f, t.first.c_str(), t.second);
    }
    for (const auto& n : d.numbers)
    {
        const hsize_t size = n.second.size();
        const hid_t space = H5Screate_simple(1, &size, nullptr);
        const hid_t a = H5Acreate2(f, n.first.c_str(), H5T_NATIVE_DOUBLE,
            space, H5P_DEFAULT, H5P_DEFAULT);
        H5Awrite(a, H5T_NATIVE_DOUBLE, n.second.data());
        H5Aclose(a);
        H5Sclose(space);
    }
}


void Foam::particleHDF5Metadata::writeXDMF
(
    const fileName& h5,
    const UList<scalar>& times,
    const label nParticles
)
{
    const fileName xmf = h5.lessExt() + ".xmf";
    const label T = times.size();
    const label N = nParticles;
    OFstream os(xmf + ".tmp");
    os.precision(16);
    os  << "<?xml version=\"1.0\" ?>\n"
        << "<Xdmf Version=\"3.0\">\n<Domain>\n"
        << "<Grid Name=\"particles\" GridType=\"Collection\""
        << " CollectionType=\"Temporal\">\n";

    // Record k of a (T, N[, c]) series, or the static (N) radius: a
    // hyperslab given by its start, stride and count per axis
    auto slab = [&](const label k, const datasetUnits& u)
    {
        const bool series = std::string(u.name) != "radius";
        const int c = u.components;
        const std::string shape =
            std::to_string(N) + (c > 1 ? " " + std::to_string(c) : "");
        const int rank = series ? (c > 1 ? 3 : 2) : 1;
        std::ostringstream item;
        item<< "<DataItem ItemType=\"HyperSlab\" Dimensions=\""
            << (series ? "1 " : "") << shape << "\">\n"
            << "<DataItem Dimensions=\"3 " << rank << "\" Format=\"XML\">";
        if (series)
        {
            item<< k << " 0" << (c > 1 ? " 0" : "") << "  1 1"
                << (c > 1 ? " 1" : "") << "  1 " << shape;
        }
        else
        {
            item<< "0 1 " << N;
        }
        item<< "</DataItem>\n<DataItem Dimensions=\""
            << (series ? std::to_string(T) + " " : "") << shape
            << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
            << h5.name().c_str() << ":/" << u.name
            << "</DataItem>\n</DataItem>\n";
        os  << item.str().c_str();
    };

    for (label k = 0; k < T; ++k)
    {
        os  << "<Grid Name=\"record" << k << "\" GridType=\"Uniform\">\n"
            << "<Time Value=\"" << times[k] << "\" />\n"
            << "<Topology TopologyType=\"Polyvertex\" NumberOfElements=\""
            << N << "\" />\n<Geometry GeometryType=\"XYZ\">\n";
        slab(k, units[3]);
        os  << "</Geometry>\n";
        for (const datasetUnits& u : units)
        {
            if (u.components == 0 || word(u.name) == "position")
            {
                continue;
            }
            os  << "<Attribute Name=\"" << u.name << "\" Center=\"Node\""
                << " AttributeType=\""
                << (u.components == 1 ? "Scalar"
                  : u.components == 3 ? "Vector" : "Tensor6")
                << "\">\n";
            slab(k, u);
            os  << "</Attribute>\n";
        }
        os  << "</Grid>\n";
    }
    os  << "</Grid>\n</Domain>\n</Xdmf>\n";
    os.flush();
    if (os.good())
    {
        mv(xmf + ".tmp", xmf);
    }
}


// ************************************************************************* //
