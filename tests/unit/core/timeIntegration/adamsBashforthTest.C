// Unit tests for the particle position update (adamsBashforth.H): exact
// for velocities linear in time at a constant and at a changing step,
// second order

#include "adamsBashforth.H"
#include "point.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace Foam;


TEST(adamsBashforth, exactForVelocityLinearInTime)
{
    // U(t) = a + b t: AB2 integrates it exactly, x(t) = a t + b t^2/2
    const vector a(0.3, -1.0, 2.0);
    const vector b(1.5, 0.25, -0.75);
    const scalar dt = 0.1;

    // Start from the exact state at t = dt (history U(0) available)
    point x = a*dt + 0.5*b*dt*dt;
    for (label k = 1; k < 50; ++k)
    {
        const scalar t = k*dt;
        x += fdm::positionStep::adamsBashforth2(dt)
            .displacement(a + b*t, a + b*(t - dt));
    }
    const scalar T = 50*dt;
    const point exact = a*T + 0.5*b*T*T;
    EXPECT_LT(mag(x - exact), 1e-12*mag(exact));
}


TEST(adamsBashforth, secondOrderConvergence)
{
    // dx/dt = (cos t, -sin t, 1), x(0) = 0, integrated to T = 2;
    // Euler first step, then AB2: global error O(dt^2)
    auto velocity = [](const scalar t)
    {
        return vector(std::cos(t), -std::sin(t), 1.0);
    };
    auto integrate = [&](const label n)
    {
        const scalar dt = 2.0/n;
        point x = fdm::positionStep::after(0, dt).displacement
        (
            velocity(0), vector::zero
        );
        for (label k = 1; k < n; ++k)
        {
            x += fdm::positionStep::after(dt, dt)
                .displacement(velocity(k*dt), velocity((k - 1)*dt));
        }
        const point exact(std::sin(2.0), std::cos(2.0) - 1.0, 2.0);
        return mag(x - exact);
    };

    const scalar e1 = integrate(100);
    const scalar e2 = integrate(200);
    const scalar order = std::log2(e1/e2);
    EXPECT_NEAR(order, 2.0, 0.1);
}


TEST(adamsBashforth, variableStepExactForVelocityLinearInTime)
{
    // Steps of 0.1, then 0.05 (a run continued at half its deltaT), then
    // 0.2: each step after one of dt0 is exact for U = a + b t, and the
    // constant-step weights are not once the step changes
    const vector a(0.3, -1.0, 2.0);
    const vector b(1.5, 0.25, -0.75);
    auto exact = [&](const scalar t) { return point(a*t + 0.5*b*t*t); };
    scalar t = 0.1, dt0 = 0.1;
    point x = exact(t);
    for (const scalar dt : {0.1, 0.05, 0.05, 0.2, 0.2})
    {
        const vector U = a + b*t, U0 = a + b*(t - dt0);
        x += fdm::positionStep::after(dt0, dt).displacement(U, U0);
        if (dt != dt0)
        {
            const point constant = exact(t)
              + fdm::positionStep::adamsBashforth2(dt).displacement(U, U0);
            EXPECT_GT(mag(constant - exact(t + dt)), 1e-4);
        }
        t += dt;
        dt0 = dt;
        EXPECT_LT(mag(x - exact(t)), 1e-12*mag(exact(t))) << "t " << t;
    }
    // No history: forward Euler
    EXPECT_EQ(fdm::positionStep::after(0, 0.1).previous, 0);
}


TEST(adamsBashforth, schemeSelection)
{
    // Euler ignores the history; Adams-Bashforth takes it when there is one
    using fdm::positionScheme;
    const fdm::positionStep e =
        fdm::positionStep::after(positionScheme::euler, 0.1, 0.1);
    EXPECT_EQ(e.current, 1);
    EXPECT_EQ(e.previous, 0);
    const fdm::positionStep ab =
        fdm::positionStep::after(positionScheme::adamsBashforth2, 0.1, 0.1);
    EXPECT_DOUBLE_EQ(ab.current, 1.5);
    EXPECT_DOUBLE_EQ(ab.previous, -0.5);
    EXPECT_EQ
    (
        fdm::positionStep::after(positionScheme::adamsBashforth2, 0, 0.1)
       .previous,
        0
    );
}


TEST(adamsBashforth, stiffRelaxationStableWithEulerOnly)
{
    // dx/dt = -k x at k dt = 1.5: Euler's factor 1 - k dt = -0.5 decays;
    // the two-step form's roots of z^2 - (1 - 1.5 k dt) z - 0.5 k dt = 0
    // are 0.44 and -1.69 (the header's stability ranges k dt < 2 and < 1),
    // so its x alternates in sign and grows
    const scalar k = 15, dt = 0.1;
    scalar xEuler = 1, xAB = 1, UOld = 0, historyDt = 0;
    scalar previousAB = xAB;
    for (label n = 0; n < 20; ++n)
    {
        const fdm::positionStep e =
            fdm::positionStep::after(fdm::positionScheme::euler, 0, dt);
        xEuler += e.dt*(e.current*(-k*xEuler));

        const fdm::positionStep ab = fdm::positionStep::after
        (
            fdm::positionScheme::adamsBashforth2, historyDt, dt
        );
        const scalar U = -k*xAB;
        previousAB = xAB;
        xAB += ab.dt*(ab.current*U + ab.previous*UOld);
        UOld = U;
        historyDt = dt;
    }
    EXPECT_LT(std::abs(xEuler), 1e-5);
    EXPECT_GT(std::abs(xAB), 1e3);
    EXPECT_LT(xAB*previousAB, 0);
}
