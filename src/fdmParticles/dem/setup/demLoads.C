/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demLoads.H"
#include "settlingGravity.H"
#include "readBounded.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::fdm::setDrag(lubricatedDEM& dem, const dictionary& props)
{
    const dictionary drag(props.subOrEmptyDict("drag"));
    // lubrication twoSphere includes the isolated sphere's drag: the same
    // viscosity on every particle, no extra drag
    const bool twoSphere = dem.model().twoSphereHydrodynamics();
    const scalar eta = dem.model().viscosity();
    const scalar viscosity = fdm::readBoundedOrDefault
    (
        drag, "viscosity", twoSphere ? eta : 0, 0, GREAT,
        "viscosity of the Stokes drag against the affine flow on every"
        " particle (0: none)"
    );
    const scalar isolatedViscosity = fdm::readBoundedOrDefault
    (
        drag, "isolatedViscosity", 0, 0, GREAT,
        "viscosity of the extra drag on particles with few interactions"
    );
    if (twoSphere && (viscosity != eta || isolatedViscosity != 0))
    {
        FatalIOErrorInFunction(drag)
            << "drag: lubricatedContact/lubrication twoSphere includes the"
            << " isolated sphere's drag with the fluid viscosity " << eta
            << "; allowed: drag/viscosity " << eta << " (the default) and"
            << " no isolatedViscosity (got viscosity " << viscosity
            << ", isolatedViscosity " << isolatedViscosity << ")"
            << exit(FatalIOError);
    }
    dem.setDrag(viscosity);
    dem.setIsolatedDrag
    (
        isolatedViscosity,
        label
        (
            fdm::readBoundedOrDefault
            (
                drag, "isolatedBelow", 3, 0, 1000,
                "interaction count below which the extra drag acts"
            )
        )
    );
}


void Foam::fdm::setGravity
(
    fdm::lubricatedDEM& dem,
    const dictionary& props,
    const scalar rho,
    const boolList& mobile
)
{
    if (!props.found("gravity"))
    {
        return;
    }
    const dictionary& dict = props.subDict("gravity");
    const scalar rhoF = fdm::readBoundedOrDefault
    (
        props, "fluidDensity", 0, 0, rho,
        "fluid density rho_f (buoyancy), below the particle density"
    );
    scalar aMean = 0, volume = 0;
    label nMobile = 0;
    forAll(mobile, i)
    {
        if (mobile[i])
        {
            aMean += dem.radii()[i];
            volume += 4.0/3.0*constant::mathematical::pi*pow3(dem.radii()[i]);
            ++nMobile;
        }
    }
    aMean /= max(nMobile, label(1));
    const fdm::settlingScales scales
    {
        dem.model().viscosity(), mag(dem.shearRate()), rho - rhoF, aMean,
        volume, dem.box().span()
    };
    const vector g = fdm::readSettlingGravity(dict, scales);

    forAll(mobile, i)
    {
        if (mobile[i])
        {
            dem.bodyForce(i) = (rho - rhoF)/rho*dem.masses()[i]*g;
        }
    }
    const scalar gammaDot = mag(dem.shearRate());
    Info<< "    gravity " << g << ", density difference " << rho - rhoF;
    if (gammaDot > 0)
    {
        Info<< ", Shields number " << fdm::shieldsOfGravity(scales, mag(g))
            << ", inertial number gammaDot sqrt(a/g) "
            << gammaDot*std::sqrt(aMean/max(mag(g), VSMALL));
    }
    Info<< nl;
}


void Foam::fdm::setPressureWall
(
    fdm::lubricatedDEM& dem,
    const dictionary& props,
    const fdm::particleList& list,
    const boolList& mobile
)
{
    if (!props.found("pressureWall"))
    {
        return;
    }
    const dictionary& dict = props.subDict("pressureWall");
    const word group = dict.get<word>("group");
    labelList spheres;
    forAll(list.group, i)
    {
        if (list.group[i] == group)
        {
            if (mobile[i])
            {
                FatalIOErrorInFunction(dict)
                    << "group: " << group << " must be one of fixedGroups"
                    << exit(FatalIOError);
            }
            spheres.append(i);
        }
    }
    direction normal = 3;
    label nOpen = 0;
    for (direction d = 0; d < 3; ++d)
    {
        if (!dem.box().periodic(d))
        {
            normal = d;
            ++nOpen;
        }
    }
    if (spheres.empty() || nOpen != 1)
    {
        FatalIOErrorInFunction(dict)
            << "pressureWall needs the spheres of group " << group
            << " (found " << spheres.size() << ") and exactly one open"
            << " direction in cell{open} (found " << nOpen << ")"
            << exit(FatalIOError);
    }
    const scalar pressure = fdm::readBounded
    (
        dict, "pressure", 0, GREAT, "imposed particle pressure P"
    );
    dem.setPressureWall
    (
        spheres,
        normal,
        pressure,
        fdm::readBounded
        (
            dict, "damping", VSMALL, GREAT,
            "wall damping c, v_w = (F - P A)/c (above deltaT times the"
            " summed contact stiffness on the wall)"
        )
    );
    Info<< "    pressure wall: " << spheres.size() << " spheres of group "
        << group << ", pressure " << pressure << nl;
}


// ************************************************************************* //
