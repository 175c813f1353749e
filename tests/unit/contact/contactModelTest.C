// Unit test of the contact model selection: without a contact block the
// model is none (no reach, no contacts, zero loads); with one, the rough
// contacts with the law it names; a misspelt law is named with the
// nearest valid one.

#include "contactModel.H"
#include "particleContacts.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(contactModel, withoutABlockThereAreNoContacts)
{
    unitTest::scratchCase sc("contactModelNone");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(2, 2, 2), 0.5, unitTest::channelSides()
    );
    autoPtr<contactModel> m = contactModel::New
    (
        unitTest::parse(""), *mesh, scalarField(2, 1.0), 1, 1e-5
    );
    EXPECT_EQ(m->pairReach(), 0);
    EXPECT_EQ(m->nContacts(), 0);
    EXPECT_EQ(m->loads().force.size(), 2);
    EXPECT_EQ(m->loads().force[0], vector::zero);
    EXPECT_EQ(dynamic_cast<const particleContacts*>(m.get()), nullptr);
}


TEST(contactModel, aBlockSelectsTheRoughContactsOfItsLaw)
{
    unitTest::scratchCase sc("contactModelHertz");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(2, 2, 2), 0.5, unitTest::channelSides()
    );
    tmp<volVectorField> U =
        unitTest::zeroField<vector>(*mesh, "U", dimVelocity, "fixedValue");
    autoPtr<contactModel> m = contactModel::New
    (
        unitTest::parse
        (
            "contact { model hertz; roughness 2e-3; friction 0.5; kn 1; }"
        ),
        *mesh, scalarField(2, 1.0), 1, 1e-5
    );
    const auto* rough = dynamic_cast<const particleContacts*>(m.get());
    ASSERT_NE(rough, nullptr);
    EXPECT_EQ(rough->law().type(), "hertz");
    EXPECT_EQ(m->pairReach(), 2e-3);

    const std::string msg = unitTest::errorOf([&]
    {
        contactModel::New
        (
            unitTest::parse
            (
                "contact { model herz; roughness 2e-3; friction 0.5; kn 1; }"
            ),
            *mesh, scalarField(2, 1.0), 1, 1e-5
        );
    });
    EXPECT_NE(msg.find("herz"), std::string::npos) << msg;
    EXPECT_NE(msg.find("hertz"), std::string::npos) << msg;
}
