// Unit test of the sheared processorCyclic patch field on a unit box of
// 8^3 cells whose y sides are processorCyclic parts (towards processor 1)
// of the empty sheared cyclic patches yMinCyclic and yMaxCyclic, at
// gammaDot = 1 and t = 0.25 + 1/48 (offset 2.17 cells).  Serial, the
// exchange itself does not run (case test restartLeesEdwards runs it on 2
// ranks); what it does with the received row does: the values received
// at the faces (those of the cells opposite them) become the neighbour
// values at x - s on the upper side and x + s on the lower one, plus the
// velocity jump -+gammaDot L_y; coupleLeesEdwardsAcrossProcessors makes
// the patch fields of a sheared field this type and leaves others, and
// the written entry reads back as the same field.

#include "shareLeesEdwardsCoupling.H"
#include "unitTestCase.H"
#include "unitTestHelpers.H"
#include "StringStream.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

struct processorBox
{
    unitTest::scratchCase sc;
    autoPtr<fvMesh> mesh;

    explicit processorBox(const word& name)
    :
        sc(name)
    {
        mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(8, 8, 8), 1.0/8,
            {"cyclic", "cyclic", "processorCyclic", "processorCyclic",
             "cyclic", "cyclic"}
        );
        sc.runTime().setTime(0.25 + 1.0/48, 1);
    }

    //- A vector field, sheared (leesEdwards on the referred cyclic
    //  patches) or not
    tmp<volVectorField> velocity(const bool sheared) const
    {
        const std::string cyclic = sheared
            ? "type leesEdwards; patchType cyclic; shearRate 1;"
            : "type cyclic;";
        return tmp<volVectorField>::New
        (
            IOobject("U", mesh->time().timeName(), *mesh),
            *mesh,
            unitTest::parse
            ((
                "dimensions [0 1 -1 0 0 0 0]; internalField uniform (0 0 0);"
                " boundaryField { \"(xMin|xMax|zMin|zMax)\" { type cyclic; }"
                " \"(yMin|yMax)Cyclic\" { " + cyclic + " }"
                " \"(yMin|yMax)\" { type processorCyclic;"
                " value uniform (0 0 0); } }"
            ).c_str())
        );
    }

    const fvPatchVectorField& side(const volVectorField& U, const word& n)
    const
    {
        return U.boundaryField()[mesh->boundaryMesh().findPatchID(n)];
    }
};

} // End anonymous namespace


TEST(leesEdwardsProcessorCyclic, onlySheared)
{
    processorBox box("leesEdwardsProcessorOnlySheared");
    tmp<volVectorField> plain(box.velocity(false));
    fdm::coupleLeesEdwardsAcrossProcessors(plain.ref());
    EXPECT_FALSE
    (
        isA<leesEdwardsProcessorCyclicFvPatchField<vector>>
        (
            box.side(plain(), "yMax")
        )
    );
    tmp<volVectorField> sheared(box.velocity(true));
    fdm::coupleLeesEdwardsAcrossProcessors(sheared.ref());
    for (const word side : {"yMin", "yMax"})
    {
        const auto* pf = isA<leesEdwardsProcessorCyclicFvPatchField<vector>>
        (
            box.side(sheared(), side)
        );
        ASSERT_TRUE(pf) << side;
        EXPECT_EQ(pf->shearRate(), 1);
        EXPECT_TRUE(pf->jumps());
    }
}


TEST(leesEdwardsProcessorCyclic, receivedRowIsShiftedAndJumps)
{
    processorBox box("leesEdwardsProcessorShift");
    tmp<volVectorField> U(box.velocity(true));
    fdm::coupleLeesEdwardsAcrossProcessors(U.ref());
    const scalar s = 0.25 + 1.0/48;
    for (const word side : {"yMin", "yMax"})
    {
        const auto& pf = refCast<const leesEdwardsProcessorCyclicFvPatchField
            <vector>>(box.side(U(), side));
        // Received: a smooth periodic function of the faces' x and z
        const vectorField& Cf = pf.patch().Cf();
        auto g = [](const scalar x, const scalar z)
        {
            return vector
            (
                std::sin(2*M_PI*x), std::cos(2*M_PI*x) + z, 0
            );
        };
        vectorField received(Cf.size());
        forAll(Cf, f)
        {
            received[f] = g(Cf[f].x(), Cf[f].z());
        }
        const scalar sign = side == "yMax" ? 1 : -1;
        const vectorField nbr(pf.neighbourValues(received));
        const vectorField noJump(pf.neighbourValues(received, false));
        scalar err = 0;
        forAll(Cf, f)
        {
            const vector expected = g(Cf[f].x() - sign*s, Cf[f].z());
            // Linear interpolation between faces 1/8 apart: within
            // (2 pi)^2/8 (1/8)^2 of a unit sinusoid
            err = max(err, mag(noJump[f] - expected));
            EXPECT_NEAR(nbr[f].x() - noJump[f].x(), sign*1.0, 1e-14);
        }
        EXPECT_LT(err, 0.08) << side;
        EXPECT_GT(err, 1e-3) << side << " (the interpolation error shows)";
    }
}


TEST(leesEdwardsProcessorCyclic, writtenEntryReadsBack)
{
    processorBox box("leesEdwardsProcessorReadBack");
    tmp<volVectorField> U(box.velocity(true));
    fdm::coupleLeesEdwardsAcrossProcessors(U.ref());
    const fvPatchVectorField& pf = box.side(U(), "yMax");
    OStringStream os;
    pf.write(os);
    IStringStream is(os.str());
    const dictionary dict(is);
    EXPECT_EQ(dict.get<word>("type"), "leesEdwardsProcessorCyclic");
    EXPECT_EQ(dict.get<word>("patchType"), "processorCyclic");
    tmp<fvPatchVectorField> back
    (
        fvPatchVectorField::New(pf.patch(), U().internalField(), dict)
    );
    const auto* read =
        isA<leesEdwardsProcessorCyclicFvPatchField<vector>>(back());
    ASSERT_TRUE(read);
    EXPECT_EQ(read->shearRate(), 1);
    EXPECT_TRUE(read->jumps());
}
