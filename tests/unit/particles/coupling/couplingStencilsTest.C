// Unit tests for Foam::fdm::couplingStencils (supports, interpolation and
// spreading of the FDM coupling, thesis 1 eq 2.53, and the force dipole of
// eq 2.66) on a lattice of cell centres, without a mesh

#include "couplingStencilsFixtures.H"
#include "HashSet.H"

#include <gtest/gtest.h>

using namespace Foam;


TEST(couplingStencils, imagesCoverThePeriodicNeighbours)
{
    EXPECT_EQ(fdm::couplingStencils::images(box(4, false)).size(), 1);
    const List<fdm::couplingStencils::image> images
    (
        fdm::couplingStencils::images(box(4, true))
    );
    ASSERT_EQ(images.size(), 3);
    EXPECT_EQ(images[0].shift, vector(-4, 0, 0));
    EXPECT_EQ(images[1].shift, vector::zero);
    EXPECT_EQ(images[2].shift, vector(4, 0, 0));
    for (const auto& im : images)
    {
        EXPECT_EQ(im.Ux, 0);
    }
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


namespace
{

// A lattice of 24^3 cells of 0.25 (L = 6), periodic in x and y, sheared by
// the offset s (5 cells) at the shear velocity V; configuration B is
// configuration A moved up by L/2 through the sheared faces
struct shearedPair
{
    const label n = 24, half = 12, sCells = 5;
    const scalar h = 0.25, s = 1.25, V = 0.8;
    lattice mesh{n, h};
    fdm::periodicBox box{point::zero, point(6, 6, 6),
        FixedList<bool, 3>({true, true, false})};
    fdm::pointBins bins{mesh.centres, 4*h};
    fdm::indicatorFunctions J{5, 0.3, h};

    shearedPair()
    {
        box.setShearOffset(s);
        box.setShearVelocity(V);
    }

    label cell(const label i, const label j, const label k) const
    {
        return i + n*(j + n*k);
    }

    // Field B from field A: B's cell (i, j, k) is A's (i, j - half, k), or
    // below the faces A's (i + sCells, j + half, k) one period down, which
    // moves at -V (jump applies to velocities only)
    List<vector> moved(const List<vector>& a, const scalar jump) const
    {
        List<vector> b(a.size());
        for (label k = 0; k < n; ++k)
        for (label j = 0; j < n; ++j)
        for (label i = 0; i < n; ++i)
        {
            b[cell(i, j, k)] =
                j >= half
              ? a[cell(i, j - half, k)]
              : a[cell((i + sCells) % n, j + half, k)] - vector(jump, 0, 0);
        }
        return b;
    }

    fdm::couplingStencils stencils(const pointField& x, const bool consistent)
        const
    {
        fdm::couplingStencils st;
        st.build(mesh.centres, bins, x, scalarField(x.size(), 1.0), J, box,
            consistent);
        return st;
    }
};

// A smooth field on the cells
List<vector> smoothField(const pointField& x)
{
    List<vector> u(x.size());
    forAll(x, c)
    {
        u[c] = vector(std::sin(x[c].y()), 0.3*std::cos(x[c].x()), 0.1*x[c].z());
    }
    return u;
}

// The force and torque residuals of the two particles' equations (eq 2.53,
// alpha_lambda = 1, no lambda): the velocity integrals less the pseudo-mass
// of each one's motion and, through a consistent overlap, of the other's
List<Pair<vector>> equations
(
    const shearedPair& c,
    const fdm::couplingStencils& st,
    const List<fdm::couplingStencils::supportIntegrals>& sums,
    const List<vector>& U,
    const List<vector>& Omega
)
{
    const auto m = st.moments(c.mesh.V);
    const auto b =
        st.overlapBlocks(c.mesh.V, 1, List<labelPair>({labelPair(0, 1)}))[0];
    List<Pair<vector>> eq(2);
    forAll(eq, p)
    {
        eq[p].first() = sums[p].fu - m[p].force(U[p], Omega[p]);
        eq[p].second() = sums[p].tu - m[p].torque(U[p], Omega[p]);
    }
    eq[0].first() -= (b.forceU & U[1]) + (b.forceOmega & Omega[1]);
    eq[0].second() -= (b.torqueU & U[1]) + (b.torqueOmega & Omega[1]);
    eq[1].first() -= (U[0] & b.forceU) + (Omega[0] & b.torqueU);
    eq[1].second() -= (U[0] & b.forceOmega) + (Omega[0] & b.torqueOmega);
    return eq;
}

} // namespace


TEST(couplingStencils, leesEdwardsKernelsDoNotSeeTheShearedFaces)
{
    // Two spheres with overlapping supports, first away from the sheared
    // faces (A), then moved up by L/2 so that both reach across them and
    // overlap there (B):
    // each particle's equation (velocity integral less the pseudo-mass of
    // its motion, lambda integrals) and the corrected fields are the same
    const shearedPair c;
    const pointField xA({point(2.9, 2.6, 3.0), point(3.2, 3.4, 3.1)});
    const List<vector> UA({vector(0.2, 0.1, 0), vector(-0.3, 0, 0.1)});
    const List<vector> Omega({vector(0, 0, -0.4), vector(0.1, 0, 0.3)});
    pointField xB(xA.size());
    List<vector> UB(UA.size());
    forAll(xA, p)
    {
        const point up = xA[p] + vector(0, 3, 0);
        UB[p] = c.box.wrapVelocity(up, UA[p]);
        xB[p] = c.box.wrap(up);
    }
    ASSERT_GT(xB[0].y() + 1, 6);
    ASSERT_LT(xB[1].y() - 1, 0);

    const List<vector> uA(smoothField(c.mesh.centres));
    const List<vector> lA(smoothField(c.mesh.centres + vector(1, 2, 3)));
    const List<vector> uB(c.moved(uA, c.V)), lB(c.moved(lA, 0));
    for (const bool consistent : {false, true})
    {
        const fdm::couplingStencils sA(c.stencils(xA, consistent));
        const fdm::couplingStencils sB(c.stencils(xB, consistent));
        const auto iA = sA.integrals(c.mesh.V, uA, lA);
        const auto iB = sB.integrals(c.mesh.V, uB, lB);
        const auto eqA = equations(c, sA, iA, UA, Omega);
        const auto eqB = equations(c, sB, iB, UB, Omega);
        forAll(xA, p)
        {
            EXPECT_LT(mag(eqA[p].first() - eqB[p].first()),
                1e-12*mag(iA[p].fu)) << consistent;
            EXPECT_LT(mag(eqA[p].second() - eqB[p].second()),
                1e-12*mag(iA[p].tu)) << consistent;
            EXPECT_LT(mag(iA[p].fl - iB[p].fl), 1e-12*mag(iA[p].fl));
            EXPECT_LT(mag(iA[p].tl - iB[p].tl), 1e-12*mag(iA[p].tl));
        }

        List<vector> cuA(uA), cuB(uB), clA(lA), clB(lB);
        sA.correctLambda(UA, Omega, 0.5, cuA, clA);
        sB.correctLambda(UB, Omega, 0.5, cuB, clB);
        sA.correctVelocity(UA, Omega, cuA);
        sB.correctVelocity(UB, Omega, cuB);
        const List<vector> expectU(c.moved(cuA, c.V)), expectL(c.moved(clA, 0));
        scalar worst = 0;
        forAll(cuB, k)
        {
            worst = max(worst, mag(cuB[k] - expectU[k]));
            worst = max(worst, mag(clB[k] - expectL[k]));
        }
        EXPECT_LT(worst, 1e-13) << consistent;
    }
}
