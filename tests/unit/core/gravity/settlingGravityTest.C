// Unit tests of the settling gravity both solvers read: the Shields number
// (thesis 2, article 3, eq 4) and its inverse by hand, the settled bed
// height and the Acrivos number, the three forms of the gravity{} block and
// its input errors.

#include "settlingGravity.H"
#include "unitTestHelpers.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;
using Foam::constant::mathematical::pi;
using unitTest::parse;
using unitTest::errorOf;

namespace
{

// eta 2, gammaDot 3, drho 0.5, a 1.5, one unit sphere in a 20 x 10 x 20 box
const fdm::settlingScales scales{2, 3, 0.5, 1.5, 4.0/3.0*pi, {20, 10, 20}};

} // namespace


TEST(settlingGravity, shieldsNumberAndItsInverse)
{
    // Sh = eta gammaDot/(drho g a): g = 6/(0.5 1.5 Sh) = 8/Sh
    EXPECT_NEAR(fdm::gravityOfShields(scales, 0.5), 16, 1e-12);
    EXPECT_NEAR(fdm::shieldsOfGravity(scales, 16), 0.5, 1e-14);
}


TEST(settlingGravity, settledBedHeight)
{
    // V per unit floor area (the 20 x 20 faces normal to y) over phi_m
    EXPECT_NEAR
    (
        fdm::settledBedHeight(scales, 1, 0.5), 4.0/3.0*pi/400/0.5, 1e-15
    );
    // along x the floor is 10 x 20
    EXPECT_NEAR
    (
        fdm::settledBedHeight(scales, 0, 0.5), 4.0/3.0*pi/200/0.5, 1e-15
    );
}


TEST(settlingGravity, theThreeFormsOfTheBlock)
{
    EXPECT_EQ
    (
        fdm::readSettlingGravity(parse("value (0 -9.81 0);"), scales),
        vector(0, -9.81, 0)
    );
    const vector gs = fdm::readSettlingGravity
    (
        parse("direction (0 -2 0); shieldsNumber 0.5;"), scales
    );
    EXPECT_NEAR(mag(gs - vector(0, -16, 0)), 0, 1e-12);

    // A = (9/2) a Sh/h_0
    const scalar h0 = 4.0/3.0*pi/400/0.5;
    const vector ga = fdm::readSettlingGravity
    (
        parse("direction (0 -1 0); acrivosNumber 0.9; packingFraction 0.5;"),
        scales
    );
    const scalar Sh = 0.9*h0/(4.5*1.5);
    EXPECT_NEAR(ga.y(), -fdm::gravityOfShields(scales, Sh), 1e-12);
}


TEST(settlingGravity, inputErrors)
{
    const auto error = [](const char* text, const fdm::settlingScales& s)
    {
        return errorOf([&]{ fdm::readSettlingGravity(parse(text), s); });
    };
    EXPECT_NE
    (
        error
        (
            "direction (0 -1 0); shieldsNumber 1; acrivosNumber 1;"
            " packingFraction 0.6;",
            scales
        ).find("not both"),
        std::string::npos
    );
    EXPECT_NE
    (
        error
        (
            "direction (0 -1 1); acrivosNumber 0.9; packingFraction 0.5;",
            scales
        ).find("must lie along"),
        std::string::npos
    );
    fdm::settlingScales still = scales;
    still.shearRate = 0;
    EXPECT_NE
    (
        error("direction (0 -1 0); shieldsNumber 1;", still)
            .find("shear rate 0"),
        std::string::npos
    );
    fdm::settlingScales light = scales;
    light.densityDifference = 0;
    EXPECT_NE
    (
        error("direction (0 -1 0); shieldsNumber 1;", light)
            .find("heavier than the fluid"),
        std::string::npos
    );
    EXPECT_NE
    (
        error("direction (0 -1 0); shieldNumber 1;", scales)
            .find("shieldsNumber"),
        std::string::npos
    );
    EXPECT_NE(error("shieldsNumber 1;", scales), "");
}
