/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "layerMeanCorrection.H"
#include "layerDiffusion.H"
#include "planeWalls.H"
#include "sumOverRanks.H"
#include "fvcFlux.H"
#include "coupledPolyPatch.H"
#include "fixedValueFvPatchFields.H"

#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::layerMeanCorrection::findWalls(const string& user)
{
    const planeWalls walls(mesh_, user);
    label nUncoupled = 0;
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if
        (
            !isA<coupledPolyPatch>(pp)
         && returnReduce(pp.size(), sumOp<label>()) > 0
        )
        {
            ++nUncoupled;
        }
    }

    bool channel = walls.size() == 2 && nUncoupled == 2;
    if (channel)
    {
        const vector n = walls.walls()[0].normal;
        normal_ = findMax(cmptMag(n));
        channel =
            mag(mag(n[normal_]) - 1) < 1e-9
         && mag((walls.walls()[1].normal & n) + 1) < 1e-9;
    }
    if (!channel)
    {
        FatalErrorInFunction
            << user.c_str() << " needs a channel: two plane walls normal to"
            << " one coordinate axis and coupled (cyclic or processor)"
            << " patches elsewhere; this mesh has " << walls.size()
            << " wall patch(es) and " << nUncoupled << " uncoupled patch(es)."
            << nl << "    Switch it off for this case." << exit(FatalError);
    }
    const scalar a = walls.walls()[0].origin[normal_];
    const scalar b = walls.walls()[1].origin[normal_];
    low_ = min(a, b);
    high_ = max(a, b);
}


namespace Foam
{
namespace
{

// The distinct values of a list, ascending, merged within tol
scalarList distinctSorted(scalarList values, const scalar tol)
{
    std::sort(values.begin(), values.end());
    DynamicList<scalar> distinct(values.size());
    for (const scalar v : values)
    {
        if (distinct.empty() || v - distinct.last() > tol)
        {
            distinct.append(v);
        }
    }
    return scalarList(std::move(distinct));
}

} // namespace
} // namespace Foam


void Foam::layerMeanCorrection::findLayers()
{
    // Distinct centre coordinates of all ranks (each rank sends its own
    // distinct ones, a layer count rather than a cell count)
    const scalar tol = 1e-8*(high_ - low_);
    const scalarField y(mesh_.C().primitiveField().component(normal_));
    List<scalarList> perRank(Pstream::nProcs());
    perRank[Pstream::myProcNo()] = distinctSorted(y, tol);
    Pstream::gatherList(perRank);
    Pstream::scatterList(perRank);
    DynamicList<scalar> all;
    for (const scalarList& l : perRank)
    {
        all.append(l);
    }
    layerCentre_ = distinctSorted(all, tol);

    layerOfCell_.setSize(y.size());
    layerVolume_ = List<scalar>(nLayers(), Zero);
    forAll(y, c)
    {
        const scalar* k = std::lower_bound
        (
            layerCentre_.cdata(), layerCentre_.cdata() + nLayers(), y[c] - tol
        );
        layerOfCell_[c] = k - layerCentre_.cdata();
        layerVolume_[layerOfCell_[c]] += mesh_.V()[c];
    }
    fdm::sumOverRanks(layerVolume_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::layerMeanCorrection::layerMeanCorrection
(
    const fvMesh& mesh,
    const string& user
)
:
    mesh_(mesh),
    normal_(0),
    low_(0),
    high_(0)
{
    findWalls(user);
    findLayers();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::layerMeanCorrection::correct
(
    const vectorField& residual,
    const scalar nu,
    volVectorField& U,
    surfaceScalarField& phi
) const
{
    // Layer means of the residual, all three components at once
    const label n = nLayers();
    List<scalar> sums(3*n, Zero);
    const scalarField& V = mesh_.V();
    forAll(layerOfCell_, c)
    {
        const label k = layerOfCell_[c];
        for (direction d = 0; d < 3; ++d)
        {
            sums[3*k + d] += residual[c][d]*V[c];
        }
    }
    fdm::sumOverRanks(sums);

    // delta: coupled patches as U's, zero on the walls
    wordList patchTypes(U.boundaryField().types());
    forAll(patchTypes, patchi)
    {
        if (!U.boundaryField()[patchi].coupled())
        {
            patchTypes[patchi] = fixedValueFvPatchVectorField::typeName;
        }
    }
    volVectorField delta
    (
        IOobject("layerMeanCorrection", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector(U.dimensions(), Zero),
        patchTypes
    );
    vectorField& dU = delta.primitiveFieldRef();
    for (direction d = 0; d < 3; ++d)
    {
        if (d == normal_)
        {
            continue;
        }
        scalarField r(n);
        forAll(r, k)
        {
            r[k] = sums[3*k + d]/layerVolume_[k];
        }
        const scalarField shift =
            fdm::solveLayerDiffusion(layerCentre_, low_, high_, nu, r);
        forAll(dU, c)
        {
            dU[c][d] = shift[layerOfCell_[c]];
        }
    }
    delta.correctBoundaryConditions();

    phi += fvc::flux(delta);
    U.primitiveFieldRef() += dU;
    U.correctBoundaryConditions();
}


// ************************************************************************* //
