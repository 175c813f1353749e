// Unit test of fdm::evaluateCoupledPatches on a channel box (cyclic in x
// and z, fixedFluxPressure walls): a cyclic patch holding stale values
// takes the mean of the two cells its faces join (the linear face value
// on a uniform mesh, found here from the patches' face cells), and the
// walls keep what they held (a fixedFluxPressure patch evaluated before
// its gradient is set is a fatal error).

#include "evaluateCoupledPatches.H"
#include "cyclicFvPatch.H"
#include "unitTestCase.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(evaluateCoupledPatches, cyclicFacesTakeTheirCellsMeanWallsKeepTheirs)
{
    unitTest::scratchCase sc("evaluateCoupledPatches");
    autoPtr<fvMesh> mesh = unitTest::boxMesh
    (
        sc.runTime(), labelVector(4, 3, 5), 0.5, unitTest::channelSides()
    );
    tmp<volScalarField> tp = unitTest::zeroField<scalar>
    (
        *mesh, "p", dimPressure, "fixedFluxPressure"
    );
    volScalarField& p = tp.ref();
    forAll(p, c)
    {
        const point& x = mesh->C()[c];
        p[c] = 1 + x.x() + 2*x.y()*x.y() - 0.3*x.z();
    }
    label nCyclic = 0;
    forAll(p.boundaryField(), patchi)
    {
        // Stale values everywhere, as decomposePar's on a processorCyclic
        const label nFaces = mesh->boundary()[patchi].size();
        p.boundaryFieldRef()[patchi] == scalarField(nFaces, 99.0);
        nCyclic += isA<cyclicFvPatch>(mesh->boundary()[patchi]) ? 1 : 0;
    }
    ASSERT_EQ(nCyclic, 4);

    fdm::evaluateCoupledPatches(p);

    forAll(p.boundaryField(), patchi)
    {
        const fvPatch& patch = mesh->boundary()[patchi];
        const scalarField& pb = p.boundaryField()[patchi];
        if (!isA<cyclicFvPatch>(patch))
        {
            EXPECT_EQ(max(mag(pb - 99.0)), 0) << patch.name();
            continue;
        }
        const labelUList& mine = patch.faceCells();
        const labelUList& theirs =
            refCast<const cyclicFvPatch>(patch).neighbPatch().faceCells();
        forAll(pb, f)
        {
            EXPECT_NEAR(pb[f], 0.5*(p[mine[f]] + p[theirs[f]]), 1e-13)
                << patch.name() << " face " << f;
        }
    }
}


// ************************************************************************* //
