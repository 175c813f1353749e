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
