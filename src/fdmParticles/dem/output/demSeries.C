/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demSeries.H"
#include "freshOutputFile.H"
#include "OSspecific.H"
#include "Time.H"
#include "readBounded.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::fdm::demOutputDir(const Time& runTime)
{
    const fileName dir =
        runTime.globalPath()/"postProcessing"/"lubricatedDEM"
       /runTime.timeName();
    mkDir(dir);
    return dir;
}


Foam::label Foam::fdm::demSeries::readInterval(const dictionary& output)
{
    return label
    (
        readBoundedOrDefault
        (
            output, "interval", 100, 1, labelMax,
            "steps between time-series rows"
        )
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::demSeries::demSeries
(
    const Time& runTime,
    const lubricatedDEM& dem
)
{
    os_.reset
    (
        new OFstream(freshOutputFile(demOutputDir(runTime), "stress"))
    );
    os_->precision(10);
    OFstream& os = os_();
    os  << "# lubricatedDEM stress (particle stresslets / cell volume,"
        << " compression < 0), viscosity " << dem.model().viscosity()
        << ", shear rate " << dem.shearRate() << nl
        << "# time strain phi interactions contacts stabilityNumber";
    for (label p = 0; p < fdm::lubricatedInteraction::nStressParts; ++p)
    {
        const word n(fdm::lubricatedInteraction::stressPartName(p));
        os  << ' ' << n << "_xx " << n << "_yy " << n << "_zz "
            << n << "_xy";
    }
    os  << nl;
}


Foam::fdm::demTracks::demTracks
(
    const Time& runTime,
    const lubricatedDEM& dem,
    const dictionary& output
)
:
    track_(output.getOrDefault<labelList>("track", labelList()))
{
    for (const label i : track_)
    {
        if (i < 0 || i >= dem.size())
        {
            FatalIOErrorInFunction(output)
                << "track: particle " << i << " does not exist; the"
                << " particle list holds indices 0 to " << dem.size() - 1
                << exit(FatalIOError);
        }
    }
    if (track_.empty())
    {
        return;
    }
    os_.reset
    (
        new OFstream(freshOutputFile(demOutputDir(runTime), "tracks"))
    );
    os_->precision(12);
    OFstream& os = os_();
    os  << "# lubricatedDEM tracks: time, then x y z of particles";
    for (const label i : track_)
    {
        os  << ' ' << i;
    }
    os  << " (wrapped into the cell)" << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::demSeries::append(const lubricatedDEM& dem)
{
    OFstream& os = os_();
    os  << dem.time() << ' ' << dem.shearRate()*dem.time() << ' '
        << dem.volumeFraction() << ' ' << dem.nInteractions() << ' '
        << dem.nContacts() << ' ' << dem.stabilityNumber();
    for (label p = 0; p < fdm::lubricatedInteraction::nStressParts; ++p)
    {
        const symmTensor s = dem.stress(p);
        os  << ' ' << s.xx() << ' ' << s.yy() << ' ' << s.zz() << ' '
            << s.xy();
    }
    os  << endl;
}


void Foam::fdm::demTracks::append(const lubricatedDEM& dem)
{
    if (!os_.valid())
    {
        return;
    }
    OFstream& os = os_();
    os  << dem.time();
    for (const label i : track_)
    {
        const point& x = dem.positions()[i];
        os  << ' ' << x.x() << ' ' << x.y() << ' ' << x.z();
    }
    os  << nl;
}


// ************************************************************************* //
