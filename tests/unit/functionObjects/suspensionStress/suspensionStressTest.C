// Unit test of the suspensionStress function object on a channel box
// (2 x 4 x 2, walls at y = 0 and 4) with a particle state written by hand:
// two spheres sheared at rate 0.5 whose stresslets give, by hand, the
// volume fraction, the relative viscosity 1 + Sigma^p_xy/(eta gammaDot)
// (eq 2.76), the contact share and N1/Sigma_xy; a wall layer of half the
// channel is refused naming the keyword.

#include "suspensionStress.H"
#include "IFstream.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>
#include <sstream>

using namespace Foam;

namespace
{

const scalar a = 0.4, gammaDot = 0.5, eta = 2*0.25;

struct stressCase
{
    unitTest::scratchCase sc;
    autoPtr<fvMesh> mesh;

    explicit stressCase(const word& name)
    :
        sc(name)
    {
        sc.writeFile("constant/transportProperties", "rho 2; nu 0.25;");
        // u_x = gammaDot y at both centres; S_xy 0.2 and 0.3, S_xx 0.05,
        // S_yy -0.03 each; contact S_xy 0.1 on the first
        sc.writeFile
        (
            "0/particleState",
            "position 2((1 1 1) (1 3 1)); velocity 2((0.5 0 0) (1.5 0 0));"
            " radius 2(0.4 0.4);"
            " stresslet 2((0.05 0.2 0 -0.03 0 -0.02) (0.05 0.3 0 -0.03 0"
            " -0.02)); dipoleTrace 2(0 0);"
            " contactStresslet 2((0 0.1 0 0 0 0) (0 0 0 0 0 0));"
        );
        mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(4, 8, 4), 0.5, unitTest::channelSides()
        );
    }

    autoPtr<functionObjects::suspensionStress> object(const char* dict)
    {
        return autoPtr<functionObjects::suspensionStress>::New
        (
            "stress", sc.runTime(), unitTest::parse(dict)
        );
    }
};

} // End anonymous namespace


TEST(suspensionStress, rowAgainstTheStressletsByHand)
{
    stressCase sc("suspensionStress");
    sc.object("normal y; flow x; bins 4; wallLayer 0;")->execute();

    IFstream is(sc.sc.path()/"postProcessing/stress/0/suspensionStress.dat");
    ASSERT_TRUE(is.good());
    string line;
    do { is.getLine(line); } while (line[0] == '#');
    std::istringstream row(line);
    std::vector<double> v;
    for (double x; row >> x;) { v.push_back(x); }
    ASSERT_GE(v.size(), 11u);

    const scalar V = 2*4*2;
    const scalar phi = 2*4.0/3.0*constant::mathematical::pi*pow3(a)/V;
    const scalar particleXy = (0.2 + 0.3 + 0.1)/V;
    const scalar Sxy = eta*gammaDot + particleXy;
    EXPECT_NEAR(v[1], phi, 1e-12);                               // phi
    EXPECT_NEAR(v[4], gammaDot, 1e-12);                          // shear rate
    EXPECT_NEAR(v[6], 1 + particleXy/(eta*gammaDot), 1e-12);     // etaRel
    EXPECT_NEAR(v[8], (0.1/V)/Sxy, 1e-12);                       // contact
    EXPECT_NEAR(v[9], ((0.05 + 0.03)*2/V)/Sxy, 1e-12);           // N1
}


TEST(suspensionStress, wallLayerOfHalfTheChannelIsRefused)
{
    stressCase sc("suspensionStressBad");
    const std::string msg = unitTest::errorOf([&]
    {
        sc.object("normal y; flow x; wallLayer 2;");
    });
    EXPECT_NE(msg.find("wallLayer"), std::string::npos) << msg;
    EXPECT_NE(msg.find("half the channel height"), std::string::npos) << msg;
}
