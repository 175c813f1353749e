// Unit tests for the consistent overlaps of Foam::fdm::couplingStencils
// (couplingStencilsOverlaps.C): two spheres 1.9 apart on a lattice of
// spacing 0.25, their supports (radius 1.075) overlapping, moving with
// different rigid motions

#include "couplingStencilsFixtures.H"
#include "HashSet.H"

#include <gtest/gtest.h>

namespace
{

const scalar alpha = 0.04;

struct overlappingPair
{
    lattice mesh;
    pointField x;
    List<vector> U;
    List<vector> Omega;

    overlappingPair()
    :
        mesh(16, 0.25),
        x({point(1.45, 2.03, 1.96), point(3.35, 2.11, 2.04)}),
        U({vector(1, 0.2, 0), vector(-0.5, 0.3, 0.1)}),
        Omega({vector(0, 0, 0.5), vector(0.2, -0.1, -0.4)})
    {}

    fdm::couplingStencils stencils(const bool consistent) const
    {
        return stencilsOf(mesh, x, 1, false, consistent);
    }

    vector rigid(const label p, const label c) const
    {
        return U[p] + (Omega[p] ^ (mesh.centres[c] - x[p]));
    }

    // The consistent fixed point: u = rigid motion of the one support that
    // covers a cell, the mean of both where they overlap, zero elsewhere
    List<vector> fixedPoint() const
    {
        const labelHashSet one(stencilsOf(mesh, x[0], 1, false).supportCells());
        const labelHashSet two(stencilsOf(mesh, x[1], 1, false).supportCells());
        List<vector> u(mesh.centres.size(), Zero);
        forAll(u, c)
        {
            const bool in0 = one.found(c), in1 = two.found(c);
            if (in0 && in1)
            {
                u[c] = 0.5*(rigid(0, c) + rigid(1, c));
            }
            else if (in0 || in1)
            {
                u[c] = rigid(in0 ? 0 : 1, c);
            }
        }
        return u;
    }

    // The velocity terms of particle p's equation, (pseudo-mass and
    // overlap blocks applied to the rigid motions) minus the velocity
    // integral over alpha: what is left at the fixed point besides the
    // force balance
    vector pseudoForce(const fdm::couplingStencils& s, const label p) const
    {
        const List<vector> lambda(mesh.centres.size(), Zero);
        const auto sums = s.integrals(mesh.V, fixedPoint(), lambda);
        const fdm::rigidBodyMoments m = s.moments(mesh.V)[p];
        vector f = (m.force(U[p], Omega[p]) - sums[p].fu)/alpha;

        const List<labelPair> pairs({labelPair(0, 1)});
        const auto b = s.overlapBlocks(mesh.V, alpha, pairs)[0];
        f +=
            p == 0
          ? (b.forceU & U[1]) + (b.forceOmega & Omega[1])
          : (b.forceU.T() & U[0]) + (b.torqueU.T() & Omega[0]);
        return f;
    }
};

} // namespace


TEST(couplingStencilsOverlaps, withoutOverlapBothFormsAreTheSame)
{
    const lattice mesh(16, 0.25);
    const point x0(2.07, 1.93, 2.11);
    const auto thesis = stencilsOf(mesh, x0, 1, false, false);
    const auto consistent = stencilsOf(mesh, x0, 1, false, true);
    const fdm::rigidBodyMoments a = thesis.moments(mesh.V)[0];
    const fdm::rigidBodyMoments b = consistent.moments(mesh.V)[0];
    EXPECT_EQ(a.volume, b.volume);
    EXPECT_EQ(a.inertia, b.inertia);

    const List<vector> U({vector(1, 0, 0)}), Omega({vector(0, 0, 0.5)});
    List<vector> u(mesh.centres.size(), vector(0.1, 0.2, 0.3));
    List<vector> v(u);
    thesis.correctVelocity(U, Omega, u);
    consistent.correctVelocity(U, Omega, v);
    EXPECT_EQ(u, v);
}


TEST(couplingStencilsOverlaps, velocityCorrectionVanishesAtTheFixedPoint)
{
    const overlappingPair pair;
    const List<vector> fixed(pair.fixedPoint());

    List<vector> u(fixed);
    pair.stencils(true).correctVelocity(pair.U, pair.Omega, u);
    scalar moved = 0;
    forAll(u, c)
    {
        moved = max(moved, mag(u[c] - fixed[c]));
    }
    EXPECT_LT(moved, 1e-14);

    // The thesis form moves the shared cells (each sphere pulls towards
    // its own motion): the reason for the consistent form
    u = fixed;
    pair.stencils(false).correctVelocity(pair.U, pair.Omega, u);
    moved = 0;
    forAll(u, c)
    {
        moved = max(moved, mag(u[c] - fixed[c]));
    }
    EXPECT_GT(moved, 0.05);
}


TEST(couplingStencilsOverlaps, particleEquationIsTheForceBalanceAtTheFixedPoint)
{
    // At the fixed point the velocity terms of each particle's equation
    // cancel, so that the equation is int J_lambda lambda = F whatever
    // alpha; in the thesis form a force of order (1/alpha) x overlap
    // volume x relative velocity is left, unequal and not opposite
    const overlappingPair pair;
    const auto consistent = pair.stencils(true);
    const auto thesis = pair.stencils(false);
    const scalar scale = mag(pair.U[0] - pair.U[1])*pair.mesh.V[0]/alpha;
    for (label p = 0; p < 2; ++p)
    {
        EXPECT_LT(mag(pair.pseudoForce(consistent, p)), 1e-12*scale);
        EXPECT_GT(mag(pair.pseudoForce(thesis, p)), scale);
    }
    EXPECT_GT
    (
        mag(pair.pseudoForce(thesis, 0) + pair.pseudoForce(thesis, 1)),
        0.01*scale
    );
}


TEST(couplingStencilsOverlaps, blocksAndPseudoMassAreTheVelocityEnergy)
{
    // (U, Omega) . M (U, Omega) with the overlap blocks equals
    // (1/alpha) sum over cells of J |ubar|^2 V, with J = 1 - prod (1 - J_u)
    // and ubar = sum J_lambda (U + Omega x r): symmetric, non-negative,
    // computed here cell by cell from the indicator alone
    const overlappingPair pair;
    const auto s = pair.stencils(true);
    const List<fdm::rigidBodyMoments> m(s.moments(pair.mesh.V));
    const auto b =
        s.overlapBlocks(pair.mesh.V, alpha, List<labelPair>({labelPair(0, 1)}))
        [0];
    scalar quadratic = 0;
    for (label p = 0; p < 2; ++p)
    {
        quadratic +=
        (
            (pair.U[p] & m[p].force(pair.U[p], pair.Omega[p]))
          + (pair.Omega[p] & m[p].torque(pair.U[p], pair.Omega[p]))
        )/alpha;
    }
    const vector f01 = (b.forceU & pair.U[1]) + (b.forceOmega & pair.Omega[1]);
    const vector t01 = (b.torqueU & pair.U[1]) + (b.torqueOmega & pair.Omega[1]);
    quadratic += 2*((pair.U[0] & f01) + (pair.Omega[0] & t01));

    const fdm::indicatorFunctions J(5, 0.3, pair.mesh.h);
    scalar energy = 0;
    forAll(pair.mesh.centres, c)
    {
        vector ubar(Zero);
        scalar unmoved = 1;
        label n = 0;
        for (label p = 0; p < 2; ++p)
        {
            const scalar r = mag(pair.mesh.centres[c] - pair.x[p]);
            if (J.inSupport(r, 1))
            {
                ++n;
                unmoved *= 1 - J.Ju(r, 1);
            }
        }
        for (label p = 0; p < 2; ++p)
        {
            if (J.inSupport(mag(pair.mesh.centres[c] - pair.x[p]), 1))
            {
                ubar += pair.rigid(p, c)/n;
            }
        }
        energy += (1 - unmoved)*magSqr(ubar)*pair.mesh.V[c]/alpha;
    }
    EXPECT_NEAR(quadratic, energy, 1e-10*energy);
}
