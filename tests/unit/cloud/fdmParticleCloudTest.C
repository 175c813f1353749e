// Unit test of the FDM particle cloud on a periodic box of a/4 cells with
// one free, neutrally buoyant sphere: the particle sub-problem (eqs
// 2.43-2.53) gives any rigid-body motion of the fluid back exactly (and
// leaves lambda at zero), a
// linear shear its translation and half its vorticity; the first move is
// an Euler step wrapped through the periodic boundary; the restart state
// gives the cloud back to the last bit; bad particle input stops naming
// the keyword; a step that moves a particle by more than maxParticleCourant
// mesh spacings stops naming it.

#include "fdmParticleCloud.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const point centre(2, 2, 2);

//- A 4 a periodic cube of 16^3 cells, one sphere of radius 1 at x0
struct cloudCase
{
    unitTest::scratchCase sc;
    autoPtr<fvMesh> mesh;
    tmp<volVectorField> U, lambda;
    dictionary transport;

    cloudCase
    (
        const word& name,
        const std::string& particles = "((free (2 2 2) 1))",
        const std::string& controls = ""
    )
    :
        sc(name, controls),
        transport(unitTest::parse("nu 1; rho 1;"))
    {
        sc.writeFile
        (
            "constant/particleProperties",
            "coupling { lambdaTolerance 1e-8; particleSolveTolerance 1e-13; }"
            " groups { free { } } particles " + particles + ";"
        );
        mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(16, 16, 16), 0.25,
            wordList(6, "cyclic")
        );
        U = unitTest::zeroField<vector>(*mesh, "U", dimVelocity);
        lambda = unitTest::zeroField<vector>(*mesh, "lambda", dimAcceleration);
    }

    //- The fluid velocity set to u(x) in every cell
    template<class Field>
    void setU(const Field& u)
    {
        forAll(mesh->C(), c)
        {
            U.ref()[c] = u(mesh->C()[c]);
        }
    }
};

} // End anonymous namespace


TEST(fdmParticleCloud, rigidMotionOfTheFluidIsGivenBackExactly)
{
    cloudCase cc("fdmParticleCloudRigid");
    fdmParticleCloud cloud(*cc.mesh, cc.transport);
    ASSERT_EQ(cloud.size(), 1);
    cloud.prepare(cc.lambda.ref());

    const vector V(0.3, -0.2, 0.1), Omega(0.5, -1, 2);
    cc.setU([&](const point& x) { return V + (Omega ^ (x - centre)); });
    cloud.correct(cc.U.ref(), cc.lambda.ref());

    EXPECT_LT(mag(cloud.state().U[0] - V), 1e-10);
    EXPECT_LT(mag(cloud.state().Omega[0] - Omega), 1e-10);
    // Nothing to correct: lambda stays zero (its relative change, the
    // residual of eq 2.54, is then round-off over round-off)
    EXPECT_LT(gMax(mag(cc.lambda().primitiveField())), 1e-9);
}


TEST(fdmParticleCloud, linearShearGivesHalfTheVorticity)
{
    cloudCase cc("fdmParticleCloudShear");
    fdmParticleCloud cloud(*cc.mesh, cc.transport);
    cloud.prepare(cc.lambda.ref());
    cc.setU([](const point& x) { return vector(0.8*(x.y() - 2), 0, 0); });
    cloud.correct(cc.U.ref(), cc.lambda.ref());

    // u = gammaDot y e_x: Omega = curl(u)/2 = -gammaDot/2 e_z
    EXPECT_LT(mag(cloud.state().U[0]), 1e-10);
    EXPECT_LT(mag(cloud.state().Omega[0] - vector(0, 0, -0.4)), 1e-10);
}


TEST(fdmParticleCloud, firstMoveIsAnEulerStepWrappedThroughTheBoundary)
{
    cloudCase cc("fdmParticleCloudMove", "((free (3.9 2 2) 1))");
    fdmParticleCloud cloud(*cc.mesh, cc.transport);
    cloud.prepare(cc.lambda.ref());
    cc.setU([](const point&) { return vector(2, 0, 0); });
    cloud.correct(cc.U.ref(), cc.lambda.ref());
    cloud.move(0.1, cc.lambda.ref());
    // 3.9 + 2 * 0.1 = 4.1, wrapped into [0, 4)
    EXPECT_NEAR(cloud.state().position[0].x(), 0.1, 1e-10);
}


TEST(fdmParticleCloud, restartStateGivesTheCloudBackToTheLastBit)
{
    vector U, Omega;
    point x;
    {
        cloudCase first("fdmParticleCloudState");
        fdmParticleCloud cloud(*first.mesh, first.transport);
        cloud.prepare(first.lambda.ref());
        first.setU([](const point& p) { return vector(0.3, p.x()/7, 0); });
        cloud.correct(first.U.ref(), first.lambda.ref());
        cloud.move(0.05, first.lambda.ref());
        cloud.correct(first.U.ref(), first.lambda.ref());
        cloud.writeState();
        U = cloud.state().U[0];
        Omega = cloud.state().Omega[0];
        x = cloud.state().position[0];
        ASSERT_TRUE(isFile(first.sc.path()/"0/particleState"));

        // The same case started again at time 0 continues from the state
        fdmParticleCloud restarted(*first.mesh, first.transport);
        EXPECT_EQ(restarted.state().position[0], x);
        EXPECT_EQ(restarted.state().U[0], U);
        EXPECT_EQ(restarted.state().Omega[0], Omega);
    }
    EXPECT_GT(mag(U), 0.1);
}


TEST(fdmParticleCloud, badParticleInputStopsNamingIt)
{
    cloudCase cc("fdmParticleCloudBad", "((free (2 2 2) -1))");
    const std::string radius = unitTest::errorOf([&]
    {
        fdmParticleCloud cloud(*cc.mesh, cc.transport);
    });
    EXPECT_NE(radius.find("radius"), std::string::npos) << radius;

    cloudCase group("fdmParticleCloudGroup", "((fre (2 2 2) 1))");
    const std::string name = unitTest::errorOf([&]
    {
        fdmParticleCloud cloud(*group.mesh, group.transport);
    });
    EXPECT_NE(name.find("fre"), std::string::npos) << name;
    EXPECT_NE(name.find("free"), std::string::npos) << name;
}


TEST(fdmParticleCloud, stepThatOutrunsTheMeshStopsNamingTheParticle)
{
    // Velocity 2 on cells of 0.25: Courant number 8 deltaT
    cloudCase cc("fdmParticleCloudCourant");
    fdmParticleCloud cloud(*cc.mesh, cc.transport);
    cloud.prepare(cc.lambda.ref());
    cc.setU([](const point&) { return vector(0, 2, 0); });
    cloud.correct(cc.U.ref(), cc.lambda.ref());

    cloud.checkMotionResolved(0.12);      // Courant 0.96: allowed
    const std::string message = unitTest::errorOf([&]
    {
        cloud.checkMotionResolved(0.13);  // Courant 1.04
    });
    EXPECT_NE(message.find("Particle 0 would move"), std::string::npos)
        << message;
    EXPECT_NE(message.find("(1.04"), std::string::npos)
        << message;
    EXPECT_NE(message.find("maxParticleCourant"), std::string::npos)
        << message;
    EXPECT_NE(message.find("lower deltaT"), std::string::npos) << message;
}


TEST(fdmParticleCloud, courantLimitIsReadAndChecked)
{
    cloudCase cc("fdmParticleCloudCourantLimit");
    cc.sc.writeFile
    (
        "constant/particleProperties",
        "coupling { lambdaTolerance 1e-8; particleSolveTolerance 1e-13;"
        " maxParticleCourant 2; } groups { free { } }"
        " particles ((free (2 2 2) 1));"
    );
    fdmParticleCloud cloud(*cc.mesh, cc.transport);
    cloud.prepare(cc.lambda.ref());
    cc.setU([](const point&) { return vector(0, 2, 0); });
    cloud.correct(cc.U.ref(), cc.lambda.ref());
    cloud.checkMotionResolved(0.24);      // Courant 1.92: allowed now
    EXPECT_FALSE(unitTest::errorOf([&] { cloud.checkMotionResolved(0.26); })
        .empty());

    cc.sc.writeFile
    (
        "constant/particleProperties",
        "coupling { lambdaTolerance 1e-8; particleSolveTolerance 1e-13;"
        " maxParticleCourant 0; } groups { free { } }"
        " particles ((free (2 2 2) 1));"
    );
    const std::string zero = unitTest::errorOf([&]
    {
        fdmParticleCloud bad(*cc.mesh, cc.transport);
    });
    EXPECT_NE(zero.find("maxParticleCourant"), std::string::npos) << zero;
}
