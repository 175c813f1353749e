// Unit test of the outer-iteration control: a step stops at the first
// iteration below the lambda tolerance, after nOuterCorrectors otherwise
// (exactly that many with tolerance 0), and a diverging or non-finite
// residual or a runaway velocity stops the run naming what to change; the
// SIMPLEC block is read with its defaults and refused when wrong.

#include "fdmOuterLoopControl.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "fpTrapsOff.H"
#include <gtest/gtest.h>
#include <limits>

using namespace Foam;

namespace
{

//- A scratch case whose fvSolution holds the given SIMPLEC block and
//  relaxation text
struct controlCase
{
    unitTest::scratchCase sc;
    autoPtr<fvMesh> mesh;

    controlCase
    (
        const word& name,
        const std::string& simplec,
        const std::string& relax = "relaxationFactors { equations { U 0.9; } }"
    )
    :
        sc(name)
    {
        sc.writeFile
        (
            "system/fvSolution",
            "solvers { U { solver PBiCGStab; } UBetweenRecords"
            " { solver smoothSolver; } p { solver GAMG; } }"
            " SIMPLEC { pRefCell 0; pRefValue 0; outerTolerance 1e-10; "
          + simplec + " } " + relax
        );
        mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(2, 2, 2), 0.5, unitTest::channelSides()
        );
    }
};

//- Outer iterations a step takes with these lambda residuals (the last
//  repeated) at tolerance tol
label iterationsFor(fdmOuterLoopControl& c, scalarList r, const scalar tol)
{
    c.setVerbose(false);
    c.start();
    label n = 0;
    while (c.loop())
    {
        c.setResiduals(1e-3, 1e-3, 1e-3, 1.0);
        c.setLambdaResidual(r[min(n, r.size() - 1)], tol, 1);
        ++n;
    }
    return n;
}

} // End anonymous namespace


TEST(fdmOuterLoopControl, stopsAtToleranceOrAfterTheMaximum)
{
    controlCase cc("outerLoop", "nCorrectors 2; nOuterCorrectors 5;");
    fdmOuterLoopControl c(*cc.mesh);
    EXPECT_EQ(iterationsFor(c, {1e-1, 1e-2, 5e-4}, 1e-3), 3);
    EXPECT_TRUE(c.converged());
    // Never below: the maximum, with a warning
    EXPECT_EQ(iterationsFor(c, {1e-2}, 1e-3), 5);
    EXPECT_FALSE(c.converged());
    // Tolerance 0: exactly nOuterCorrectors
    EXPECT_EQ(iterationsFor(c, {1e-12}, 0), 5);
}


TEST(fdmOuterLoopControl, divergenceStopsNamingWhatToChange)
{
    controlCase cc("outerLoopDiverge", "nCorrectors 2; nOuterCorrectors 50;");
    fdmOuterLoopControl c(*cc.mesh);
    // With floating-point traps on, the arithmetic that makes a NaN traps
    // before the control sees it: the NaN case runs with them off
    fdm::fpTrapsOff trapsOff;
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    for (const scalarList& r :
        {scalarList({1e-2, nan}), scalarList({1e-4, 1e-2, 2.0})})
    {
        const std::string msg =
            unitTest::errorOf([&]{ iterationsFor(c, r, 1e-6); });
        EXPECT_NE(msg.find("force-density residual"), std::string::npos)
            << msg;
        EXPECT_NE(msg.find("Lower the U relaxation factor"), std::string::npos)
            << msg;
        EXPECT_NE(msg.find("lower deltaT"), std::string::npos) << msg;
    }
    // A velocity 1e6 times that of the first outer iteration
    const std::string runaway = unitTest::errorOf([&]
    {
        c.start();
        c.loop();
        c.setResiduals(1e-2, 1, 1, 1.0);
        c.loop();
        c.setResiduals(1e-2, 1, 1, 2e6);
    });
    EXPECT_NE(runaway.find("largest cell velocity"), std::string::npos)
        << runaway;
}


TEST(fdmOuterLoopControl, blockDefaultsAndSolversBetweenRecords)
{
    controlCase cc("outerLoopRead", "nCorrectors 2; nOuterCorrectors 5;");
    const fdmOuterLoopControl c(*cc.mesh);
    EXPECT_EQ(c.nCorrectors(false), 2);
    EXPECT_EQ(c.nCorrectors(true), 2);
    EXPECT_TRUE(c.momentumPredictor(false));
    EXPECT_TRUE(c.momentumPredictor(true));
    EXPECT_EQ(c.accelerationDepth(), 0);
    EXPECT_FALSE(c.layerMeanCorrection());
    EXPECT_EQ(c.solverDict("U", true).get<word>("solver"), "smoothSolver");
    EXPECT_EQ(c.solverDict("U", false).get<word>("solver"), "PBiCGStab");
    EXPECT_EQ(c.solverDict("p", true).get<word>("solver"), "GAMG");

    controlCase full
    (
        "outerLoopReadAll",
        "nCorrectors 2; nCorrectorsBetweenRecords 1; momentumPredictor off;"
        " nOuterCorrectors 5; acceleration anderson; accelerationDepth 6;"
        " layerMeanCorrection on; RhieChowFactor 0.8;"
    );
    const fdmOuterLoopControl d(*full.mesh);
    EXPECT_EQ(d.nCorrectors(true), 1);
    EXPECT_FALSE(d.momentumPredictor(false));
    EXPECT_FALSE(d.momentumPredictor(true));
    EXPECT_EQ(d.accelerationDepth(), 6);
    EXPECT_TRUE(d.layerMeanCorrection());
    EXPECT_EQ(d.RhieChowFactor(), 0.8);

    controlCase between
    (
        "outerLoopReadBetween",
        "nCorrectors 2; nOuterCorrectors 5;"
        " momentumPredictorBetweenRecords off;"
    );
    const fdmOuterLoopControl e(*between.mesh);
    EXPECT_TRUE(e.momentumPredictor(false));
    EXPECT_FALSE(e.momentumPredictor(true));
}


TEST(fdmOuterLoopControl, wrongBlockOrRelaxationIsRefused)
{
    auto errorFor = [](const std::string& simplec, const std::string& relax)
    {
        controlCase cc("outerLoopBad", simplec, relax);
        return unitTest::errorOf([&]{ fdmOuterLoopControl c(*cc.mesh); });
    };
    const std::string ok = "relaxationFactors { equations { U 0.9; } }";

    const std::string spelt =
        errorFor("nCorrectors 2; nOuterCorector 5;", ok);
    EXPECT_NE(spelt.find("nOuterCorector"), std::string::npos) << spelt;
    EXPECT_NE(spelt.find("nOuterCorrectors"), std::string::npos) << spelt;

    const std::string noRelax =
        errorFor("nCorrectors 2; nOuterCorrectors 5;", "");
    EXPECT_NE(noRelax.find("relaxation"), std::string::npos) << noRelax;

    const std::string one =
        errorFor
        (
            "nCorrectors 2; nOuterCorrectors 5;",
            "relaxationFactors { equations { U 1; } }"
        );
    EXPECT_NE(one.find("relaxation"), std::string::npos) << one;

    const std::string factor =
        errorFor("nCorrectors 2; nOuterCorrectors 5; RhieChowFactor 1.5;", ok);
    EXPECT_NE(factor.find("RhieChowFactor"), std::string::npos) << factor;
}
