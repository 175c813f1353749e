/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "planeWalls.H"
#include "wallPolyPatch.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::planeWalls::planeWalls
(
    const fvMesh& mesh,
    const string& user,
    const bool planeOnly
)
:
    mesh_(mesh),
    nOther_(0)
{
    DynamicList<wall> walls;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        const label nFaces = returnReduce(pp.size(), sumOp<label>());
        if (!isA<wallPolyPatch>(pp) || nFaces == 0)
        {
            continue;
        }
        const vectorField nf(pp.faceNormals());
        const vector n = normalised(gSum(nf));
        // Plane: one normal and all face centres on one plane (gMax of an
        // empty local list is -GREAT: ranks without faces do not count)
        const scalar bend = gMax(mag(nf - n));
        const point origin = gSum(pp.faceCentres())/nFaces;
        const scalar offPlane = gMax(mag((pp.faceCentres() - origin) & n));
        const bool plane =
            bend <= 1e-6 && offPlane <= 1e-6*cbrt(gSum(mesh.V()));
        if (!plane && !planeOnly)
        {
            ++nOther_;
            continue;
        }
        if (!plane)
        {
            FatalErrorInFunction
                << "Wall patch " << pp.name() << " is not a plane: the "
                << user.c_str() << " supports plane walls only"
                << exit(FatalError);
        }
        walls.append(wall{pp.name(), n, origin, pp.index()});
    }
    walls_.transfer(walls);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::planeWalls::velocity(const wall& w) const
{
    const volVectorField& U = mesh_.lookupObject<volVectorField>("U");
    const scalarField& magSf = mesh_.boundary()[w.patch].magSf();
    const vectorField& Ub = U.boundaryField()[w.patch];
    return gSum(Ub*magSf)/gSum(magSf);
}


Foam::scalar Foam::planeWalls::shearRate() const
{
    if (walls_.size() != 2 || nOther_ > 0)
    {
        return 0;
    }
    const scalar gap = mag(walls_[1].distance(walls_[0].origin));
    return mag(velocity(walls_[0]) - velocity(walls_[1]))/max(gap, VSMALL);
}


// ************************************************************************* //
