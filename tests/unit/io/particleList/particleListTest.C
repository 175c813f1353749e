// Unit tests of the particle list reader and its physical checks: inline
// rows with and without a count, the stops on a malformed list naming the
// file, and checkParticleList on radii, walls and overlaps.

#include "particleList.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

using unitTest::parse;
using unitTest::errorOf;

fdm::periodicBox channel()
{
    // Walls at y = 0 and 10, periodic in x and z
    FixedList<bool, 3> periodic(true);
    periodic[1] = false;
    return fdm::periodicBox(point::zero, point(10, 10, 10), periodic);
}

} // namespace


TEST(readParticleList, readsInlineRowsWithOrWithoutCount)
{
    const dictionary plain
    (
        parse("particles ( (a (1 2 3) 0.5) (b (4 5 6) 1) );")
    );
    const fdm::particleList l = fdm::readParticleList(plain, "constant");
    ASSERT_EQ(l.group.size(), 2);
    EXPECT_EQ(l.group[1], "b");
    EXPECT_EQ(l.position[0], point(1, 2, 3));
    EXPECT_EQ(l.radius[1], 1);

    const dictionary counted(parse("particles 1 ( (a (1 2 3) 0.5) );"));
    EXPECT_EQ(fdm::readParticleList(counted, "constant").group.size(), 1);
}


TEST(readParticleList, stopsOnMalformedLists)
{
    const dictionary wrongCount(parse("particles 3 ( (a (1 2 3) 0.5) );"));
    const std::string count = errorOf
    (
        [&]{ fdm::readParticleList(wrongCount, "constant"); }
    );
    EXPECT_NE(count.find("announces 3"), std::string::npos) << count;

    const dictionary empty(parse("particles ();"));
    EXPECT_NE
    (
        errorOf([&]{ fdm::readParticleList(empty, "constant"); })
       .find("is empty"),
        std::string::npos
    );

    const dictionary both
    (
        parse("particles ( (a (1 2 3) 0.5) ); particlesFile \"list\";")
    );
    EXPECT_NE
    (
        errorOf([&]{ fdm::readParticleList(both, "constant"); })
       .find("exactly one"),
        std::string::npos
    );

    const dictionary missing(parse("particlesFile \"noSuchList\";"));
    EXPECT_NE
    (
        errorOf([&]{ fdm::readParticleList(missing, "/nonexistent"); })
       .find("does not exist"),
        std::string::npos
    );
}


TEST(checkParticleList, acceptsSeparateSpheresInsideTheWalls)
{
    const List<point> x({point(1, 2, 1), point(3.5, 2, 1)});
    const List<scalar> a({1, 1});
    EXPECT_EQ
    (
        errorOf([&]{ fdm::checkParticleList(x, a, channel(), "list"); }),
        ""
    );
}


TEST(checkParticleList, stopsOnRadiusWallOrOverlap)
{
    const List<point> x({point(1, 2, 1), point(3.5, 2, 1)});
    const List<scalar> zero({1, 0});
    EXPECT_NE
    (
        errorOf([&]{ fdm::checkParticleList(x, zero, channel(), "l"); })
       .find("radius 0"),
        std::string::npos
    );

    // Through the wall y = 0
    const List<point> low({point(1, 0.5, 1), point(5, 5, 5)});
    const List<scalar> a({1, 1});
    EXPECT_NE
    (
        errorOf([&]{ fdm::checkParticleList(low, a, channel(), "l"); })
       .find("not inside the domain"),
        std::string::npos
    );

    // Overlap across the periodic x boundary
    const List<point> across({point(0.5, 5, 5), point(9.6, 5, 5)});
    EXPECT_NE
    (
        errorOf([&]{ fdm::checkParticleList(across, a, channel(), "l"); })
       .find("overlapping"),
        std::string::npos
    );
}


// ************************************************************************* //
