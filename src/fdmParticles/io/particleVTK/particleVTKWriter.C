/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleVTKWriter.H"
#include "OSspecific.H"
#include "OFstream.H"
#include "error.H"
#include "readBounded.H"

// * * * * * * * * * * * * * * * * vtkPolyFile  * * * * * * * * * * * * * * //

Foam::fdm::vtkPolyFile::vtkPolyFile
(
    const fileName& path,
    const scalar time,
    const UList<point>& points,
    const bool lines,
    const bool ascii
)
:
    path_(path),
    tmp_(path + ".tmp"),
    os_(new std::ofstream(tmp_)),
    format_
    (
        vtk::newFormatter
        (
            *os_,
            ascii ? vtk::formatType::INLINE_ASCII
                  : vtk::formatType::INLINE_BASE64
        )
    ),
    size_(lines ? points.size()/2 : points.size()),
    pointData_(!lines)
{
    vtk::formatter& f = format_();
    f.xmlHeader().beginVTKFile<vtk::fileTag::POLY_DATA>();

    f.beginFieldData();
    f.writeTimeValue(time);
    f.endFieldData();

    f.tag
    (
        vtk::fileTag::PIECE,
        vtk::fileAttr::NUMBER_OF_POINTS, points.size(),
        lines ? vtk::fileAttr::NUMBER_OF_LINES : vtk::fileAttr::NUMBER_OF_VERTS,
        size_
    );

    f.tag(vtk::fileTag::POINTS)
        .beginDataArray<float, 3>(vtk::dataArrayAttr::POINTS);
    f.writeSize(vtk::sizeofData<float, 3>(points.size()));
    vtk::writeList(f, points);
    f.flush();
    f.endDataArray();
    f.endTag(vtk::fileTag::POINTS);

    // Cells: vertex k is point k; line k joins points 2k and 2k + 1
    const label nPerCell = lines ? 2 : 1;
    labelList offsets(size_);
    forAll(offsets, k)
    {
        offsets[k] = nPerCell*(k + 1);
    }
    const vtk::fileTag cells =
        lines ? vtk::fileTag::LINES : vtk::fileTag::VERTS;
    f.tag(cells);
    f.beginDataArray<label>(vtk::dataArrayAttr::CONNECTIVITY);
    f.writeSize(vtk::sizeofData<label>(points.size()));
    vtk::writeIdentity(f, points.size());
    f.flush();
    f.endDataArray();
    f.beginDataArray<label>(vtk::dataArrayAttr::OFFSETS);
    f.writeSize(vtk::sizeofData<label>(size_));
    vtk::writeList(f, offsets);
    f.flush();
    f.endDataArray();
    f.endTag(cells);

    if (pointData_)
    {
        f.beginPointData();
    }
    else
    {
        f.beginCellData();
    }
}


Foam::fdm::vtkPolyFile::~vtkPolyFile()
{
    // Not closed (an error on the way): the whole files stay as they were
    if (format_.valid())
    {
        format_.clear();
        os_.reset();
        rm(tmp_);
    }
}


void Foam::fdm::vtkPolyFile::close()
{
    vtk::formatter& f = format_();
    if (pointData_)
    {
        f.endPointData();
    }
    else
    {
        f.endCellData();
    }
    f.endPiece();
    f.endTag(vtk::fileTag::POLY_DATA);
    f.endVTKFile();
    format_.clear();
    os_->flush();
    const bool good = os_->good();
    os_.reset();
    if (!good)
    {
        rm(tmp_);
        FatalErrorInFunction
            << "Cannot write " << tmp_ << " (disk full?)" << exit(FatalError);
    }
    mv(tmp_, path_);
}


// * * * * * * * * * * * * * * particleVTKWriter * * * * * * * * * * * * * //

Foam::fdm::particleVTKWriter::particleVTKWriter
(
    const fileName& dir,
    const scalar startTime,
    const bool ascii
)
:
    dir_(dir),
    ascii_(ascii)
{
    // Continue the series of earlier runs up to (not including) the start
    // time, which this run writes again; listed files that are gone drop
    particles_.load(dir_/"particles.vtp", true);
    particles_.removeNewer(startTime);
    contacts_.load(dir_/"contacts.vtp", true);
    contacts_.removeNewer(startTime);
}


Foam::label Foam::fdm::particleVTKWriter::readInterval
(
    const dictionary& output
)
{
    return label
    (
        readBoundedOrDefault
        (
            output, "vtkInterval", 0, 0, labelMax,
            "steps between VTK files (0: at the write times)"
        )
    );
}


void Foam::fdm::particleVTKWriter::publish
(
    vtk::seriesWriter& series,
    const word& base,
    const scalar time,
    const fileName& file
) const
{
    series.append(time, file);
    series.sort();
    const fileName path = dir_/base + ".vtp.series";
    {
        OFstream os(path + ".tmp");
        series.print(os);
    }
    mv(path + ".tmp", path);
}


Foam::fdm::particleVTKWriter::particleFile::particleFile
(
    particleVTKWriter& writer,
    const fileName& name,
    const scalar time,
    const UList<point>& positions
)
:
    writer_(writer),
    file_(writer.dir_/name, time, positions, false, writer.ascii_),
    time_(time),
    name_(name)
{}


void Foam::fdm::particleVTKWriter::particleFile::close()
{
    file_.close();
    writer_.publish(writer_.particles_, "particles", time_, name_);
}


Foam::fdm::particleVTKWriter::particleFile
Foam::fdm::particleVTKWriter::particles
(
    const word& timeName,
    const scalar time,
    const UList<point>& positions
)
{
    mkDir(dir_);
    return particleFile(*this, "particles_" + timeName + ".vtp", time,
        positions);
}


void Foam::fdm::particleVTKWriter::contacts
(
    const word& timeName,
    const scalar time,
    const UList<point>& positions,
    const UList<contactLink>& network
)
{
    mkDir(dir_);
    const label n = network.size();
    List<point> ends(2*n);
    labelList i(n), j(n);
    scalarList normalForce(n);
    List<vector> tangentialForce(n), force(n);
    forAll(network, k)
    {
        const contactLink& c = network[k];
        ends[2*k] = positions[c.i];
        ends[2*k + 1] = positions[c.i] + c.branch;
        i[k] = c.i;
        j[k] = c.j;
        normalForce[k] = c.normalForce;
        tangentialForce[k] = c.tangentialForce;
        force[k] = c.force();
    }
    const fileName name = "contacts_" + timeName + ".vtp";
    vtkPolyFile f(dir_/name, time, ends, true, ascii_);
    f.write("i", i);
    f.write("j", j);
    f.write("normalForce", normalForce);
    f.write("tangentialForce", tangentialForce);
    f.write("force", force);
    f.close();
    publish(contacts_, "contacts", time, name);
}


// ************************************************************************* //
