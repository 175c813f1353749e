// Unit tests for the particle position update (adamsBashforth.H)

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
        point x = fdm::positionStep::of(false, dt).displacement
        (
            velocity(0), vector::zero
        );
        for (label k = 1; k < n; ++k)
        {
            x += fdm::positionStep::of(true, dt)
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
