// Unit test of what the FDM cloud writes besides its restart state: which
// steps record (time series every timeSeriesInterval steps, VTK every
// vtkInterval, the write times, the last step), the HDF5 records published
// at the write times, the lagrangian cloud with d = 2a, and the output
// block's input errors.

#include "particleCloudOutput.H"
#include "IOField.H"
#include "cloud.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "unitTestHDF5.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const char* controls =
    "deltaT 0.1; endTime 1; writeControl timeStep; writeInterval 5;";

struct twoParticles
{
    fdm::particleState state;
    fdm::particleLoads hydro{2}, contact{2};
    List<scalar> trace{List<scalar>(2, 0.0)};

    twoParticles()
    {
        state.group = labelList({0, 0});
        state.radius = scalarField(List<scalar>({0.1, 0.15}));
        state.position =
            pointField({point(0.3, 0.3, 0.3), point(0.7, 0.6, 0.5)});
        state.resizeVelocities();
        state.U[1] = vector(1, 2, 3);
    }

    particleCloudOutput::particles view() const
    {
        return {state, hydro, trace, contact, UList<bool>::null()};
    }
};

autoPtr<fvMesh> box(unitTest::scratchCase& sc)
{
    return unitTest::boxMesh
    (
        sc.runTime(), labelVector(4, 4, 4), 0.25, unitTest::channelSides()
    );
}

} // End anonymous namespace


TEST(particleCloudOutput, recordsOnTheDueStepsAndPublishesAtWriteTimes)
{
    unitTest::scratchCase sc("particleCloudOutput", controls);
    autoPtr<fvMesh> mesh = box(sc);
    particleCloudOutput out
    (
        *mesh, unitTest::parse("timeSeriesInterval 2; vtkInterval 3;"),
        dictionary()
    );
    const twoParticles p;
    Time& runTime = sc.runTime();
    labelList due;
    while (runTime.run())
    {
        ++runTime;
        if (out.recordDue())
        {
            due.append(runTime.timeIndex());
        }
        out.writeTimeSeries
        (
            p.view(), []{ return particleHDF5Metadata::description(); }
        );
    }
    // Even steps, VTK steps 3, 6, 9, the write times 5, 10
    EXPECT_EQ(due, labelList({2, 3, 4, 5, 6, 8, 9, 10}));

    const fileName h5 = sc.path()/"postProcessing/particles.h5";
    const std::vector<double> t = unitTest::readDataset(h5, "time");
    ASSERT_EQ(t.size(), 5u);
    for (label k = 0; k < 5; ++k)
    {
        EXPECT_NEAR(t[k], 0.2*(k + 1), 1e-12) << k;
    }
}


TEST(particleCloudOutput, lagrangianCloudHoldsTheParticles)
{
    unitTest::scratchCase sc("particleCloudOutputLagrangian", controls);
    autoPtr<fvMesh> mesh = box(sc);
    const particleCloudOutput out(*mesh, dictionary(), dictionary());
    const twoParticles p;
    out.writeLagrangian(p.view());

    const fileName cloudDir = cloud::prefix/"particles";
    const IOField<scalar> d
    (
        IOobject("d", "0", cloudDir, *mesh, IOobject::MUST_READ)
    );
    EXPECT_EQ(d, scalarList({0.2, 0.3}));
    const IOField<vector> U
    (
        IOobject("U", "0", cloudDir, *mesh, IOobject::MUST_READ)
    );
    EXPECT_EQ(U[1], vector(1, 2, 3));
    for (const word f : {"contactForce", "stresslet", "omega", "group"})
    {
        EXPECT_TRUE(isFile(sc.path()/"0"/cloudDir/f)) << f;
    }
}


TEST(particleCloudOutput, badOutputBlockIsRefused)
{
    unitTest::scratchCase sc("particleCloudOutputBad", controls);
    autoPtr<fvMesh> mesh = box(sc);
    const std::string zero = unitTest::errorOf([&]
    {
        particleCloudOutput
            (*mesh, unitTest::parse("timeSeriesInterval 0;"), dictionary());
    });
    EXPECT_NE(zero.find("timeSeriesInterval 0"), std::string::npos) << zero;
    EXPECT_NE(zero.find(">= 1"), std::string::npos) << zero;

    const std::string spelt = unitTest::errorOf([&]
    {
        particleCloudOutput
            (*mesh, unitTest::parse("vtkIntervall 2;"), dictionary());
    });
    EXPECT_NE(spelt.find("vtkInterval"), std::string::npos) << spelt;
}
