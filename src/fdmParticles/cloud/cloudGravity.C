/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "cloudGravity.H"
#include "planeWalls.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::fdm::settlingScales Foam::fdm::heavySphereScales
(
    const UList<particleGroup>& groups,
    const particleState& state,
    const scalar rhoFluid,
    const scalar eta,
    const scalar gammaDot,
    const vector& span
)
{
    settlingScales s{eta, gammaDot, 0, 0, 0, span};
    label n = 0;
    forAll(state.radius, p)
    {
        const particleGroup& g = groups[state.group[p]];
        if (g.translationPrescribed() || g.density() == rhoFluid)
        {
            continue;
        }
        const scalar drho = g.density() - rhoFluid;
        if (n > 0 && drho != s.densityDifference)
        {
            FatalErrorInFunction
                << "gravity by a Shields or Acrivos number: the free spheres"
                << " of other density than the fluid must share one density"
                << " (found " << s.densityDifference + rhoFluid << " and "
                << g.density() << " in group " << g.name() << "); give the"
                << " acceleration instead: gravity (0 -9.81 0);"
                << exit(FatalError);
        }
        s.densityDifference = drho;
        s.meanRadius += state.radius[p];
        s.volume +=
            4.0/3.0*constant::mathematical::pi*pow3(state.radius[p]);
        ++n;
    }
    s.meanRadius /= max(n, label(1));
    return s;
}


Foam::vector Foam::fdm::readCloudGravity
(
    const dictionary& props,
    const fvMesh& mesh,
    const UList<particleGroup>& groups,
    const particleState& state,
    const scalar rhoFluid,
    const scalar eta
)
{
    if (!props.isDict("gravity"))
    {
        return props.getOrDefault<vector>("gravity", Zero);
    }
    const dictionary& dict = props.subDict("gravity");
    const bool byNumber =
        dict.found("shieldsNumber") || dict.found("acrivosNumber");
    const scalar gammaDot =
        planeWalls(mesh, "gravity", false).shearRate();
    const settlingScales s = byNumber
      ? heavySphereScales
        (
            groups, state, rhoFluid, eta, gammaDot, mesh.bounds().span()
        )
      : settlingScales{eta, gammaDot, 0, 0, 0, mesh.bounds().span()};
    const vector g = readSettlingGravity(dict, s);
    Info<< "    gravity " << g;
    if (byNumber)
    {
        Info<< ", Shields number " << shieldsOfGravity(s, mag(g))
            << " (heavy spheres: density difference " << s.densityDifference
            << ", mean radius " << s.meanRadius << ", wall shear rate "
            << gammaDot << ")";
    }
    Info<< nl;
    return g;
}


// ************************************************************************* //
