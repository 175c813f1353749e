/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "settlingGravity.H"
#include "checkKeywords.H"
#include "readBounded.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The axis a direction lies along, or stop: the settled bed's height is
//  measured along it
Foam::direction axisOf(const Foam::dictionary& dict, const Foam::vector& dir)
{
    using namespace Foam;
    const vector n = cmptMag(dir)/mag(dir);
    direction up = 0;
    for (direction d = 1; d < 3; ++d)
    {
        up = n[d] > n[up] ? d : up;
    }
    if (n[up] < 1 - 1e-9)
    {
        FatalIOErrorInFunction(dict)
            << "acrivosNumber in " << dict.name() << ": direction " << dir
            << " must lie along x, y or z (the settled bed's height is"
            << " measured along it)" << exit(FatalIOError);
    }
    return up;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fdm::gravityOfShields
(
    const settlingScales& s,
    const scalar Sh
)
{
    return s.viscosity*s.shearRate/(s.densityDifference*s.meanRadius*Sh);
}


Foam::scalar Foam::fdm::shieldsOfGravity
(
    const settlingScales& s,
    const scalar g
)
{
    return s.viscosity*s.shearRate/(s.densityDifference*s.meanRadius*g);
}


Foam::scalar Foam::fdm::settledBedHeight
(
    const settlingScales& s,
    const direction up,
    const scalar phiM
)
{
    return s.volume*s.span[up]/(s.span.x()*s.span.y()*s.span.z())/phiM;
}


Foam::vector Foam::fdm::readSettlingGravity
(
    const dictionary& dict,
    const settlingScales& s
)
{
    checkKeywords
    (
        dict,
        {"direction", "shieldsNumber", "acrivosNumber", "packingFraction",
         "value"},
        "gravity (direction with shieldsNumber, or with acrivosNumber and"
        " packingFraction; or value)"
    );
    const bool sh = dict.found("shieldsNumber");
    const bool ac = dict.found("acrivosNumber");
    if (!sh && !ac)
    {
        return dict.get<vector>("value");
    }
    const vector dir = dict.get<vector>("direction");
    if (sh == ac || dict.found("value"))
    {
        FatalIOErrorInFunction(dict)
            << "gravity in " << dict.name() << ": give shieldsNumber or"
            << " acrivosNumber, not both (acrivosNumber with"
            << " packingFraction), or value alone" << exit(FatalIOError);
    }
    if (mag(dir) < VSMALL || mag(s.shearRate) < VSMALL
     || !(s.densityDifference > 0))
    {
        FatalIOErrorInFunction(dict)
            << "gravity in " << dict.name() << ": shieldsNumber and"
            << " acrivosNumber need a non-zero direction, a sheared"
            << " suspension (shear rate " << s.shearRate << ") and"
            << " spheres heavier than the fluid (density difference "
            << s.densityDifference << "); otherwise give the acceleration:"
            << " value (0 -9.81 0);" << exit(FatalIOError);
    }
    scalar Sh = 0;
    if (sh)
    {
        Sh = readBounded
        (
            dict, "shieldsNumber", VSMALL, GREAT,
            "Shields number eta gammaDot/((rho_p - rho_f) g a)"
        );
    }
    else
    {
        const scalar A = readBounded
        (
            dict, "acrivosNumber", VSMALL, GREAT,
            "Acrivos number (9/2) eta gammaDot/((rho_p - rho_f) g h_0)"
        );
        const scalar phiM = readBounded
        (
            dict, "packingFraction", VSMALL, 1,
            "volume fraction phi_m of the settled bed, h_0 = V/phi_m"
        );
        const scalar h0 = settledBedHeight(s, axisOf(dict, dir), phiM);
        Sh = A*h0/(4.5*s.meanRadius);
        Info<< "    Acrivos number " << A << ", settled bed height h_0 ="
            << " V/phi_m " << h0 << " (phi_m " << phiM << "): Shields"
            << " number " << Sh << nl;
    }
    return dir/mag(dir)*gravityOfShields(s, Sh);
}


// ************************************************************************* //
