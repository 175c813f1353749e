// Unit tests for the lubricatedContact dictionary
// (Foam::fdm::lubricatedContact(const dictionary&)): each keyword read,
// bad values named with what is allowed

#include "lubricatedContact.H"
#include "unitTestHelpers.H"
#include "lubricatedContactInputs.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;
using Foam::constant::mathematical::pi;


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
        EXPECT_NE(msg.find("centre"), std::string::npos) << msg;
        EXPECT_NE(msg.find("shearArms"), std::string::npos) << msg;
        EXPECT_NE(msg.find("contactPoint"), std::string::npos) << msg;
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
    EXPECT_NE(msg.find("asperities"), std::string::npos) << msg;
    EXPECT_NE(msg.find("outside"), std::string::npos) << msg;
}


TEST(lubricatedContact, torquesKeywordSelectsTheRollingForm)
{
    // A pair at u = 0.1 a (within one radius): the thesis' rolling damping,
    // a tenth of its leading term with article2Code (twisting unchanged),
    // none without either; a misspelt choice is named with the valid ones
    dictionary d(unitTest::lubricatedContactInputs(0.2));
    const fdm::lubricatedPairMotion m{vector(0, 1, 0), 0.1, 1, Zero, Zero,
        Zero};
    scalar L = 0;   // ln(a/u) after the step
    const auto loadsWith = [&](const word& form)
    {
        d.set("torques", form);
        fdm::lubricatedContact law(d);
        fdm::lubricatedPairState s = law.start(0.1, 1);
        const fdm::lubricatedPairLoads loads = law.step(m, 1e-3, s);
        L = -s.logGap;
        return loads;
    };
    using form = fdm::lubricatedContact::torqueForms;
    EXPECT_EQ(fdm::lubricatedContact(d).torques(), form::thesis);
    const fdm::lubricatedPairLoads thesis = loadsWith("thesis");
    const fdm::lubricatedPairLoads code = loadsWith("article2Code");
    const fdm::lubricatedPairLoads none = loadsWith("none");
    EXPECT_GT(thesis.rollingDamping, 0);
    EXPECT_GT(thesis.twistingDamping, 0);

    // (3/2 + c u) L against (3/20 + c u) L at the same gap: their
    // difference is (27/20) pi eta a^3 L, L = ln(a/u), eta = a = 1
    EXPECT_NEAR(L, std::log(10.0), 0.05);
    EXPECT_NEAR
    (
        thesis.rollingDamping - code.rollingDamping, 1.35*pi*L, 1e-12
    );
    EXPECT_EQ(code.twistingDamping, thesis.twistingDamping);
    EXPECT_EQ(none.rollingDamping, 0);
    EXPECT_EQ(none.twistingDamping, 0);
    EXPECT_EQ(none.normalLubrication, thesis.normalLubrication);

    d.set("torques", "off");
    const std::string msg =
        unitTest::errorOf([&d]() { fdm::lubricatedContact bad(d); });
    EXPECT_NE(msg.find("torques"), std::string::npos) << msg;
    EXPECT_NE(msg.find("article2Code"), std::string::npos) << msg;
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
