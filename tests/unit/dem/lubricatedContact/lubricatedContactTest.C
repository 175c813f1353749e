// Unit tests for Foam::fdm::lubricatedContact (thesis 2, article 1)

#include "lubricatedContact.H"
#include "unitTestHelpers.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;
using Foam::constant::mathematical::pi;

namespace
{

// eta, g, k_n/g, k_t/g, eps, mu, cutoff
fdm::lubricatedContact model(const scalar eps, const scalar g = 1e4)
{
    return fdm::lubricatedContact(1, g, 1, 0.5, eps, 0.4, 2);
}

// The required keywords of the lubricatedContact dictionary
dictionary inputs(const scalar friction)
{
    dictionary d;
    d.add("viscosity", 1.0);
    d.add("stiffness", 1e4);
    d.add("roughness", 1e-3);
    d.add("friction", friction);
    return d;
}

fdm::lubricatedPairMotion normalMotion(const scalar un)
{
    return {vector(0, 1, 0), un, 1, Zero, Zero, Zero};
}

} // namespace


TEST(lubricatedContact, gapSolvesTheLogGapEquationForExtremeGaps)
{
    // Eq 22 in u = exp(delta): (1+alpha) u+ - B - u-/(dt* u+) = 0
    const fdm::lubricatedContact m = model(0);
    const scalar g = m.stiffness();
    for (const scalar u0 : {1e-1, 1e-4, 1e-9, 1e-30, 1e-200})
    for (const scalar un : {0.5, 1e-3, 0.0, -1e-3, -0.1})
    for (const scalar dt : {1e-6, 1e-3, 1.0})
    {
        fdm::lubricatedPairState s{std::log(u0), false, Zero};
        m.step(normalMotion(un), dt, s);
        const scalar u = std::exp(s.logGap);
        const scalar dtStar = dt*g/(1.5*pi);
        ASSERT_GT(u, 0) << "u0 " << u0 << " un " << un << " dt " << dt;
        const scalar B = un - 1/dtStar;
        const scalar scale = mag(B) + u0/(dtStar*u);
        EXPECT_NEAR((u - B - u0/(dtStar*u))/scale, 0, 1e-13)
            << "u0 " << u0 << " un " << un << " dt " << dt;
    }
}


TEST(lubricatedContact, rigidLimitGivesTheReynoldsLubricationForce)
{
    // g -> infinity: u -> u_n, F_n -> 3/2 pi eta a^2 du/dt / u (eq 3)
    const fdm::lubricatedContact m = model(0, 1e14);
    const scalar u0 = 1e-2;
    const scalar dt = 1e-6;
    const scalar udot = -0.3;
    fdm::lubricatedPairState s = m.start(u0, 1);
    const fdm::lubricatedPairLoads f =
        m.step(normalMotion(u0 + udot*dt), dt, s);
    const scalar u1 = std::exp(s.logGap);
    EXPECT_NEAR(u1, u0 + udot*dt, 1e-9);
    const scalar ref = 1.5*pi*udot/u1;
    EXPECT_NEAR(f.normalLubrication/ref, 1, 1e-4);
    EXPECT_EQ(f.normalContact, 0);
}


TEST(lubricatedContact, heldContactRelaxesToTheSpringEquilibrium)
{
    // Fixed u_n < eps: steady state of eq 14, (1 + alpha) u = u_n + alpha eps,
    // the whole force carried by the asperities
    const scalar eps = 1e-2;
    const fdm::lubricatedContact m = model(eps);
    const scalar un = 2e-3;
    fdm::lubricatedPairState s = m.start(0.02, 1);
    fdm::lubricatedPairLoads f{};
    for (label i = 0; i < 2000; ++i)
    {
        f = m.step(normalMotion(un), 1e-2, s);
    }
    const scalar u = std::exp(s.logGap);
    EXPECT_TRUE(s.contact);
    EXPECT_NEAR(u, 0.5*(un + eps), 1e-12);
    EXPECT_NEAR(f.normalContact, -m.stiffness()*(eps - u), 1e-9);
    EXPECT_NEAR(f.normalLubrication, 0, 1e-9);
}


TEST(lubricatedContact, contactStartsWhereTheGapReachesTheRoughness)
{
    // A step of exactly t_c (eq 20, corrected sign) lands on u = eps; a
    // longer step is split there and equals the two pieces done apart
    const scalar eps = 1e-2;
    const fdm::lubricatedContact m = model(eps);
    const scalar u0 = 0.05;
    const scalar un = -0.02;
    const scalar tau = 1.5*pi/m.stiffness();           // tau = nu_n a/g
    const scalar tc = tau*(u0 - eps)/(eps*(eps - un));

    fdm::lubricatedPairState s = m.start(u0, 1);
    m.step(normalMotion(un), tc, s);
    EXPECT_NEAR(std::exp(s.logGap), eps, 1e-12);

    const scalar dt = 3*tc;
    fdm::lubricatedPairState split = m.start(u0, 1);
    const fdm::lubricatedPairLoads f = m.step(normalMotion(un), dt, split);
    EXPECT_TRUE(split.contact);

    fdm::lubricatedPairState manual{std::log(eps), true, Zero};
    m.step(normalMotion(un), dt - tc, manual);
    EXPECT_NEAR(split.logGap, manual.logGap, 1e-10);
    const scalar u = std::exp(split.logGap);
    EXPECT_NEAR(f.normalContact, -m.stiffness()*(eps - u), 1e-9);
}


TEST(lubricatedContact, smoothSpheresNeverTouch)
{
    // eps = 0: a pair pressed hard for a long time closes exponentially but
    // keeps u > 0 (article 1: the spring g in series removes the 1/u
    // singularity)
    const fdm::lubricatedContact m = model(0);
    fdm::lubricatedPairState s = m.start(0.1, 1);
    scalar prev = s.logGap;
    for (label i = 0; i < 5000; ++i)
    {
        m.step(normalMotion(-0.5), 1e-2, s);
        ASSERT_TRUE(std::isfinite(s.logGap));
        EXPECT_LE(s.logGap, prev + 1e-12);
        EXPECT_FALSE(s.contact);
        prev = s.logGap;
    }
    EXPECT_LT(s.logGap, std::log(1e-300));

    // Loads stay finite there too (shear lubrication and torques in logs)
    const fdm::lubricatedPairLoads f = m.step
    (
        {vector(0, 1, 0), -0.5, 1, vector(1, 0, 0), vector(0, 0, 1), Zero},
        1e-2, s
    );
    EXPECT_TRUE(std::isfinite(mag(f.shearLubrication)));
    EXPECT_TRUE(std::isfinite(f.rollingDamping));
    EXPECT_TRUE(std::isfinite(f.normalLubrication));
}


TEST(lubricatedContact, separatedShearIsAMaxwellElement)
{
    // No contact, constant slip velocity: F_s -> nu_t(u) v (eq 27 steady)
    const fdm::lubricatedContact m = model(1e-3);
    const scalar u = 0.05;
    fdm::lubricatedPairState s = m.start(u, 1);
    const vector v(0.2, 0, -0.1);
    fdm::lubricatedPairLoads f{};
    for (label i = 0; i < 4000; ++i)
    {
        f = m.step({vector(0, 1, 0), u, 1, v, Zero, Zero}, 1e-3, s);
    }
    const scalar nut = m.shearLubricationCoefficient(std::log(u), 1);
    EXPECT_NEAR(mag(f.shearLubrication - nut*v)/(nut*mag(v)), 0, 1e-10);
    EXPECT_EQ(mag(f.shearContact), 0);
    // eq 4 directly
    EXPECT_NEAR(nut, 0.5*pi*(-2 + 2.05*std::log(2.05/0.05)), 1e-12);
}


TEST(lubricatedContact, contactSticksThenSlidesAtTheCoulombCap)
{
    const scalar eps = 1e-2;
    const fdm::lubricatedContact m = model(eps);
    const scalar un = -1e-2;                    // pressed: u = 0 at rest
    fdm::lubricatedPairState s{std::log(0.5*(un + eps) + 1e-6), true, Zero};
    const vector n(0, 1, 0);
    for (label i = 0; i < 200; ++i)
    {
        m.step({n, un, 1, Zero, Zero, Zero}, 1e-2, s);
    }
    ASSERT_TRUE(s.contact);

    // A small slip sticks: elastic force, no tangential lubrication
    const scalar dt = 1e-4;
    fdm::lubricatedPairLoads f =
        m.step({n, un, 1, vector(1e-3, 0, 0), Zero, Zero}, dt, s);
    const scalar cap = m.friction()*mag(f.normalContact);
    EXPECT_NEAR(f.shearContact.x(), m.tangentialStiffness()*1e-3*dt, 1e-15);
    EXPECT_EQ(mag(f.shearLubrication), 0);
    EXPECT_LT(mag(f.shearContact), cap);

    // Keep slipping: the contact part saturates at mu |F_n^c|, along the
    // slip, and the rest is lubrication (eq 33)
    for (label i = 0; i < 2000; ++i)
    {
        f = m.step({n, un, 1, vector(0, 0, 0.5), Zero, Zero}, dt, s);
    }
    const scalar capNow = m.friction()*mag(f.normalContact);
    EXPECT_NEAR(mag(f.shearContact), capNow, 1e-12*capNow);
    EXPECT_GT(f.shearContact.z(), 0);
    EXPECT_GT(f.shearLubrication.z(), 0);
}


TEST(lubricatedContact, torquesActOnlyWithinOneRadius)
{
    const fdm::lubricatedContact m = model(0);
    fdm::lubricatedPairState s = m.start(0.01, 1);
    fdm::lubricatedPairLoads f =
        m.step({vector(1, 0, 0), 0.01, 1, Zero, Zero, Zero}, 1e-9, s);
    const scalar u = std::exp(s.logGap);
    EXPECT_NEAR
    (
        f.rollingDamping, pi*(1.5 + 0.126*u)*std::log(1/u), 1e-9
    );
    EXPECT_NEAR(f.twistingDamping, pi*u*std::log(1/u), 1e-12);

    s = m.start(1.2, 1);
    f = m.step({vector(1, 0, 0), 1.2, 1, Zero, Zero, Zero}, 1e-9, s);
    EXPECT_EQ(f.rollingDamping, 0);
    EXPECT_EQ(f.twistingDamping, 0);
}


TEST(lubricatedContact, surfaceVelocityIsFrameInvariantWithEitherArms)
{
    // A pair of unequal spheres in rigid-body rotation: no slip (both arm
    // choices); a pure relative translation along the tangent: the
    // contact-point slip is that velocity, the radius slip is it scaled by
    // (a_1 + a_2)/(a_1 + a_2 + u_n) (YADE's avoidGranularRatcheting)
    const vector n(0.6, 0.64, 0.48);
    const scalar a1 = 1, a2 = 1.4, un = 0.3;
    const vector Omega(0.3, -0.7, 0.5);
    const vector dv = Omega ^ ((a1 + a2 + un)*n);
    const vector t = vector(0, 0.6, -0.8);   // t.n = 0
    for (const auto arms :
        {
            fdm::lubricatedContact::shearArms::contactPoint,
            fdm::lubricatedContact::shearArms::radius
        })
    {
        const fdm::lubricatedContact m(1, 1e4, 1, 0.5, 0, 0.4, 2, arms);
        EXPECT_LT
        (
            mag(m.surfaceVelocity(dv, n, un, a1, a2, Omega, Omega)), 1e-14
        );
        const scalar scale =
            arms == fdm::lubricatedContact::shearArms::radius
          ? (a1 + a2)/(a1 + a2 + un) : 1;
        EXPECT_LT
        (
            mag(m.surfaceVelocity(t, n, un, a1, a2, Zero, Zero) - scale*t),
            1e-14
        );
    }
}


TEST(lubricatedContact, shearArmsKeywordListsTheChoices)
{
    FatalIOError.throwExceptions();
    dictionary d(inputs(0.2));
    d.add("shearArms", "radius");
    EXPECT_EQ
    (
        fdm::lubricatedContact(d).arms(),
        fdm::lubricatedContact::shearArms::radius
    );
    d.set("shearArms", "centre");
    try
    {
        fdm::lubricatedContact m(d);
        FAIL() << "unknown shearArms accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("centre"), std::string::npos);
        EXPECT_NE(msg.find("contactPoint"), std::string::npos);
    }
}


TEST(lubricatedContact, badInputNamesTheKeyword)
{
    FatalIOError.throwExceptions();
    const dictionary d(inputs(-0.2));
    try
    {
        fdm::lubricatedContact m(d);
        FAIL() << "negative friction accepted";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE(std::string(e.message()).find("friction"), std::string::npos);
    }
}


TEST(lubricatedContact, twoSphereLubricationReplacesTheThesisForms)
{
    // lubrication twoSphere: the squeeze stays, the tangential dashpot and
    // the rolling and twisting torques go to the two-body hydrodynamics
    dictionary d(inputs(0.4));
    d.add("lubrication", "twoSphere");
    const fdm::lubricatedContact twoSphere(d);
    const fdm::lubricatedContact thesis(inputs(0.4));
    ASSERT_TRUE(twoSphere.twoSphereHydrodynamics());
    EXPECT_FALSE(thesis.twoSphereHydrodynamics());
    EXPECT_EQ(twoSphere.lubricationName(), "twoSphere");

    fdm::lubricatedPairMotion m = normalMotion(0.05);
    m.normal = vector(0, 1, 0);
    m.contactVelocity = vector(0.3, -0.2, 0);
    m.relativeSpin = vector(0.1, 0.2, 0.3);
    fdm::lubricatedPairState s1 = twoSphere.start(0.05, 1);
    fdm::lubricatedPairState s2 = thesis.start(0.05, 1);
    const fdm::lubricatedPairLoads l1 = twoSphere.step(m, 1e-3, s1);
    const fdm::lubricatedPairLoads l2 = thesis.step(m, 1e-3, s2);
    EXPECT_EQ(l1.normalLubrication, l2.normalLubrication);
    EXPECT_EQ(mag(l1.shearLubrication), 0);
    EXPECT_GT(mag(l2.shearLubrication), 0);
    EXPECT_EQ(l1.rollingDamping, 0);
    EXPECT_EQ(l1.twistingDamping, 0);
    EXPECT_GT(l2.rollingDamping, 0);
}


TEST(lubricatedContact, lubricationKeywordIsChecked)
{
    auto messageOf = [](const dictionary& d)
    {
        return unitTest::errorOf([&d]() { fdm::lubricatedContact m(d); });
    };
    dictionary misspelt(inputs(0.4));
    misspelt.add("lubrication", "twoSpheres");
    EXPECT_NE(messageOf(misspelt).find("twoSphere"), std::string::npos)
        << messageOf(misspelt);

    dictionary tableWithThesis(inputs(0.4));
    tableWithThesis.add("table", "somewhere");
    EXPECT_NE(messageOf(tableWithThesis).find("twoSphere only"),
        std::string::npos) << messageOf(tableWithThesis);

    dictionary farCutoff(inputs(0.4));
    farCutoff.add("lubrication", "twoSphere");
    farCutoff.add("cutoff", 12.0);
    EXPECT_NE(messageOf(farCutoff).find("allowed cutoff <= 10"),
        std::string::npos) << messageOf(farCutoff);
}
