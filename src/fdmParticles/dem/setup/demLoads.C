/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demLoads.H"
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


Foam::scalar Foam::fdm::shieldsFromAcrivos
(
    const fdm::lubricatedDEM& dem,
    const dictionary& dict,
    const vector& dir,
    const boolList& mobile,
    const scalar aMean
)
{
    const scalar A = fdm::readBounded
    (
        dict, "acrivosNumber", VSMALL, GREAT,
        "Acrivos number (9/2) eta gammaDot/((rho_p - rho_f) g h_0)"
    );
    const scalar phiM = fdm::readBounded
    (
        dict, "packingFraction", VSMALL, 1,
        "volume fraction phi_m of the settled bed, h_0 = V/phi_m"
    );
    const vector n = cmptMag(dir)/mag(dir);
    direction up = 0;
    for (direction d = 1; d < 3; ++d)
    {
        up = n[d] > n[up] ? d : up;
    }
    if (n[up] < 1 - 1e-9)
    {
        FatalIOErrorInFunction(dict)
            << "acrivosNumber: direction " << dir << " must lie along x, y"
            << " or z (the settled bed's height is measured along it)"
            << exit(FatalIOError);
    }
    const vector& L = dem.box().span();
    scalar volume = 0;
    forAll(mobile, i)
    {
        if (mobile[i])
        {
            volume += 4.0/3.0*constant::mathematical::pi*pow3(dem.radii()[i]);
        }
    }
    const scalar h0 = volume*L[up]/(L.x()*L.y()*L.z())/phiM;
    const scalar Sh = A*h0/(4.5*aMean);
    Info<< "    Acrivos number " << A << ", settled bed height h_0 = V/phi_m "
        << h0 << " (phi_m " << phiM << "): Shields number " << Sh << nl;
    return Sh;
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
    scalar aMean = 0;
    label nMobile = 0;
    forAll(mobile, i)
    {
        if (mobile[i])
        {
            aMean += dem.radii()[i];
            ++nMobile;
        }
    }
    aMean /= max(nMobile, label(1));

    vector g(Zero);
    if (dict.found("shieldsNumber") || dict.found("acrivosNumber"))
    {
        const vector dir = dict.get<vector>("direction");
        if (dict.found("shieldsNumber") && dict.found("acrivosNumber"))
        {
            FatalIOErrorInFunction(dict)
                << "give shieldsNumber or acrivosNumber, not both"
                << exit(FatalIOError);
        }
        if (mag(dir) < VSMALL || mag(dem.shearRate()) < VSMALL)
        {
            FatalIOErrorInFunction(dict)
                << "shieldsNumber and acrivosNumber need a non-zero"
                << " direction and a sheared cell (cell{shearRate}); give"
                << " the acceleration instead: value (0 -9.81 0);"
                << exit(FatalIOError);
        }
        const scalar Sh = dict.found("shieldsNumber")
          ? fdm::readBounded
            (
                dict, "shieldsNumber", VSMALL, GREAT,
                "Shields number eta gammaDot/((rho_p - rho_f) g a)"
            )
          : shieldsFromAcrivos(dem, dict, dir, mobile, aMean);
        g = dir/mag(dir)*dem.model().viscosity()*mag(dem.shearRate())
           /((rho - rhoF)*aMean*Sh);
    }
    else
    {
        g = dict.get<vector>("value");
    }

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
        Info<< ", Shields number "
            << dem.model().viscosity()*gammaDot/((rho - rhoF)*mag(g)*aMean)
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
