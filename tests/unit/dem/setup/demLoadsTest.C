// Unit tests of the loads lubricatedDEMFoam reads besides the pair
// interactions: Stokes drag against the affine flow (thesis 2, article 1,
// eqs 40-41), the weight from an acceleration, a Shields number (article 3,
// eq 4) or an Acrivos number, and the pressure wall's input checks.

#include "demLoads.H"
#include "unitTestHelpers.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

#include <string>

using namespace Foam;
using Foam::constant::mathematical::pi;
using unitTest::parse;
using unitTest::errorOf;

namespace
{

// Viscosity 1, no pair reaches beyond 1e-3 (the spheres below stay apart)
fdm::lubricatedContact model()
{
    return fdm::lubricatedContact(1, 1e4, 1, 1e3, 1e-3, 0.5, 1e-3);
}

// Two spheres of radius 1 and density 2 far apart in a 20^3 cell open
// along y (no sheared images), shear rate gammaDot; the second is fixed
fdm::lubricatedDEM twoSpheres(const scalar gammaDot)
{
    FixedList<bool, 3> periodic(true);
    periodic[1] = false;
    fdm::lubricatedDEM dem
    (
        fdm::periodicBox(point::zero, point(20, 20, 20), periodic),
        gammaDot,
        model()
    );
    dem.addParticle(point(5, 10, 5), 1, 2);
    dem.addParticle(point(15, 1, 15), 1, 2, false);
    return dem;
}

} // namespace


TEST(demLoads, dragSlowsAFreeSphereImplicitly)
{
    // Without shear the fluctuation decays as v+ = m v/(m + dt 6 pi eta a)
    fdm::lubricatedDEM dem(twoSpheres(0));
    fdm::setDrag(dem, parse("drag { viscosity 0.5; }"));
    dem.velocities()[0] = vector(1, 0, 0);
    const scalar m = dem.masses()[0];
    const scalar dt = 0.01;
    dem.step(dt);
    EXPECT_NEAR
    (
        dem.velocities()[0].x(), m/(m + dt*6*pi*0.5), 1e-14
    );

    // No drag block: no drag
    fdm::lubricatedDEM free(twoSpheres(0));
    fdm::setDrag(free, parse("other 1;"));
    free.velocities()[0] = vector(1, 0, 0);
    free.step(dt);
    EXPECT_EQ(free.velocities()[0].x(), 1);
}


TEST(demLoads, twoSphereLubricationBringsItsOwnDrag)
{
    // lubrication twoSphere includes the isolated drag at the fluid
    // viscosity: the default, and any other value an error
    auto twoSphereDEM = []()
    {
        fdm::lubricatedContact law(model());
        law.useTwoSphereHydrodynamics();
        fdm::lubricatedDEM dem(fdm::periodicBox(point::zero,
            point(20, 20, 20), FixedList<bool, 3>(true)), 0, law);
        dem.addParticle(point(5, 10, 5), 1, 2);
        return dem;
    };
    fdm::lubricatedDEM dem(twoSphereDEM());
    fdm::setDrag(dem, parse("other 1;"));
    dem.velocities()[0] = vector(1, 0, 0);
    const scalar m = dem.masses()[0];
    dem.step(0.01);
    EXPECT_NEAR(dem.velocities()[0].x(), m/(m + 0.01*6*pi), 1e-14);

    for (const char* bad :
        {"drag { viscosity 0.5; }", "drag { isolatedViscosity 1; }"})
    {
        fdm::lubricatedDEM other(twoSphereDEM());
        const std::string msg =
            errorOf([&]() { fdm::setDrag(other, parse(bad)); });
        EXPECT_NE(msg.find("lubrication twoSphere includes"),
            std::string::npos) << bad << ": " << msg;
    }
}


TEST(demLoads, weightFromTheAcceleration)
{
    // (rho_p - rho_f) V g on the mobile sphere only
    fdm::lubricatedDEM dem(twoSpheres(1));
    const boolList mobile({true, false});
    fdm::setGravity
    (
        dem,
        parse("gravity { value (0 -10 0); } fluidDensity 0.5;"),
        2,
        mobile
    );
    const scalar V = 4.0/3.0*pi;
    EXPECT_NEAR(dem.bodyForce(0).y(), -(2 - 0.5)*V*10, 1e-12);
    EXPECT_EQ(dem.bodyForce(1), vector::zero);
}


TEST(demLoads, weightFromTheShieldsNumber)
{
    // Sh = eta gammaDot/((rho_p - rho_f) g a): g = 1*2/(2*1*0.5) = 2
    fdm::lubricatedDEM dem(twoSpheres(2));
    const boolList mobile({true, false});
    fdm::setGravity
    (
        dem,
        parse("gravity { direction (0 -3 0); shieldsNumber 0.5; }"),
        2,
        mobile
    );
    const scalar V = 4.0/3.0*pi;
    EXPECT_NEAR(dem.bodyForce(0).y(), -2*V*2, 1e-12);

    // Both numbers, or a Shields number without shear, stop the run
    fdm::lubricatedDEM both(twoSpheres(2));
    EXPECT_NE
    (
        errorOf
        (
            [&]
            {
                fdm::setGravity
                (
                    both,
                    parse
                    (
                        "gravity { direction (0 -1 0); shieldsNumber 1;"
                        " acrivosNumber 1; packingFraction 0.6; }"
                    ),
                    2,
                    mobile
                );
            }
        ).find("not both"),
        std::string::npos
    );
    fdm::lubricatedDEM still(twoSpheres(0));
    EXPECT_NE
    (
        errorOf
        (
            [&]
            {
                fdm::setGravity
                (
                    still,
                    parse("gravity { direction (0 -1 0); shieldsNumber 1; }"),
                    2,
                    mobile
                );
            }
        ),
        ""
    );
}


TEST(demLoads, pressureWallNeedsFixedSpheresAndOneOpenDirection)
{
    fdm::lubricatedDEM dem(twoSpheres(1));
    const boolList mobile({true, false});
    fdm::particleList list;
    list.group.append("bed");
    list.group.append("lid");
    const std::string wall =
        "pressureWall { group lid; pressure 2; damping 100; }";
    EXPECT_EQ
    (
        errorOf
        (
            [&]
            {
                fdm::setPressureWall(dem, parse(wall.c_str()), list, mobile);
            }
        ),
        ""
    );
    EXPECT_NE
    (
        errorOf
        (
            [&]
            {
                fdm::setPressureWall
                (
                    dem,
                    parse("pressureWall { group bed; pressure 2; damping 1; }"),
                    list,
                    mobile
                );
            }
        ).find("must be one of fixedGroups"),
        std::string::npos
    );
}


// ************************************************************************* //
