// Unit test of momentumBalance on a channel box (walls at y = 0 and 1):
// the wall force of a parabolic profile against its value worked out by
// hand, the wall force of an arbitrary field against the volume sum of the
// discrete momentum operators (eqs 4.14-4.16 telescope: Gauss sums over
// cells leave the boundary faces), and the line written, in a file of its
// own per run.

#include "momentumBalance.H"
#include "fvc.H"
#include "IFstream.H"
#include "unitTestCase.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const label n = 4;
const scalar Delta = 0.25;
const scalar nu = 0.7;

//- A channel box of n^3 cells with zero U (walls fixed) and p on it
struct channel
{
    unitTest::scratchCase sc;
    autoPtr<fvMesh> mesh;
    tmp<volVectorField> tU;
    tmp<volScalarField> tp;

    explicit channel(const word& name)
    :
        sc(name)
    {
        mesh = unitTest::boxMesh
        (
            sc.runTime(), labelVector(n, n, n), Delta,
            unitTest::channelSides()
        );
        tU = unitTest::zeroField<vector>
        (
            *mesh, "U", dimVelocity, "fixedValue"
        );
        tp = unitTest::zeroField<scalar>(*mesh, "p", sqr(dimVelocity));
    }
};

} // End anonymous namespace


TEST(momentumBalance, parabolicProfileWallForceByHand)
{
    channel ch("momentumBalanceParabola");
    const autoPtr<fvMesh>& mesh = ch.mesh;
    volVectorField& U = ch.tU.ref();
    volScalarField& p = ch.tp.ref();

    // u_x = y (1 - y), zero on both walls; p 2 on the lower wall, 1 on the
    // upper one
    forAll(U, celli)
    {
        const scalar y = mesh->C()[celli].y();
        U[celli] = vector(y*(1 - y), 0, 0);
    }
    p.boundaryFieldRef()[mesh->boundaryMesh().findPatchID("yMin")] == 2;
    p.boundaryFieldRef()[mesh->boundaryMesh().findPatchID("yMax")] == 1;

    // Each wall: nu (0 - u(Delta/2))/(Delta/2) per unit area on area 1
    // (the dev(T(grad U)) traction is zero: u_x depends on y only);
    // pressure: -p S_f summed, 2 - 1 along +y
    const scalar uFirst = 0.5*Delta*(1 - 0.5*Delta);
    const vector expected(-2*nu*uFirst/(0.5*Delta), 2 - 1, 0);
    const vector F = momentumBalance::wallForce(U, p, nu);
    EXPECT_LT(mag(F - expected), 1e-12);
}


TEST(momentumBalance, wallForceIsTheVolumeSumOfTheMomentumOperators)
{
    channel ch("momentumBalanceTelescope");
    const autoPtr<fvMesh>& mesh = ch.mesh;
    volVectorField& U = ch.tU.ref();
    volScalarField& p = ch.tp.ref();

    // Arbitrary periodic fields with arbitrary wall values
    forAll(U, celli)
    {
        const vector& x = mesh->C()[celli];
        U[celli] = vector
        (
            Foam::sin(2*M_PI*x.x()) + x.y()*x.y(),
            (1 + Foam::cos(2*M_PI*x.z()))*x.y()*x.y(),
            0.3*Foam::sin(2*M_PI*(x.x() + x.z())) + x.y()
        );
        p[celli] = Foam::cos(2*M_PI*x.x())*(1 + x.y());
    }
    forAll(mesh->boundary(), patchi)
    {
        if (!mesh->boundary()[patchi].coupled())
        {
            const vectorField& Cf = mesh->boundary()[patchi].Cf();
            U.boundaryFieldRef()[patchi] ==
                vector(0.5, 0, 0.2)*Cf.component(0);
            p.boundaryFieldRef()[patchi] ==
                1 + Cf.component(2) + 2*Cf.component(1);
        }
    }

    const dimensionedScalar nuDim("nu", dimViscosity, nu);
    const volVectorField divSigma
    (
        nuDim*fvc::laplacian(U)
      + fvc::div(nuDim*dev(T(fvc::grad(U))))
      - fvc::grad(p)
    );
    const vector volumeSum = gSum(divSigma.primitiveField()*mesh->V());
    const vector F = momentumBalance::wallForce(U, p, nu);
    // Every component of every term non-zero (the dev(T(grad U))
    // traction included: a check that leaves it out fails)
    EXPECT_GT(cmptMin(cmptMag(F)), 0.1);
    EXPECT_LT(mag(F - volumeSum), 1e-12*mag(F));
}


TEST(momentumBalance, writesOneLinePerCallInAFileOfItsOwn)
{
    channel ch("momentumBalanceWrite");
    const autoPtr<fvMesh>& mesh = ch.mesh;
    tmp<volVectorField>& tU = ch.tU;
    const tmp<volScalarField>& tp = ch.tp;
    tmp<volVectorField> tl =
        unitTest::zeroField<vector>(*mesh, "lambda", dimAcceleration);
    tU.ref().primitiveFieldRef() = vector(1, 0, 0);
    tl.ref().primitiveFieldRef()[0] = vector(0, 64, 0);
    {
        momentumBalance first(*mesh);
        first.write(tU(), tp(), tl(), nu, vector(0, 1, 0), vector(2, 0, 0));
        momentumBalance second(*mesh);
        second.write(tU(), tp(), tl(), nu, vector(0, 1, 0), vector(3, 0, 0));
    }

    const fileName dir = ch.sc.path()/"postProcessing/momentumBalance/0";
    for (const word f : {"momentumBalance.dat", "momentumBalance_1.dat"})
    {
        IFstream is(dir/f);
        ASSERT_TRUE(is.good()) << f;
        string line;
        do { is.getLine(line); } while (line[0] == '#');
        IStringStream ls(line);
        scalarList v(15);
        scalar time;
        ls >> time;
        for (scalar& x : v) { ls >> x; }
        EXPECT_EQ(time, 0);
        // lambdaV: one cell of volume Delta^3 = 1/64 holding (0 64 0)
        EXPECT_NEAR(v[1], 1, 1e-12);
        EXPECT_NEAR(v[4], 1, 1e-12);
        // pressure -V0 gradP0 (V0 = 1), meanU
        EXPECT_NEAR(v[9], f == "momentumBalance.dat" ? -2 : -3, 1e-12);
        EXPECT_NEAR(v[12], 1, 1e-12);
    }
}
