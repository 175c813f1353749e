// Unit test of particleGroup: the defaults, the three forms of a motion
// (free, fixed, a vector) and the input errors, each naming the keyword and
// what is allowed.

#include "particleGroup.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(particleGroup, defaultsAreNeutrallyBuoyantFreeAndUnloaded)
{
    const particleGroup g("suspended", unitTest::parse(""), 998.0);
    EXPECT_EQ(g.name(), "suspended");
    EXPECT_EQ(g.density(), 998.0);
    EXPECT_FALSE(g.translationPrescribed());
    EXPECT_FALSE(g.rotationPrescribed());
    EXPECT_EQ(g.force(), vector::zero);
    EXPECT_EQ(g.torque(), vector::zero);

    const particleGroup d;
    EXPECT_EQ(d.name(), "default");
    EXPECT_EQ(d.density(), 1.0);
    EXPECT_FALSE(d.translationPrescribed());
}


TEST(particleGroup, fixedAndPrescribedMotionsAndLoads)
{
    const particleGroup g
    (
        "held",
        unitTest::parse
        (
            "density 2500; translation fixed; rotation (0 0 0.5);"
            " force (1 -2 3); torque (0 0 -1);"
        ),
        1000.0
    );
    EXPECT_EQ(g.density(), 2500.0);
    EXPECT_TRUE(g.translationPrescribed());
    EXPECT_EQ(g.translation(), vector::zero);
    EXPECT_TRUE(g.rotationPrescribed());
    EXPECT_EQ(g.rotation(), vector(0, 0, 0.5));
    EXPECT_EQ(g.force(), vector(1, -2, 3));
    EXPECT_EQ(g.torque(), vector(0, 0, -1));

    const particleGroup free("free", unitTest::parse("rotation free;"), 1);
    EXPECT_FALSE(free.rotationPrescribed());
}


TEST(particleGroup, badInputNamesTheKeywordAndWhatIsAllowed)
{
    const std::string motion = unitTest::errorOf([]{
        particleGroup("g", unitTest::parse("translation held;"), 1); });
    EXPECT_NE(motion.find("translation"), std::string::npos) << motion;
    EXPECT_NE(motion.find("free, fixed or a velocity vector"),
              std::string::npos) << motion;

    const std::string density = unitTest::errorOf([]{
        particleGroup("g", unitTest::parse("density -1;"), 1); });
    EXPECT_NE(density.find("density -1"), std::string::npos) << density;
    EXPECT_NE(density.find("> 0"), std::string::npos) << density;

    const std::string spelling = unitTest::errorOf([]{
        particleGroup("g", unitTest::parse("torgue (0 0 1);"), 1); });
    EXPECT_NE(spelling.find("torgue"), std::string::npos) << spelling;
    EXPECT_NE(spelling.find("torque"), std::string::npos) << spelling;
}
