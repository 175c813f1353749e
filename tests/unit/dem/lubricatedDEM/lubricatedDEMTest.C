// Unit tests for Foam::fdm::lubricatedDEM: the two-particle tests of
// thesis 2 (article 1, section 3), conservation, frame invariance,
// Lees-Edwards images, restart and stability

#include "lubricatedDEM.H"
#include "unitTestHelpers.H"
#include "mathematicalConstants.H"
#include "OStringStream.H"
#include "IStringStream.H"
#include "scalarList.H"

#include <gtest/gtest.h>
#include <cfenv>
#include <cmath>
#include <random>

using namespace Foam;
using Foam::constant::mathematical::pi;

namespace
{

fdm::periodicBox cube(const scalar L)
{
    return fdm::periodicBox(point::zero, point(L, L, L),
        FixedList<bool, 3>({true, true, true}));
}

// Sphere of radius a = 1, density rho, settling under its weight onto a
// fixed sphere from an initial gap u0 (article 1, section 3): returns the
// gap history
struct settling
{
    fdm::lubricatedDEM dem;
    scalar weight;

    settling(const scalar eps, const scalar g, const scalar rho,
        const scalar gravity, const scalar u0)
    :
        dem(cube(40), 0, fdm::lubricatedContact(1, g, 1, 0.5, eps, 0.4, 4))
    {
        dem.addParticle(point(20, 20, 20), 1, rho, false);
        dem.addParticle(point(20, 22 + u0, 20), 1, rho);
        weight = rho*4.0/3.0*pi*gravity;
        dem.bodyForce(1) = vector(0, -weight, 0);
    }

    //- Centre gap u_n
    scalar centreGap() const
    {
        return mag(dem.positions()[1] - dem.positions()[0]) - 2;
    }

    //- True gap u = u_n - u_e, u_e = F_n/g the deflection of the bulk
    //  spring under the normal force on the fixed sphere (traction > 0)
    scalar gap() const
    {
        const vector n = dem.positions()[1] - dem.positions()[0];
        const scalar Fn = dem.forces()[0] & (n/mag(n));
        return centreGap() - Fn/dem.model().stiffness();
    }
};

} // namespace


TEST(lubricatedDEM, settlingSphereGapDecaysAsTheViscousExponential)
{
    // Overdamped (inertial time m u/(3/2 pi eta a^2) <= 1e-3 tau_c below
    // u = 0.01), smooth: u = u0 exp(-(8/9) t/tau_c), tau_c = eta/(a rho g)
    // (eq 36), followed from u = 1e-2 a down to 1e-7 a without u <= 0
    const scalar rho = 0.01;
    const scalar grav = 1000;
    settling s(0, 1e4, rho, grav, 0.5);
    const scalar tauC = 1/(rho*grav);
    const scalar dt = 0.2*s.dem.criticalTimeStep();

    // The solvers trap floating-point exceptions: roughness 0 must raise
    // none (no log(0), no 0/0)
    std::feclearexcept(FE_DIVBYZERO | FE_INVALID);
    s.dem.step(dt);
    while (s.gap() > 1e-2)
    {
        s.dem.step(dt);
    }
    const scalar t0 = s.dem.time();
    const scalar u0 = s.gap();
    while (s.gap() > 1e-7)
    {
        s.dem.step(dt);
        ASSERT_GT(s.gap(), 0);
    }
    const scalar rate =
        -std::log(s.gap()/u0)/(s.dem.time() - t0)*tauC;
    EXPECT_NEAR(rate, 8.0/9.0, 0.01*8.0/9.0);
    EXPECT_FALSE(std::fetestexcept(FE_DIVBYZERO | FE_INVALID));
}


TEST(lubricatedDEM, roughSphereRestsAtTheAsperityEquilibrium)
{
    // Contact number K = k_n eps a/(m g) > 1: the gap settles at
    // u_eq = eps a - m g/k_n (eq 37)
    const scalar eps = 1e-2;
    const scalar g = 1e4;
    const scalar rho = 0.01;
    const scalar grav = 1000;
    settling s(eps, g, rho, grav, 0.05);
    const scalar dt = 0.2*s.dem.criticalTimeStep();
    while (s.dem.time() < 30/(rho*grav))
    {
        s.dem.step(dt);
    }
    const scalar ueq = eps - s.weight/g;
    ASSERT_GT(ueq, 0.3*eps);
    EXPECT_NEAR(s.gap(), ueq, 1e-6*eps);
    // The centre gap is u + u_e with u_e = -mg/g under the weight
    EXPECT_NEAR(s.centreGap(), ueq - s.weight/g, 1e-6*eps);
    EXPECT_EQ(s.dem.nContacts(), 1);
}


namespace
{

// A random dilute cloud with random velocities and spins
fdm::lubricatedDEM randomCloud(const scalar shearRate, const label n,
    const unsigned seed)
{
    fdm::lubricatedDEM dem(cube(14), shearRate,
        fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.4, 2));
    std::mt19937 gen(seed);
    std::uniform_real_distribution<scalar> u01(0, 1);
    DynamicList<point> placed;
    while (placed.size() < n)
    {
        const point x(14*u01(gen), 14*u01(gen), 14*u01(gen));
        bool free = true;
        for (const point& y : placed)
        {
            free = free && mag(dem.box().minimumImage(y - x)) > 2.9;
        }
        if (free)
        {
            placed.append(x);
            const label i =
                dem.addParticle(x, u01(gen) < 0.5 ? 1 : 1.4, 1e-2);
            dem.velocities()[i] = vector(u01(gen), u01(gen), u01(gen)) - 0.5*vector::one;
            dem.spins()[i] = vector(u01(gen), u01(gen), u01(gen)) - 0.5*vector::one;
        }
    }
    return dem;
}

} // namespace


TEST(lubricatedDEM, forcesAndMomentsBalance)
{
    // Pairwise loads: no net force, and no net moment about the origin
    // once the branch vectors are counted (sum T_i + l x F per pair)
    fdm::lubricatedDEM dem = randomCloud(0.7, 25, 2);
    for (label i = 0; i < 20; ++i)
    {
        dem.step(1e-3);
    }
    ASSERT_GT(dem.nInteractions(), 10);
    scalar scale = 0;
    vector total(Zero);
    for (const vector& f : dem.forces())
    {
        scale = max(scale, mag(f));
        total += f;
    }
    EXPECT_LT(mag(total)/scale, 1e-12);

    // One pair: the torques balance the moment of the pair forces,
    // T_1 + T_2 = l x F_1
    fdm::lubricatedDEM pair(cube(14), 0,
        fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.4, 2));
    pair.addParticle(point(5, 5, 5), 1, 1e-2);
    pair.addParticle(point(6.5, 6.2, 5.4), 1.4, 1e-2);
    pair.velocities()[0] = vector(0.3, -0.2, 0.1);
    pair.spins()[1] = vector(0.5, 0.1, -0.4);
    for (label i = 0; i < 4; ++i)
    {
        pair.step(1e-3);
    }
    // The loads of a step act at the positions it starts from
    const vector l =
        pair.box().minimumImage(pair.positions()[1] - pair.positions()[0]);
    pair.step(1e-3);
    const vector moment =
        pair.torques()[0] + pair.torques()[1] - (l ^ pair.forces()[0]);
    EXPECT_LT(mag(moment), 1e-12*mag(pair.forces()[0])*mag(l));
}


TEST(lubricatedDEM, rigidBodyMotionGivesNoShearForce)
{
    // Two spheres spinning and orbiting together (gammaDot = 0): the
    // contact-point velocity vanishes, so no tangential force and torque
    fdm::lubricatedDEM dem(cube(12), 0,
        fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.4, 2));
    const point c(6, 6, 6);
    const vector Omega(0.3, -0.7, 0.5);
    const point x0(5, 5.6, 6.3);
    const point x1 = x0 + 2.05*vector(0.6, 0.64, 0.48);
    dem.addParticle(x0, 1, 1e-2);
    dem.addParticle(x1, 1, 1e-2);
    dem.velocities()[0] = Omega ^ (x0 - c);
    dem.velocities()[1] = Omega ^ (x1 - c);
    dem.spins()[0] = Omega;
    dem.spins()[1] = Omega;
    dem.step(1e-6);
    ASSERT_EQ(dem.nInteractions(), 1);
    // normal force only: torques vanish, force along the branch vector
    EXPECT_LT(mag(dem.torques()[0]), 1e-12*mag(dem.forces()[0]) + 1e-15);
    const vector n = (x1 - x0)/mag(x1 - x0);
    const vector f = dem.forces()[0];
    EXPECT_LT(mag(f - (f & n)*n), 1e-9*mag(f) + 1e-15);
}


TEST(lubricatedDEM, leesEdwardsImagesGiveTheInteriorForce)
{
    // The same pair, once inside the cell and once straddling the sheared
    // y faces: identical loads (the cell is invariant under the shift)
    auto run = [](const scalar yShift)
    {
        fdm::lubricatedDEM dem(cube(12), 1.3,
            fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.4, 2));
        dem.setTime(0.77);
        const scalar offset = dem.box().shearOffset();
        point a(4, 5 + yShift, 3);
        point b(5.2, 6.6 + yShift, 3.5);
        // Moving b up by yShift inside a sheared cell moves its image by
        // the affine shift; place it where the sheared copy lies
        if (b.y() >= 12)
        {
            b = point(b.x() - offset, b.y() - 12, b.z());
        }
        dem.addParticle(a, 1, 1e-2);
        dem.addParticle(b, 1.1, 1e-2);
        dem.velocities()[0] = vector(0.1, 0.2, -0.3);
        dem.velocities()[1] = vector(-0.2, 0.05, 0.1);
        dem.spins()[1] = vector(0, 0, 0.4);
        dem.step(1e-4);
        return dem.forces()[0];
    };
    const vector inside = run(0);
    const vector across = run(6);
    ASSERT_GT(mag(inside), 0);
    EXPECT_LT(mag(inside - across), 1e-9*mag(inside));
}


TEST(lubricatedDEM, spheresAddedTogetherRunAsSpheresAddedOneByOne)
{
    // addParticles (setup's bulk addition) gives the spheres of as many
    // addParticle calls: masses, the fixed flag, zero loads before the
    // first step, and the same trajectories bitwise
    fdm::lubricatedDEM oneByOne = randomCloud(1, 40, 5);
    oneByOne.addParticle(point(7, 7, 7.5), 1, 1e-2, false);
    boolList mobile(oneByOne.size(), true);
    mobile.last() = false;
    fdm::lubricatedDEM together
    (
        cube(14), 1, fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.4, 2)
    );
    together.addParticles
    (
        oneByOne.positions(), oneByOne.radii(), 1e-2, mobile
    );
    together.velocities() = oneByOne.velocities();
    together.spins() = oneByOne.spins();
    ASSERT_EQ(together.size(), 41);
    EXPECT_EQ(together.masses(), oneByOne.masses());
    EXPECT_EQ(together.forces(), List<vector>(41, Zero));
    EXPECT_EQ(together.stresslets(0), List<symmTensor>(41, Zero));

    for (label i = 0; i < 200; ++i)
    {
        oneByOne.step(5e-4);
        together.step(5e-4);
    }
    ASSERT_GT(together.nInteractions(), 0);
    EXPECT_EQ(together.positions(), oneByOne.positions());
    EXPECT_EQ(together.spins(), oneByOne.spins());
    // The fixed sphere moves with the affine flow only
    EXPECT_EQ(together.velocities().last(), vector::zero);
    EXPECT_EQ(together.spins().last(), vector::zero);
}


TEST(lubricatedDEM, restartFromTheWrittenStateIsBitwise)
{
    // Steps of 5e-4, a quarter of the critical step sqrt(m/g)
    fdm::lubricatedDEM straight = randomCloud(1, 40, 5);
    fdm::lubricatedDEM first = randomCloud(1, 40, 5);
    for (label i = 0; i < 1200; ++i)
    {
        straight.step(5e-4);
    }
    for (label i = 0; i < 600; ++i)
    {
        first.step(5e-4);
    }
    OStringStream os;
    os.precision(17);
    first.writeState(os);
    IStringStream is(os.str());
    const dictionary state(is);

    fdm::lubricatedDEM restarted = randomCloud(1, 40, 5);
    restarted.readState(state);
    for (label i = 0; i < 600; ++i)
    {
        restarted.step(5e-4);
    }
    ASSERT_GT(straight.nInteractions(), 0);
    forAll(straight.positions(), i)
    {
        EXPECT_EQ(straight.positions()[i], restarted.positions()[i]) << i;
        EXPECT_EQ(straight.spins()[i], restarted.spins()[i]) << i;
    }
}


TEST(lubricatedDEM, writtenStateOfPairsThatNeverInteractedIsDefined)
{
    // A pair beyond the cut-off (gap 4.1 a) but within its skin (0.3 a):
    // listed, never stepped, so only the pair search defines its state;
    // two fixed spheres nearly touching are not listed (their loads move
    // nothing)
    fdm::lubricatedDEM dem
    (
        cube(40), 1, fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-3, 0.4, 4)
    );
    dem.addParticle(point(20, 20, 20), 1, 1, false);
    dem.addParticle(point(20, 26.1, 20), 1, 1);
    dem.addParticle(point(20, 17.99, 20), 1, 1, false);
    dem.step(1e-3);
    ASSERT_EQ(dem.nInteractions(), 0);

    OStringStream os;
    dem.writeState(os);
    IStringStream is(os.str());
    const dictionary state(is);
    ASSERT_EQ(state.get<List<labelPair>>("pairs").size(), 1);
    EXPECT_EQ(state.get<List<labelPair>>("pairs")[0], labelPair(0, 1));
    EXPECT_EQ(state.get<scalarList>("pairLogGap")[0], 0);
    EXPECT_FALSE(state.get<boolList>("pairContact")[0]);
    EXPECT_EQ(state.get<List<vector>>("pairShearForce")[0], vector::zero);
}


TEST(lubricatedDEM, stabilityNumberFlagsTooLargeSteps)
{
    // A pressed pair: s < 1 at a tenth of the critical step, and the
    // thesis rule dt_cr = sqrt(m/g) is the scale where s reaches order 1
    for (const scalar factor : {0.1, 3.0})
    {
        settling s(1e-2, 1e4, 0.01, 1000, 0.005);
        const scalar dt = factor*s.dem.criticalTimeStep();
        scalar sMax = 0;
        for (label i = 0; i < 200; ++i)
        {
            s.dem.step(dt);
            sMax = max(sMax, s.dem.stabilityNumber());
        }
        if (factor < 1)
        {
            EXPECT_LT(sMax, 1);
        }
        else
        {
            EXPECT_GT(sMax, 1);
        }
    }
}


namespace
{

// Cell periodic in x and z, open along y (gravity along the gradient)
fdm::periodicBox openY(const scalar L, const scalar H)
{
    return fdm::periodicBox(point::zero, point(L, H, L),
        FixedList<bool, 3>({true, false, true}));
}

} // namespace


TEST(lubricatedDEM, isolatedSphereFallsAtTheStokesVelocity)
{
    // A lone heavy sphere with drag eta_d against the affine flow
    // gammaDot y e_x (article 3): terminal fluctuation velocity
    // W/(6 pi (eta_d + eta_iso) a) downwards and no slip along x; the extra
    // drag of isolated particles (below 3 interactions) adds eta_iso.
    // Falling across the shear, the sphere lags the affine flow by
    // v'_x = -m gammaDot v'_y/(6 pi eta a), its inertia
    const scalar W = 2.0, etaD = 1.0/30, etaIso = 1.0, gammaDot = 0.5;
    for (const scalar iso : {0.0, etaIso})
    {
        fdm::lubricatedDEM dem(openY(12, 200), gammaDot,
            fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.5, 2));
        dem.setDrag(etaD);
        dem.setIsolatedDrag(iso, 3);
        dem.addParticle(point(6, 150, 6), 1, 1e-3);
        dem.bodyForce(0) = vector(0, -W, 0);
        for (label i = 0; i < 4000; ++i)
        {
            dem.step(1e-3);
        }
        const scalar c = 6*pi*(etaD + iso);
        const scalar vExact = W/c;
        const scalar lag = dem.masses()[0]*gammaDot*vExact/c;
        EXPECT_NEAR(dem.velocities()[0].y()/vExact, -1, 1e-9);
        EXPECT_NEAR(dem.velocities()[0].x()/lag, 1, 1e-6);
    }
}


TEST(lubricatedDEM, fixedSpheresFollowTheAffineFlow)
{
    // A floor sphere at height y moves at gammaDot y e_x; it neither
    // falls under load nor spins, and floor spheres do not interact
    const scalar gammaDot = 0.8, y = 3.0, t = 1.5;
    fdm::lubricatedDEM dem(openY(12, 40), gammaDot,
        fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.5, 2));
    dem.addParticle(point(2, y, 6), 1, 1e-3, false);
    dem.addParticle(point(2, y + 2.1, 6), 1, 1e-3);
    dem.addParticle(point(4.005, y, 6), 1, 1e-3, false);
    dem.bodyForce(1) = vector(0, -1, 0);
    const label n = 1500;
    for (label i = 0; i < n; ++i)
    {
        dem.step(t/n);
    }
    const scalar x = std::fmod(2 + gammaDot*y*t, 12.0);
    EXPECT_NEAR(dem.positions()[0].x(), x, 1e-10);
    EXPECT_EQ(dem.positions()[0].y(), y);
    EXPECT_EQ(mag(dem.spins()[0]), 0);
    // The mobile sphere with each floor sphere; the two floor spheres,
    // 0.005 a apart, do not interact
    EXPECT_EQ(dem.nInteractions(), 2);
}


TEST(lubricatedDEM, floorCarriesTheWeightOfAPile)
{
    // Mobile spheres resting on a floor of fixed spheres at zero shear:
    // at rest, the forces on the floor add up to the total weight
    // (Newton's third law across the pair loads; the floor spheres are
    // the only support)
    fdm::lubricatedDEM dem(openY(8, 40), 0,
        fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.5, 1));
    dem.setDrag(1);
    label nFixed = 0;
    for (const scalar x : {1.0, 3.0, 5.0, 7.0})
    {
        for (const scalar z : {1.0, 3.0, 5.0, 7.0})
        {
            dem.addParticle(point(x, 1, z), 1, 1e-2, false);
            ++nFixed;
        }
    }
    const scalar W = 5;
    vector weight(Zero);
    for (const point& x : {point(2, 2.6, 2), point(6, 2.6, 2),
        point(2, 2.6, 6), point(6, 2.6, 6), point(4, 2.5, 4)})
    {
        const label i = dem.addParticle(x, 1, 1e-2);
        dem.bodyForce(i) = vector(0, -W, 0);
        weight += dem.bodyForce(i);
    }
    for (label i = 0; i < 60000; ++i)
    {
        dem.step(2e-4);
    }
    vector floorForce(Zero);
    scalar vMax = 0;
    for (label i = 0; i < dem.size(); ++i)
    {
        if (i < nFixed)
        {
            floorForce += dem.forces()[i];
        }
        else
        {
            vMax = max(vMax, mag(dem.velocities()[i]));
        }
    }
    EXPECT_LT(vMax, 1e-6);
    EXPECT_LT(mag(floorForce - weight)/mag(weight), 1e-4);

}


TEST(lubricatedDEM, pressureWallCarriesTheImposedPressure)
{
    // Spheres on a floor under a wall of fixed spheres free to move along
    // y at zero shear and no gravity: at rest the wall carries P A and the
    // floor the same load, opposite (the spheres transmit it)
    const scalar L = 8, P = 2;
    fdm::lubricatedDEM dem(openY(L, 40), 0,
        fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.5, 1));
    dem.setDrag(1);
    labelList floor, wall;
    for (const scalar x : {1.0, 3.0, 5.0, 7.0})
    {
        for (const scalar z : {1.0, 3.0, 5.0, 7.0})
        {
            floor.append(dem.addParticle(point(x, 1, z), 1, 1e-2, false));
            wall.append(dem.addParticle(point(x, 6.6, z), 1, 1e-2, false));
        }
    }
    for (const scalar x : {2.0, 6.0})
    {
        for (const scalar z : {2.0, 6.0})
        {
            dem.addParticle(point(x, 3.8, z), 1.2, 1e-2);
        }
    }
    dem.setPressureWall(wall, vector::Y, P, 50);
    for (label i = 0; i < 60000; ++i)
    {
        dem.step(2e-4);
    }
    const scalar PA = P*L*L;
    scalar floorLoad = 0, wallLoad = 0;
    for (const label i : floor)
    {
        floorLoad += dem.forces()[i].y();
    }
    for (const label i : wall)
    {
        wallLoad += dem.forces()[i].y();
    }
    EXPECT_LT(mag(dem.wallVelocity()), 1e-8);
    EXPECT_NEAR(wallLoad/PA, 1, 1e-5);
    EXPECT_NEAR(dem.wallLoad()/PA, 1, 1e-5);
    EXPECT_NEAR(-floorLoad/PA, 1, 1e-5);
    // The wall came down onto the spheres
    EXPECT_LT(dem.positions()[wall[0]].y(), 6.6 - 0.3);
}


TEST(lubricatedDEM, corruptPairHistoryIsAnError)
{
    fdm::lubricatedDEM dem = randomCloud(1, 40, 5);
    for (label i = 0; i < 50; ++i)
    {
        dem.step(5e-4);
    }
    OStringStream os;
    os.precision(17);
    dem.writeState(os);
    const string text(os.str());

    // A pair list longer than its states
    {
        IStringStream is(text);
        dictionary state(is);
        state.name() = "0.1/particleState";
        List<labelPair> pairs(state.get<List<labelPair>>("pairs"));
        ASSERT_GT(pairs.size(), 1);
        pairs.append(labelPair(0, 1));
        state.set("pairs", pairs);
        const std::string message =
            unitTest::errorOf([&]() { dem.readState(state); });
        EXPECT_NE(message.find("one entry per pair"), std::string::npos)
            << message;
        EXPECT_NE(message.find("0.1/particleState"), std::string::npos)
            << message;
    }
    // A pair listed twice
    {
        IStringStream is(text);
        dictionary state(is);
        List<labelPair> pairs(state.get<List<labelPair>>("pairs"));
        pairs[1] = pairs[0];
        state.set("pairs", pairs);
        const std::string message =
            unitTest::errorOf([&]() { dem.readState(state); });
        EXPECT_NE(message.find("twice"), std::string::npos) << message;
    }
    // A particle that is not in the case
    {
        IStringStream is(text);
        dictionary state(is);
        List<labelPair> pairs(state.get<List<labelPair>>("pairs"));
        pairs[0] = labelPair(0, dem.size());
        state.set("pairs", pairs);
        const std::string message =
            unitTest::errorOf([&]() { dem.readState(state); });
        EXPECT_NE(message.find("is not two particles"), std::string::npos)
            << message;
    }
}


TEST(lubricatedDEM, twoSphereLubricationMovesAPairAsStokesFlow)
{
    // Two free spheres (a = 1, St = 1e-3) at gap 1 in shear with the
    // isolated drag and lubrication twoSphere: after 10 relaxation times
    // m/(6 pi eta a) their relative velocity is Batchelor & Green's
    //     V = W x r + E.r - [A dd + B (I - dd)].E.r
    // (golden A(1) = 0.1866626359, B(1) = 0.0222799832, from
    // fdmResistance.pairShear).  Along x (E.r normal to r) B alone; along
    // (1, 1, 0) (E.r along r) A alone, the gap closing by 2e-3 meanwhile
    const scalar golden[2] = {0.0222799832, 0.1866626359};
    const vector dirs[2] = {vector(1, 0, 0), vector(1, 1, 0)/std::sqrt(2.0)};
    for (label k = 0; k < 2; ++k)
    {
        fdm::lubricatedContact law(1, 1e5, 1, 0.5, 0, 0, 4);
        law.useTwoSphereHydrodynamics();
        fdm::lubricatedDEM dem(cube(30), 1, law);
        dem.setDrag(1);
        const vector r = 3*dirs[k];
        dem.addParticle(point(15, 15, 15) - 0.5*r, 1, 1e-3);
        dem.addParticle(point(15, 15, 15) + 0.5*r, 1, 1e-3);
        for (label n = 0; n < 40; ++n)
        {
            dem.step(5e-5);
        }
        const vector rNow = dem.positions()[1] - dem.positions()[0];
        const vector d = rNow/mag(rNow);
        const symmTensor E(0, 0.5, 0, 0, 0, 0);
        const vector Er = E & rNow;
        // Stored velocities are relative to the affine flow, so their
        // difference is the disturbance V - (W x r + E.r)
        const vector dV = dem.velocities()[1] - dem.velocities()[0];
        const scalar measured =
            k == 0
          ? -(dV & Er)/(Er & Er)
          : -(dV & d)/(Er & d);
        EXPECT_NEAR(measured, golden[k], (k == 0 ? 1e-3 : 1e-2)*golden[k])
            << (k == 0 ? "B" : "A");
    }
}
