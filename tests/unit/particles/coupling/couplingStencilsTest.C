// Unit tests for Foam::fdm::couplingStencils (supports, interpolation and
// spreading of the FDM coupling, thesis 1 eq 2.53, and the force dipole of
// eq 2.66) on a lattice of cell centres, without a mesh

#include "couplingStencilsFixtures.H"
#include "HashSet.H"

#include <gtest/gtest.h>

using namespace Foam;


TEST(couplingStencils, imageShiftsCoverThePeriodicNeighbours)
{
    EXPECT_EQ(fdm::couplingStencils::imageShifts(box(4, false)).size(), 1);
    const List<vector> shifts(fdm::couplingStencils::imageShifts(box(4, true)));
    ASSERT_EQ(shifts.size(), 3);
    EXPECT_EQ(shifts[0], vector(-4, 0, 0));
    EXPECT_EQ(shifts[1], vector::zero);
    EXPECT_EQ(shifts[2], vector(4, 0, 0));
}


TEST(couplingStencils, supportHoldsExactlyTheCellsWithinReach)
{
    const lattice mesh(16, 0.25);
    const point x0(2.1, 1.9, 2.05);
    const fdm::couplingStencils s(stencilsOf(mesh, x0, 1, false));

    const scalar R = 1 + 0.3*mesh.h;
    label expected = 0;
    for (const point& c : mesh.centres)
    {
        expected += mag(c - x0) <= R;
    }
    EXPECT_EQ(s.size(), 1);
    EXPECT_EQ(s.supportCells().size(), expected);
    for (const label c : s.supportCells())
    {
        EXPECT_LE(mag(mesh.centres[c] - x0), R);
    }
}


TEST(couplingStencils, periodicImageReachesAcrossTheBoundary)
{
    // A sphere at x = 0.3 in a box periodic in x covers cells near x = 4
    // with offsets measured from its image at x = 4.3
    const lattice mesh(16, 0.25);
    const point x0(0.3, 2, 2);
    const fdm::couplingStencils s(stencilsOf(mesh, x0, 1, true));
    const fdm::couplingStencils walled(stencilsOf(mesh, x0, 1, false));

    label across = 0;
    for (const label c : s.supportCells())
    {
        across += mesh.centres[c].x() > 3;
    }
    EXPECT_GT(across, 0);
    EXPECT_EQ(s.supportCells().size(), walled.supportCells().size() + across);

    // Moments about the image centre: a centred sphere has no first moment
    // beyond the lattice's off-centring, like the same sphere away from
    // the boundary
    const fdm::rigidBodyMoments m = s.moments(mesh.V)[0];
    const fdm::rigidBodyMoments inside =
        stencilsOf(mesh, point(2.3, 2, 2), 1, false).moments(mesh.V)[0];
    EXPECT_NEAR(m.volume, inside.volume, 1e-12);
    EXPECT_NEAR(mag(m.firstMoment - inside.firstMoment), 0, 1e-12);
}


TEST(couplingStencils, overlappingSupportsShareLambda)
{
    // Two spheres 1.9 apart: their supports (radius 1.075) overlap.  The
    // shared J_lambda integrates lambda = 1 over the union exactly once.
    const lattice mesh(16, 0.25);
    pointField x(2);
    x[0] = point(1.45, 2, 2);
    x[1] = point(3.4, 2, 2);
    const fdm::couplingStencils s(stencilsOf(mesh, x, 1, false));
    const fdm::couplingStencils one(stencilsOf(mesh, x[0], 1, false));
    const fdm::couplingStencils two(stencilsOf(mesh, x[1], 1, false));

    const label shared =
        one.supportCells().size() + two.supportCells().size()
      - s.supportCells().size();
    EXPECT_GT(shared, 0);

    const List<vector> u(mesh.centres.size(), Zero);
    const List<vector> lambda(mesh.centres.size(), vector(1, 0, 0));
    const auto sums = s.integrals(mesh.V, u, lambda);
    const scalar total = sums[0].fl.x() + sums[1].fl.x();
    EXPECT_NEAR(total, s.supportCells().size()*mesh.V[0], 1e-12);
    const scalar alone = one.integrals(mesh.V, u, lambda)[0].fl.x();
    EXPECT_NEAR(sums[0].fl.x(), alone - 0.5*shared*mesh.V[0], 1e-12);
}


TEST(couplingStencils, integralsOfARigidMotionAreThePseudoMass)
{
    // J_u u and J_u r x u of u = U + Omega x r are the pseudo-mass applied
    // to (U, Omega) (eq 2.53), whatever the lattice's off-centring
    const lattice mesh(16, 0.25);
    const point x0(2.07, 1.93, 2.11);
    const fdm::couplingStencils s(stencilsOf(mesh, x0, 1, false));
    const vector U(0.3, -1.2, 0.7);
    const vector Omega(-0.4, 0.9, 0.25);

    const List<vector> u(rigidField(mesh.centres, x0, U, Omega));
    const List<vector> lambda(mesh.centres.size(), Zero);
    const auto sums = s.integrals(mesh.V, u, lambda);
    const fdm::rigidBodyMoments m = s.moments(mesh.V)[0];

    EXPECT_LT(mag(sums[0].fu - m.force(U, Omega)), 1e-12*mag(sums[0].fu));
    EXPECT_LT(mag(sums[0].tu - m.torque(U, Omega)), 1e-12*mag(sums[0].tu));
    EXPECT_EQ(sums[0].fl, vector::zero);
}


TEST(couplingStencils, correctionsMoveTowardsTheRigidMotion)
{
    const lattice mesh(16, 0.25);
    const point x0(2.07, 1.93, 2.11);
    const fdm::couplingStencils s(stencilsOf(mesh, x0, 1, false));
    const List<vector> U({vector(1, 0, 0)});
    const List<vector> Omega({vector(0, 0, 0.5)});
    const List<vector> rigid
    (
        rigidField(mesh.centres, x0, U[0], Omega[0])
    );

    // A field that is already rigid is left alone
    List<vector> u(rigid);
    s.correctVelocity(U, Omega, u);
    forAll(u, c)
    {
        EXPECT_LT(mag(u[c] - rigid[c]), 1e-15);
    }

    // From rest: u = J_u (U + Omega x r) and lambda = (U + Omega x r)/alpha
    // on the support, untouched elsewhere
    const scalar alpha = 0.5;
    const fdm::indicatorFunctions J(5, 0.3, mesh.h);
    List<vector> rest(mesh.centres.size(), Zero);
    List<vector> lambda(mesh.centres.size(), vector(0, 7, 0));
    for (const label c : s.supportCells())
    {
        lambda[c] = Zero;
    }
    s.correctLambda(U, Omega, alpha, rest, lambda);
    s.correctVelocity(U, Omega, rest);
    const labelHashSet inSupport(s.supportCells());
    forAll(rest, c)
    {
        if (inSupport.found(c))
        {
            const scalar Ju = J.Ju(mag(mesh.centres[c] - x0), 1);
            EXPECT_LT(mag(rest[c] - Ju*rigid[c]), 1e-14);
            EXPECT_LT(mag(lambda[c] - rigid[c]/alpha), 1e-14);
        }
        else
        {
            EXPECT_EQ(rest[c], vector::zero);
            EXPECT_EQ(lambda[c], vector(0, 7, 0));
        }
    }
}


TEST(couplingStencils, dipoleIntegralsOfUniformFields)
{
    // lambda = e_x and p - pMean = 2: force V_s e_x, moment V_s e_x (x)
    // first moment of the support cells, pressure 2 times the J_u volume
    const lattice mesh(16, 0.25);
    const point x0(2.07, 1.93, 2.11);
    const fdm::couplingStencils s(stencilsOf(mesh, x0, 1, false));
    const List<vector> lambda(mesh.centres.size(), vector(1, 0, 0));
    const scalarField p(mesh.centres.size(), 3);

    const auto d = s.dipoles(mesh.V, lambda, p, 1)[0];
    vector first(Zero);
    for (const label c : s.supportCells())
    {
        first += mesh.V[c]*(mesh.centres[c] - x0);
    }
    const scalar Vs = s.supportCells().size()*mesh.V[0];
    EXPECT_NEAR(d.force.x(), Vs, 1e-12);
    EXPECT_NEAR(mag(d.moment - vector(1, 0, 0)*first), 0, 1e-12);
    EXPECT_NEAR(d.pressure, 2*s.moments(mesh.V)[0].volume, 1e-12);
}


// ************************************************************************* //
