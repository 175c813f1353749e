// Unit tests of the strict keyword check: the edit distance against
// hand-counted values, the nearest spelling of the misspellings users make,
// and the check itself on small dictionaries.

#include "checkKeywords.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

using unitTest::parse;


TEST(editDistance, handCountedValues)
{
    EXPECT_EQ(fdm::editDistance("", ""), 0u);
    EXPECT_EQ(fdm::editDistance("", "abc"), 3u);
    EXPECT_EQ(fdm::editDistance("kitten", "sitting"), 3u);
    // Case is ignored: subgrid is subGrid
    EXPECT_EQ(fdm::editDistance("subgrid", "subGrid"), 0u);
    // One deletion, one transposition (two substitutions)
    EXPECT_EQ(fdm::editDistance("gravty", "gravity"), 1u);
    EXPECT_EQ(fdm::editDistance("frictoin", "friction"), 2u);
}


TEST(nearestSpelling, misspeltKeywords)
{
    const std::vector<std::string> top
    {
        "coupling", "gravity", "gapFloor", "groups", "indicator",
        "particles", "particlesFile", "subGrid", "contact", "output"
    };
    EXPECT_EQ(fdm::nearestSpelling("subgrid", top), "subGrid");
    EXPECT_EQ(fdm::nearestSpelling("contacts", top), "contact");
    EXPECT_EQ(fdm::nearestSpelling("gravty", top), "gravity");
    EXPECT_EQ(fdm::nearestSpelling("particleFile", top), "particlesFile");
    EXPECT_EQ(fdm::nearestSpelling("anything", {}), "");
}


TEST(checkKeywords, acceptsAllowedAndHeader)
{
    FatalIOError.throwExceptions();
    const dictionary d(parse("FoamFile { version 2.0; } a 1; b { c 2; }"));
    EXPECT_NO_THROW(fdm::checkKeywords(d, {"a", "b"}));
}


TEST(checkKeywords, stopsOnUnknownKeywordNamingTheNearest)
{
    FatalIOError.throwExceptions();
    const dictionary d(parse("roughness 5e-3; frictoin 0.5;"));
    try
    {
        fdm::checkKeywords(d, {"roughness", "friction", "kn"}, "contact");
        FAIL() << "frictoin was accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("'frictoin'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("'friction'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("contact"), std::string::npos) << msg;
    }
}


TEST(checkChoice, stopsOnUnknownValue)
{
    FatalIOError.throwExceptions();
    const dictionary d(parse("model hertx;"));
    EXPECT_NO_THROW(fdm::checkChoice(d, "model", "hertz", {"hertz", "none"}));
    EXPECT_THROW
    (
        fdm::checkChoice(d, "model", "hertx", {"hertz", "none"}),
        Foam::error
    );
}


TEST(readChoice, defaultValueAndMisspeltChoice)
{
    // An Enum choice: the default without the keyword, the named value
    // with it, a misspelt one stopped with the keyword and the nearest
    // valid spelling (Enum's own lookup names neither)
    enum class shape { sphere, cube };
    const Enum<shape> names
    ({
        {shape::sphere, "sphere"},
        {shape::cube, "cube"}
    });
    EXPECT_EQ
    (
        fdm::readChoice(parse("other 1;"), "shape", names, shape::sphere),
        shape::sphere
    );
    EXPECT_EQ
    (
        fdm::readChoice(parse("shape cube;"), "shape", names, shape::sphere),
        shape::cube
    );
    const dictionary bad(parse("shape cub;"));
    const std::string msg = unitTest::errorOf
    (
        [&bad, &names]()
        {
            fdm::readChoice(bad, "shape", names, shape::sphere);
        }
    );
    EXPECT_NE(msg.find("shape 'cub'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("nearest valid spelling: 'cube'"), std::string::npos)
        << msg;
}
