// Unit tests for the contact laws selected by name (hertz, adhesiveHertz):
// the adhesive force of thesis 1, chapter 5 (eqs 5.1-5.2) and its input

#include "contactLawTestHelpers.H"
#include "unitTestHelpers.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;


TEST(hertzContact, selectedByName)
{
    EXPECT_EQ(law(thesis)->type(), "hertz");
    EXPECT_EQ(law(thesis + " model hertz;")->type(), "hertz");
    EXPECT_EQ(law(thesis)->adhesionForce(), 0);
}


TEST(hertzContact, adhesionPullOffAndFrictionOnTheElasticPart)
{
    const auto c = law(thesis + " model adhesiveHertz; adhesionForce 2;");
    EXPECT_EQ(c->type(), "adhesiveHertz");

    // Just inside the roughness the pair pulls with F_adh (eq 5.1)
    fdm::contactGeometry g = geometry(hr*(1 - 1e-9));
    vector slip = Zero;
    fdm::contactForce f = c->evaluate(g, slip);
    EXPECT_NEAR(f.force.x(), 2, 1e-6);

    // Outside it nothing: the pull-off force is F_adh
    g.gap = hr*(1 + 1e-9);
    f = c->evaluate(g, slip);
    EXPECT_EQ(mag(f.force), 0);

    // Where F_el = F_adh the net normal force vanishes, and the friction
    // cap is mu F_el, not mu (F_el - F_adh) (eq 5.2)
    scalar lo = floorGap, hi = hr;
    for (int it = 0; it < 200; ++it)
    {
        const scalar mid = 0.5*(lo + hi);
        (c->elasticNormalForce(mid, floorGap) > 2 ? lo : hi) = mid;
    }
    g.gap = 0.5*(lo + hi);
    slip = vector(0, 1, 0);
    f = c->evaluate(g, slip);
    EXPECT_NEAR(f.force.x(), 0, 1e-9);
    EXPECT_NEAR(mag(f.tangential), mu*2, 1e-9);

    // Adhesion number: F_adh = G 6 pi eta a_1^2 gammaDot
    const auto d =
        law
        (
            "model adhesiveHertz; roughness 5e-3; friction 0.1;"
            " shearRate 3; meanDeformation 0.1; adhesionNumber 0.5;"
        );
    EXPECT_NEAR(d->adhesionForce(), 0.5*6*constant::mathematical::pi*3, 1e-12);
}


TEST(hertzContact, adhesionGivenOnceWithItsScale)
{
    const std::string adhesive = thesis + " model adhesiveHertz;";
    EXPECT_NE(unitTest::errorOf([&]() { law(adhesive); })
        .find("neither"), std::string::npos);
    EXPECT_NE(unitTest::errorOf([&]()
        { law(adhesive + " adhesionForce 1; adhesionNumber 1;"); })
        .find("both"), std::string::npos);
    // kn given directly: no shearRate to scale the adhesion number by
    EXPECT_NE(unitTest::errorOf([&]()
        { law(adhesive + " adhesionNumber 1;"); })
        .find("needs the reference shearRate"), std::string::npos);
    EXPECT_NE(unitTest::errorOf([&]()
        { law(adhesive + " adhesionForce -1;"); })
        .find("adhesionForce"), std::string::npos);
}
