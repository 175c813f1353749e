// Unit tests for the lubricatedContact dictionary
// (Foam::fdm::lubricatedContact(const dictionary&)): each keyword read,
// bad values named with what is allowed

#include "lubricatedContact.H"
#include "unitTestHelpers.H"
#include "lubricatedContactInputs.H"

#include <gtest/gtest.h>

using namespace Foam;


TEST(lubricatedContact, shearArmsKeywordListsTheChoices)
{
    FatalIOError.throwExceptions();
    dictionary d(unitTest::lubricatedContactInputs(0.2));
    d.add("shearArms", "radius");
    EXPECT_EQ
    (
        fdm::lubricatedContact(d).arms(),
        fdm::lubricatedContact::shearArms::radius
    );
    d.set("shearArms", "centre");
    try
    {
        fdm::lubricatedContact m(d);
        FAIL() << "unknown shearArms accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("centre"), std::string::npos);
        EXPECT_NE(msg.find("contactPoint"), std::string::npos);
    }
}


TEST(lubricatedContact, asperitiesKeywordListsTheChoices)
{
    auto messageOf = [](const dictionary& d)
    {
        return unitTest::errorOf([&d]() { fdm::lubricatedContact m(d); });
    };
    dictionary d(unitTest::lubricatedContactInputs(0.2));
    EXPECT_EQ
    (
        fdm::lubricatedContact(d).asperitiesPlace(),
        fdm::lubricatedContact::asperities::outside
    );
    d.add("asperities", "inside");
    EXPECT_EQ
    (
        fdm::lubricatedContact(d).asperitiesPlace(),
        fdm::lubricatedContact::asperities::inside
    );

    dictionary withTwoSphere(d);
    withTwoSphere.add("lubrication", "twoSphere");
    EXPECT_NE(messageOf(withTwoSphere).find("asperities outside"),
        std::string::npos) << messageOf(withTwoSphere);

    d.set("asperities", "within");
    const std::string msg = messageOf(d);
    EXPECT_NE(msg.find("within"), std::string::npos) << msg;
    EXPECT_NE(msg.find("outside"), std::string::npos) << msg;
}


TEST(lubricatedContact, torquesNoneLeavesOutRollingAndTwisting)
{
    // A pair at u = 0.1 a (within one radius): damping with the thesis'
    // torques, none without; a misspelt choice is named
    dictionary d(unitTest::lubricatedContactInputs(0.2));
    const fdm::lubricatedPairMotion m{vector(0, 1, 0), 0.1, 1, Zero, Zero,
        Zero};
    fdm::lubricatedContact thesis(d);
    fdm::lubricatedPairState s = thesis.start(0.1, 1);
    const fdm::lubricatedPairLoads with = thesis.step(m, 1e-3, s);
    EXPECT_TRUE(thesis.torques());
    EXPECT_GT(with.rollingDamping, 0);
    EXPECT_GT(with.twistingDamping, 0);

    d.add("torques", "none");
    fdm::lubricatedContact none(d);
    s = none.start(0.1, 1);
    const fdm::lubricatedPairLoads without = none.step(m, 1e-3, s);
    EXPECT_FALSE(none.torques());
    EXPECT_EQ(without.rollingDamping, 0);
    EXPECT_EQ(without.twistingDamping, 0);
    EXPECT_EQ(without.normalLubrication, with.normalLubrication);

    d.set("torques", "off");
    const std::string msg =
        unitTest::errorOf([&d]() { fdm::lubricatedContact bad(d); });
    EXPECT_NE(msg.find("torques"), std::string::npos) << msg;
    EXPECT_NE(msg.find("none"), std::string::npos) << msg;
}


TEST(lubricatedContact, badInputNamesTheKeyword)
{
    FatalIOError.throwExceptions();
    const dictionary d(unitTest::lubricatedContactInputs(-0.2));
    try
    {
        fdm::lubricatedContact m(d);
        FAIL() << "negative friction accepted";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE(std::string(e.message()).find("friction"), std::string::npos);
    }
}


TEST(lubricatedContact, lubricationKeywordIsChecked)
{
    auto messageOf = [](const dictionary& d)
    {
        return unitTest::errorOf([&d]() { fdm::lubricatedContact m(d); });
    };
    dictionary misspelt(unitTest::lubricatedContactInputs(0.4));
    misspelt.add("lubrication", "twoSpheres");
    EXPECT_NE(messageOf(misspelt).find("twoSphere"), std::string::npos)
        << messageOf(misspelt);

    dictionary tableWithThesis(unitTest::lubricatedContactInputs(0.4));
    tableWithThesis.add("table", "somewhere");
    EXPECT_NE(messageOf(tableWithThesis).find("twoSphere only"),
        std::string::npos) << messageOf(tableWithThesis);

    dictionary farCutoff(unitTest::lubricatedContactInputs(0.4));
    farCutoff.add("lubrication", "twoSphere");
    farCutoff.add("cutoff", 12.0);
    EXPECT_NE(messageOf(farCutoff).find("allowed cutoff <= 10"),
        std::string::npos) << messageOf(farCutoff);
}


// ************************************************************************* //
