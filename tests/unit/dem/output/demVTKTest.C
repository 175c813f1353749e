// Unit test of the DEM's VTK output: particles and contacts files at the
// first step and then every vtkInterval steps only, the particle file with
// one point per sphere and the stresslet parts.

#include "demVTK.H"
#include <fstream>
#include <iterator>
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "demTestSystem.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(demVTK, writesAtTheStartAndEveryIntervalWithEverySphere)
{
    unitTest::scratchCase sc("demVTK");
    Time& runTime = sc.runTime();
    const fdm::lubricatedDEM dem = unitTest::threeSpheres(50);
    fdm::demVTK vtk(runTime, unitTest::parse("vtkInterval 2;"));

    const fileName dir = sc.path()/"VTK";
    auto count = [&]{ return readDir(dir, fileName::FILE).size(); };
    vtk.write(dem, runTime, 0);
    EXPECT_TRUE(isFile(dir/"particles_0.vtp"));
    EXPECT_TRUE(isFile(dir/"contacts_0.vtp"));
    const label atStart = count();
    ++runTime;
    vtk.write(dem, runTime, 1);
    EXPECT_EQ(count(), atStart);
    ++runTime;
    vtk.write(dem, runTime, 2);
    EXPECT_GT(count(), atStart);
    EXPECT_TRUE(isFile(dir/("particles_" + runTime.timeName() + ".vtp")));

    std::ifstream is(dir/"particles_0.vtp");
    const std::string xml
    (
        (std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>()
    );
    EXPECT_NE(xml.find("NumberOfPoints='3'"), std::string::npos)
        << xml.substr(0, 600);
    for (label p = 0; p < fdm::lubricatedInteraction::nStressParts; ++p)
    {
        const std::string name =
            "stresslet_" + std::string(fdm::lubricatedInteraction::stressPartName(p));
        EXPECT_NE(xml.find(name), std::string::npos) << name;
    }
}
