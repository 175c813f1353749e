/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "momentumBalance.H"
#include "fvc.H"
#include "OSspecific.H"
#include "freshOutputFile.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::momentumBalance::momentumBalance(const fvMesh& mesh)
:
    mesh_(mesh)
{
    if (Pstream::master())
    {
        const fileName dir =
            mesh.time().globalPath()/"postProcessing"/"momentumBalance"
           /mesh.time().timeName();
        mkDir(dir);
        file_.reset
        (
            new OFstream(fdm::freshOutputFile(dir, "momentumBalance"))
        );
        file_().precision(12);
        file_()
            << "# Mechanical consistency (thesis 1, eqs 4.14-4.16), per unit"
            << " fluid density" << nl
            << "# time lambdaV(3) lambdaParts(3) wall(3) pressure(3)"
            << " meanU(3)" << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::momentumBalance::wallForce
(
    const volVectorField& U,
    const volScalarField& p,
    const scalar nu
)
{
    const fvMesh& mesh = U.mesh();
    const volTensorField devT(nu*dev(T(fvc::grad(U))));

    vector F(Zero);
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        if (patch.coupled() || patch.size() == 0)
        {
            continue;
        }
        const vectorField& Sf = patch.Sf();
        const scalarField& magSf = patch.magSf();
        const vectorField viscous
        (
            nu*U.boundaryField()[patchi].snGrad()*magSf
          + (Sf & devT.boundaryField()[patchi])
        );
        F += sum(viscous - p.boundaryField()[patchi]*Sf);
    }
    return returnReduce(F, sumOp<vector>());
}


void Foam::momentumBalance::write
(
    const volVectorField& U,
    const volScalarField& p,
    const volVectorField& lambda,
    const scalar nu,
    const vector& lambdaParts,
    const vector& gradP0
)
{
    const vector lambdaV = gSum(lambda.primitiveField()*mesh_.V());
    const vector wall = wallForce(U, p, nu);
    const scalar V0 = gSum(mesh_.V());
    const vector pressure = -V0*gradP0;
    const vector meanU = gSum(U.primitiveField()*mesh_.V())/V0;

    if (file_.valid())
    {
        OFstream& os = file_();
        os  << mesh_.time().timeName();
        for (const vector& v : {lambdaV, lambdaParts, wall, pressure, meanU})
        {
            os  << ' ' << v.x() << ' ' << v.y() << ' ' << v.z();
        }
        os  << endl;
    }
}


// ************************************************************************* //
