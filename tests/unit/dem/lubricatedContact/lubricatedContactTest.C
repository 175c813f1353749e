// Unit tests for Foam::fdm::lubricatedContact (thesis 2, article 1)

#include "lubricatedContact.H"
#include "unitTestHelpers.H"
#include "lubricatedContactInputs.H"
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


TEST(lubricatedContact, asperitiesInsideTouchOnTheOverlap)
{
    // Article 2 (eqs 2-9): contact on the overlap u_n < 0, lubrication on
    // h = u_n + eps a.  Held at an overlap delta the asperity spring k_n in
    // series with the bulk g (k_n = g here) carries -g delta/2; held at a
    // gap delta < eps a the spheres do not touch (they do with the
    // asperities outside)
    const scalar eps = 1e-2, delta = 2e-3, g = 1e4;
    const fdm::lubricatedContact inside
    (
        1, g, 1, 0.5, eps, 0.4, 2,
        fdm::lubricatedContact::shearArms::contactPoint,
        fdm::lubricatedContact::asperities::inside
    );
    const fdm::lubricatedContact outside = model(eps, g);
    EXPECT_EQ(inside.gapShift(), eps);
    EXPECT_EQ(outside.gapShift(), 0);

    fdm::lubricatedPairState pressed = inside.start(0.02, 1);
    fdm::lubricatedPairLoads f{};
    for (label i = 0; i < 2000; ++i)
    {
        f = inside.step(normalMotion(-delta), 1e-2, pressed);
    }
    EXPECT_TRUE(pressed.contact);
    EXPECT_NEAR(std::exp(pressed.logGap), eps - 0.5*delta, 1e-12);
    EXPECT_NEAR(f.normalContact, -0.5*g*delta, 1e-8);

    fdm::lubricatedPairState apart = inside.start(0.02, 1);
    fdm::lubricatedPairState touching = outside.start(0.02, 1);
    for (label i = 0; i < 2000; ++i)
    {
        f = inside.step(normalMotion(delta), 1e-2, apart);
        outside.step(normalMotion(delta), 1e-2, touching);
    }
    EXPECT_FALSE(apart.contact);
    EXPECT_NEAR(std::exp(apart.logGap), delta + eps, 1e-12);
    EXPECT_EQ(f.normalContact, 0);
    EXPECT_TRUE(touching.contact);
}


TEST(lubricatedContact, asperitiesInsideRunTheLawOnTheShiftedGap)
{
    // The same law at the centre gap u_n + eps a, prefactors on a: an
    // approaching pair's loads equal the outside law's at the shifted gap
    const scalar eps = 2e-2;
    const fdm::lubricatedContact inside
    (
        1, 1e4, 1, 0.5, eps, 0.4, 2,
        fdm::lubricatedContact::shearArms::radius,
        fdm::lubricatedContact::asperities::inside
    );
    const fdm::lubricatedContact outside
    (
        1, 1e4, 1, 0.5, eps, 0.4, 2, fdm::lubricatedContact::shearArms::radius
    );
    fdm::lubricatedPairState a = inside.start(0.1, 1);
    fdm::lubricatedPairState b = outside.start(0.1 + eps, 1);
    for (label i = 0; i < 300; ++i)
    {
        // to an overlap of 0.018 a, then held: contact for article 2 once
        // h < eps a
        const scalar un = max(0.1 - 2e-3*i, -0.018);
        fdm::lubricatedPairMotion m{vector(0, 1, 0), un, 1,
            vector(0.3, -0.1, 0), vector(0, 0, 0.2), vector(0, 0, 0.1)};
        const fdm::lubricatedPairLoads fa = inside.step(m, 1e-3, a);
        m.centreGap += eps;
        const fdm::lubricatedPairLoads fb = outside.step(m, 1e-3, b);
        EXPECT_NEAR(a.logGap, b.logGap, 1e-12);
        EXPECT_EQ(a.contact, b.contact);
        EXPECT_NEAR(fa.normalContact, fb.normalContact, 1e-9);
        EXPECT_NEAR(fa.normalLubrication, fb.normalLubrication, 1e-9);
        EXPECT_LT(mag(fa.shearContact - fb.shearContact), 1e-9);
        EXPECT_LT(mag(fa.shearLubrication - fb.shearLubrication), 1e-9);
        EXPECT_NEAR(fa.rollingDamping, fb.rollingDamping, 1e-9);
    }
    EXPECT_TRUE(a.contact);
}


TEST(lubricatedContact, twoSphereLubricationReplacesTheThesisForms)
{
    // lubrication twoSphere: the squeeze stays, the tangential dashpot and
    // the rolling and twisting torques go to the two-body hydrodynamics
    dictionary d(unitTest::lubricatedContactInputs(0.4));
    d.add("lubrication", "twoSphere");
    const fdm::lubricatedContact twoSphere(d);
    const fdm::lubricatedContact thesis(unitTest::lubricatedContactInputs(0.4));
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


// ************************************************************************* //
