/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demMonitor.H"
#include "Time.H"
#include "clockTime.H"
#include "isFinite.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::symmTensor Foam::fdm::totalStress(const lubricatedDEM& dem)
{
    symmTensor s(Zero);
    for (label p = 0; p < fdm::lubricatedInteraction::nStressParts; ++p)
    {
        s += dem.stress(p);
    }
    return s;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::demMonitor::report
(
    const lubricatedDEM& dem,
    const Time& runTime,
    const clockTime& clock,
    const scalar sMax
)
{
    const symmTensor s = totalStress(dem);
    const scalar etaGammaDot =
        dem.model().viscosity()*max(mag(dem.shearRate()), SMALL);
    timeLeft_.update
    (
        clock.elapsedTime(), runTime.elapsedCpuTime(), runTime.value()
    );
    Info<< "Time = " << runTime.timeName()
        << "  strain " << dem.shearRate()*dem.time()
        << "  eta_r " << s.xy()/etaGammaDot
        << "  mu " << s.xy()/max(-s.yy(), SMALL)
        << "  interactions " << dem.nInteractions()
        << "  contacts " << dem.nContacts()
        << "  crushed " << dem.nCrushed()
        << "  s " << sMax;
    if (dem.wallLoad() != 0)
    {
        Info<< "  wall load " << dem.wallLoad()
            << "  wall velocity " << dem.wallVelocity();
    }
    Info
        << "  left " << label(timeLeft_.seconds(runTime.endTime().value()))
        << " s" << endl;
}


void Foam::fdm::demMonitor::check
(
    const lubricatedDEM& dem,
    const Time& runTime
)
{
    if (!warnedCrushed_ && dem.nCrushed() > 0)
    {
        warnedCrushed_ = true;
        WarningInFunction
            << "Time " << runTime.timeName() << ": " << dem.nCrushed()
            << " contacts carry more than the asperity force k_n eps a;"
            << " their gap closes exponentially and the pairs stay glued"
            << " (contact number k_n eps a/F below 1, thesis 2 eq 38)."
            << nl << "    Raise stiffness or roughness in"
            << " constant/particleProperties (lubricatedContact)" << endl;
    }

    const fdm::periodicBox& box = dem.box();
    forAll(dem.positions(), i)
    {
        const point& x = dem.positions()[i];
        if (!fdm::isFinite(x))
        {
            FatalErrorInFunction
                << "Time " << runTime.timeName() << ": particle " << i
                << " has the position " << x << ", not finite.  Lower deltaT"
                << " in system/controlDict." << nl << "    Last good state:"
                << " the latest time directory" << exit(FatalError);
        }
        for (direction d = 0; d < 3; ++d)
        {
            if
            (
                !box.periodic(d)
             && (x[d] < box.min()[d] || x[d] > box.min()[d] + box.span()[d])
            )
            {
                FatalErrorInFunction
                    << "Time " << runTime.timeName() << ": particle " << i
                    << " at " << x << " left the cell through its open"
                    << " direction " << vector::componentNames[d]
                    << " (cell from "
                    << box.min()[d] << " to "
                    << box.min()[d] + box.span()[d] << ").  Enlarge the"
                    << " cell in constant/particleProperties (cell{min,"
                    << " max}) or lower the shear rate against gravity."
                    << nl << "    Last good state: the latest time"
                    << " directory" << exit(FatalError);
            }
        }
    }

    const scalar s = dem.stabilityNumber();
    const symmTensor sigma = totalStress(dem);
    if (s < 1 && std::isfinite(sigma.xy()) && std::isfinite(sigma.yy()))
    {
        return;
    }
    FatalErrorInFunction
        << "Time " << runTime.timeName() << ": ";
    if (!(s < 1))
    {
        FatalError
            << "stability number " << s << " >= 1: the leapfrog step is"
            << " unstable for the stiffest particle (sum of its"
            << " interaction stiffnesses against its mass).  Lower deltaT"
            << " in system/controlDict to about "
            << 0.5*runTime.deltaTValue()/max(s, SMALL)
            << " or lower the stiffness in constant/particleProperties";
    }
    else
    {
        FatalError
            << "the stress is not finite (NaN or overflow).  Lower deltaT"
            << " in system/controlDict";
    }
    FatalError
        << "." << nl << "    Last good state: the latest time directory"
        << " written before " << runTime.timeName() << exit(FatalError);
}


// ************************************************************************* //
