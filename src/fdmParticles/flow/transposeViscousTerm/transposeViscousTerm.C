/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "transposeViscousTerm.H"
#include "fvc.H"
#include "extrapolatedCalculatedFvPatchFields.H"
#include "gaussGrad.H"
#include "schemeEntries.H"
#include "shareLeesEdwardsCoupling.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The names fvc::grad and fvc::div give the term's parts, which fvSchemes
// looks up
const Foam::word gradName("grad(U)");
const Foam::word divName("div((nu*dev(T(grad(U)))))");


//- The Gauss linear gradient of U as fvc::grad computes it (linear face
//  values summed into the cells as they are interpolated, in the order
//  and arithmetic of surfaceInterpolationScheme::interpolate and
//  gaussGrad::gradf, the same boundary correction)
Foam::tmp<Foam::volTensorField> gaussLinearGrad(const Foam::volVectorField& U)
{
    using namespace Foam;
    const fvMesh& mesh = U.mesh();
    tmp<volTensorField> tGrad
    (
        new volTensorField
        (
            IOobject
            (
                gradName,
                U.instance(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            mesh,
            dimensionedTensor(U.dimensions()/dimLength, Zero),
            extrapolatedCalculatedFvPatchTensorField::typeName
        )
    );
    volTensorField& G = tGrad.ref();
    fdm::shareLeesEdwardsCoupling(G, U);
    tensorField& g = G.primitiveFieldRef();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const vectorField& Sf = mesh.Sf();
    const scalarField& w = mesh.weights();
    const vectorField& u = U.primitiveField();

    forAll(own, f)
    {
        const tensor Sfu = Sf[f]*(w[f]*(u[own[f]] - u[nei[f]]) + u[nei[f]]);
        g[own[f]] += Sfu;
        g[nei[f]] -= Sfu;
    }
    forAll(mesh.boundary(), patchi)
    {
        const fvPatchVectorField& pU = U.boundaryField()[patchi];
        const vectorField& pSf = mesh.Sf().boundaryField()[patchi];
        const labelUList& cells = mesh.boundary()[patchi].faceCells();
        if (pU.coupled())
        {
            const scalarField& pw = mesh.weights().boundaryField()[patchi];
            const vectorField inside(pU.patchInternalField());
            const vectorField across(pU.patchNeighbourField());
            forAll(cells, i)
            {
                g[cells[i]] +=
                    pSf[i]*(pw[i]*inside[i] + (1.0 - pw[i])*across[i]);
            }
        }
        else
        {
            forAll(cells, i)
            {
                g[cells[i]] += pSf[i]*pU[i];
            }
        }
    }
    g /= mesh.V();
    G.correctBoundaryConditions();
    fv::gaussGrad<vector>::correctBoundaryConditions(U, G);
    return tGrad;
}


//- nu dev(T(g)) in place, cells and patch values
void formStress(const Foam::scalar nu, Foam::volTensorField& g)
{
    for (Foam::tensor& t : g.primitiveFieldRef())
    {
        t = nu*Foam::dev(t.T());
    }
    for (Foam::fvPatchTensorField& pg : g.boundaryFieldRef())
    {
        for (Foam::tensor& t : pg)
        {
            t = nu*Foam::dev(t.T());
        }
    }
}


//- Sum over the faces of S_f & (linear face value of s), per cell, in the
//  order and arithmetic of surfaceInterpolationScheme::dotInterpolate and
//  fvc::surfaceIntegrate
void sumFaceFluxes(const Foam::volTensorField& s, Foam::vectorField& d)
{
    const Foam::fvMesh& mesh = s.mesh();
    const Foam::labelUList& own = mesh.owner();
    const Foam::labelUList& nei = mesh.neighbour();
    const Foam::vectorField& Sf = mesh.Sf();
    const Foam::scalarField& w = mesh.weights();
    const Foam::tensorField& si = s.primitiveField();

    forAll(own, f)
    {
        const Foam::vector flux =
            Sf[f] & (w[f]*(si[own[f]] - si[nei[f]]) + si[nei[f]]);
        d[own[f]] += flux;
        d[nei[f]] -= flux;
    }

    forAll(mesh.boundary(), patchi)
    {
        const Foam::fvPatchTensorField& ps = s.boundaryField()[patchi];
        const Foam::vectorField& pSf = mesh.Sf().boundaryField()[patchi];
        const Foam::labelUList& cells = mesh.boundary()[patchi].faceCells();
        if (ps.coupled())
        {
            const Foam::scalarField& pw = mesh.weights().boundaryField()[patchi];
            const Foam::tensorField inside(ps.patchInternalField());
            const Foam::tensorField across(ps.patchNeighbourField());
            forAll(cells, i)
            {
                d[cells[i]] +=
                    pSf[i] & (pw[i]*inside[i] + (1.0 - pw[i])*across[i]);
            }
        }
        else
        {
            forAll(cells, i)
            {
                d[cells[i]] += pSf[i] & ps[i];
            }
        }
    }
    d /= mesh.V();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::fdm::transposeViscousTermIsLinear(const fvMesh& mesh)
{
    return
        isGaussLinear(mesh.gradScheme(gradName))
     && isGaussLinear(mesh.divScheme(divName));
}


Foam::tmp<Foam::volVectorField> Foam::fdm::transposeViscousTerm
(
    const dimensionedScalar& nu,
    const volVectorField& U
)
{
    const fvMesh& mesh = U.mesh();
    if (!transposeViscousTermIsLinear(mesh))
    {
        return fvc::div
        (
            fdm::shareLeesEdwardsCoupling(nu*dev(T(fvc::grad(U))), U)
        );
    }

    tmp<volTensorField> tStress(gaussLinearGrad(U));
    formStress(nu.value(), tStress.ref());

    tmp<volVectorField> tTerm
    (
        new volVectorField
        (
            IOobject
            (
                divName,
                U.instance(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            mesh,
            dimensionedVector(nu.dimensions()*U.dimensions()/dimArea, Zero),
            extrapolatedCalculatedFvPatchVectorField::typeName
        )
    );
    sumFaceFluxes(tStress(), tTerm.ref().primitiveFieldRef());
    tTerm.ref().correctBoundaryConditions();
    return tTerm;
}


// ************************************************************************* //
