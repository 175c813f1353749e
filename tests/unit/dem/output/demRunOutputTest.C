// Unit test of what a lubricatedDEMFoam run writes after its steps: over
// five steps with a write every second step and a record every second
// step, stress.dat and particles.h5 get a record at steps 2 and 4, the
// particleState is written at the write times and at the run's end (step
// 5, not a write time), and the VTK files of the start time exist.

#include "demRunOutput.H"
#include "IFstream.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "unitTestHDF5.H"
#include "demTestSystem.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(demRunOutput, recordsEveryIntervalAndWritesAtWriteTimesAndTheEnd)
{
    unitTest::scratchCase sc
    (
        "demRunOutput",
        "deltaT 0.001; endTime 0.005; writeInterval 2;"
    );
    Time& runTime = sc.runTime();
    fdm::lubricatedDEM dem = unitTest::threeSpheres(0);
    {
        fdm::demRunOutput output
        (
            runTime,
            dem,
            unitTest::parse
            (
                "particles ((a (2 3 4) 1) (a (4.05 3.2 4) 1)"
                " (a (6 5 2) 1.2)); density 1; output { interval 2; }"
            )
        );
        EXPECT_TRUE(isFile(sc.path()/"VTK/particles_0.vtp"));
        while (runTime.run())
        {
            ++runTime;
            dem.step(runTime.deltaTValue());
            output.afterStep(dem, runTime);
        }
        EXPECT_EQ(output.steps(), 5);
    }

    for (const word t : {"0.002", "0.004", "0.005"})
    {
        EXPECT_TRUE(isFile(sc.path()/t/"particleState")) << t;
    }
    for (const word t : {"0.001", "0.003"})
    {
        EXPECT_FALSE(isDir(sc.path()/t)) << t;
    }

    IFstream is(sc.path()/"postProcessing/lubricatedDEM/0/stress.dat");
    label rows = 0;
    for (string line; is.getLine(line), is.good();)
    {
        rows += (!line.empty() && line[0] != '#');
    }
    EXPECT_EQ(rows, 2);

    const auto x = unitTest::readDataset
    (
        sc.path()/"postProcessing/particles.h5",
        "position"
    );
    EXPECT_EQ(x.size(), 2u*3*3);
}
