/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleHDF5Writer.H"
#include "particleHDF5Files.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "error.H"

#include <unistd.h>
#include <fcntl.h>
#include "SubList.H"

using namespace Foam::particleHDF5Files;

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Flush a closed file to the disk before it is renamed into place
void syncFile(const fileName& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd >= 0)
    {
        ::fsync(fd);
        ::close(fd);
    }
}

//- A name beside path that is not taken yet: path.suffix, path.suffix1, ...
fileName freeName(const fileName& path, const word& suffix)
{
    fileName name = path + "." + suffix;
    for (label i = 1; exists(name); ++i)
    {
        name = path + "." + suffix + Foam::name(i);
    }
    return name;
}

//- Records of a segment, 0 when it cannot be read (a kill while it was
//  created)
label nRecords(const fileName& path)
{
    scalarList t;
    particleHDF5Files::readTimes(path, t);
    return t.size();
}

//- Records of a committed segment before startTime (round-off tolerant)
label nRecordsBefore(const fileName& path, const scalar startTime)
{
    scalarList t;
    if (!particleHDF5Files::readTimes(path, t))
    {
        FatalErrorInFunction
            << "Cannot open " << path << ", listed in particles.h5: move"
            << " postProcessing/particles.h5 and postProcessing/particles/"
            << " away to start a new series" << exit(FatalError);
    }
    label keep = 0;
    while
    (
        keep < t.size() && t[keep] < startTime - 1e-12*(1 + mag(startTime))
    )
    {
        ++keep;
    }
    return keep;
}

//- particles/segment<k>.h5, relative to postProcessing
fileName segmentName(const label k)
{
    return fileName("particles")/word("segment" + Foam::name(k) + ".h5");
}

//- Index k of "segment<k>.h5", -1 for other names
label segmentIndex(const fileName& name)
{
    const std::string s(name.name());
    if (s.size() < 11 || s.compare(0, 7, "segment") != 0
     || s.compare(s.size() - 3, 3, ".h5") != 0)
    {
        return -1;
    }
    const std::string digits(s.substr(7, s.size() - 10));
    if (digits.empty()
     || digits.find_first_not_of("0123456789") != std::string::npos)
    {
        return -1;
    }
    return std::stol(digits);
}

} // namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::particleHDF5Writer::recover(const scalar startTime)
{
    const fileName dir = path_.path();
    mkDir(dir/"particles");

    const fileName tmp = path_ + ".tmp";
    if (isFile(tmp))
    {
        Info<< "particles.h5: removed " << tmp << ", a commit that a killed"
            << " run did not finish" << nl;
        rm(tmp);
    }

    if (isFile(path_))
    {
        adoptExisting();
    }
    removeUnlisted();
    if (!dropRecordsFrom(startTime) && (segments_.size() || isFile(path_)))
    {
        writeMaster();
    }
}


void Foam::particleHDF5Writer::adoptExisting()
{
    const fileName dir = path_.path();
    wordList listed;
    const label status = readSegmentList(path_, listed);
    if (status == unreadable)
    {
        const fileName aside = freeName(path_, "unreadable");
        mv(path_, aside);
        Info<< "particles.h5: " << path_ << " cannot be opened (written"
            << " by a killed run of an earlier version); moved to "
            << aside << ", the series starts afresh" << nl;
    }
    else if (status == plainSeries)
    {
        // Hard-linked, not moved: until the particles.h5 written below
        // replaces it, the old file stays what a kill would leave
        const fileName seg = segmentName(nextSegment());
        if (::link(path_.c_str(), (dir/seg).c_str()) != 0)
        {
            FatalErrorInFunction
                << "Cannot link " << path_ << " to " << dir/seg
                << exit(FatalError);
        }
        segments_.append(seg);
        records_.append(nRecords(dir/seg));
        Info<< "particles.h5: series of an earlier version kept as "
            << dir/seg << nl;
    }
    else
    {
        for (const word& w : listed)
        {
            segments_.append(fileName("particles")/w);
            records_.append(nRecords(dir/segments_.last()));
        }
    }
}


void Foam::particleHDF5Writer::removeUnlisted()
{
    const fileName dir = path_.path();
    // Segments that no particles.h5 lists: records a killed run wrote
    // after its last commit (or before a crash of the commit itself)
    for (const fileName& f : readDir(dir/"particles", fileName::FILE))
    {
        const fileName seg = fileName("particles")/f;
        if (segmentIndex(f) >= 0 && !segments_.found(seg))
        {
            Info<< "particles.h5: removed " << dir/seg << ", "
                << nRecords(dir/seg) << " uncommitted record(s) of a run"
                << " that stopped before its next write" << nl;
            rm(dir/seg);
        }
    }
}


bool Foam::particleHDF5Writer::dropRecordsFrom(const scalar startTime)
{
    const fileName dir = path_.path();
    // Records at or after the start time are recomputed by this run
    forAll(segments_, i)
    {
        const fileName file = dir/segments_[i];
        const label keep = nRecordsBefore(file, startTime);
        if (keep == records_[i])
        {
            continue;
        }
        // The new list first, then particles.h5 over it, and only then
        // the files it no longer lists are removed: a kill at any point
        // leaves a particles.h5 whose segments all exist
        const List<fileName> obsolete(SubList<fileName>(segments_,
            segments_.size() - i, i));
        label dropped = -keep;
        for (label j = i; j < records_.size(); ++j)
        {
            dropped += records_[j];
        }
        segments_.setSize(i);
        records_.setSize(i);
        if (keep > 0)
        {
            const fileName seg = segmentName(nextSegment());
            copyRecords(file, dir/seg, keep);
            segments_.append(seg);
            records_.append(keep);
        }
        writeMaster();
        for (const fileName& f : obsolete)
        {
            rm(dir/f);
        }
        Info<< "particles.h5: dropped " << dropped << " record(s) at or"
            << " after the start time " << startTime << " (this run"
            << " recomputes them)" << nl;
        return true;
    }
    return false;
}


Foam::label Foam::particleHDF5Writer::nextSegment() const
{
    label next = 0;
    const fileName dir = path_.path()/"particles";
    for (const fileName& f : readDir(dir, fileName::FILE))
    {
        next = max(next, segmentIndex(f) + 1);
    }
    return next;
}


void Foam::particleHDF5Writer::writeMaster() const
{
    const fileName tmp = path_ + ".tmp";
    writeVirtualSeries
    (
        tmp, radius_, group_, segments_, records_, description_
    );
    syncFile(tmp);
    if (!mv(tmp, path_))
    {
        FatalErrorInFunction
            << "Cannot rename " << tmp << " to " << path_
            << exit(FatalError);
    }
    scalarList times;
    readTimes(path_, times);
    particleHDF5Metadata::writeXDMF(path_, times, radius_.size());
}


void Foam::particleHDF5Writer::openSegment()
{
    openName_ = segmentName(nextSegment());
    open_ = createSegment(path_.path()/openName_, radius_, group_);
    openRecords_ = 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleHDF5Writer::particleHDF5Writer
(
    const fileName& path,
    const scalarField& radius,
    const labelList& group,
    const scalar startTime,
    const particleHDF5Metadata::description& description
)
:
    path_(path),
    radius_(radius),
    group_(group),
    description_(description),
    open_(-1),
    openRecords_(0)
{
    if (Pstream::master())
    {
        recover(startTime);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::particleHDF5Writer::~particleHDF5Writer()
{
    commit();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleHDF5Writer::append(const scalar time, const record& r)
{
    if (!Pstream::master())
    {
        return;
    }
    if (open_ < 0)
    {
        openSegment();
    }
    appendSeriesRecord
    (
        open_,
        time,
        {
            r.position.cdata()->cdata(),
            r.velocity.cdata()->cdata(),
            r.angularVelocity.cdata()->cdata(),
            r.force.cdata()->cdata(),
            r.torque.cdata()->cdata(),
            r.stresslet.cdata()->cdata(),
            r.dipoleTrace.cdata(),
            r.contactForce.cdata()->cdata(),
            r.contactTorque.cdata()->cdata(),
            r.contactStresslet.cdata()->cdata()
        }
    );
    ++openRecords_;
}


void Foam::particleHDF5Writer::commit()
{
    if (open_ < 0)
    {
        return;
    }
    closeSegment(open_);
    open_ = -1;
    segments_.append(openName_);
    records_.append(openRecords_);
    writeMaster();
}


Foam::label Foam::particleHDF5Writer::nCommitted() const
{
    label n = 0;
    for (const label r : records_)
    {
        n += r;
    }
    return n;
}


// ************************************************************************* //
