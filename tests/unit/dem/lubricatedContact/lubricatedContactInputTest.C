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
