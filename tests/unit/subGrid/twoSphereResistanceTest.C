// Unit tests for Foam::fdm::twoSphereResistance: the two-body
// hydrodynamics of a pair from data/resistance/twoBody_lambda1 against the
// exact two-sphere motion (Batchelor & Green 1972 functions A, B, golden
// values of fdmResistance.pairShear), Lorentz reciprocity, relabelling and
// the squeeze term of the lubricated contact (thesis 2, article 1, eq 4)

#include "twoSphereResistance.H"
#include "mathematicalConstants.H"
#include "point.H"
#include "DynamicList.H"
#include "unitTestHelpers.H"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>
#include <string>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

const label n = 12;
typedef Eigen::Matrix<double, n, n> matrix;
typedef Eigen::Matrix<double, n, 1> column;

fdm::twoSphereResistance twoBody(const scalar xMin = 1e-6)
{
    return fdm::twoSphereResistance
    (
        fdm::twoSphereResistance::defaultTable(), 1, xMin
    );
}

// Simple shear u = y e_x: E and the unit velocities
const symmTensor shearE(0, 0.5, 0, 0, 0, 0);

// Loads (F1, T1, F2, T2) for the velocities x = (U1, W1, U2, W2)
column loadsOf
(
    const fdm::twoSphereResistance& law,
    const vector& d,
    const scalar gap,
    const column& x,
    const symmTensor& E,
    const scalar a2 = 1
)
{
    auto v = [&x](const label k) { return vector(x[k], x[k+1], x[k+2]); };
    const fdm::twoSphereLoads l =
        law.loads(d, gap, 1, a2, v(0), v(3), v(6), v(9), E, true);
    const vector out[4] = {l.force[0], l.torque[0], l.force[1], l.torque[1]};
    column c;
    for (label k = 0; k < n; ++k)
    {
        c[k] = out[k/3][k % 3];
    }
    return c;
}

// -dLoads/dx by probing (the loads are linear in the velocities)
matrix resistanceOf
(
    const fdm::twoSphereResistance& law,
    const vector& d,
    const scalar gap,
    const scalar a2 = 1
)
{
    matrix R;
    for (label j = 0; j < n; ++j)
    {
        const column c = loadsOf
        (
            law, d, gap, column::Unit(j), symmTensor::zero, a2
        );
        R.col(j) = -c;
    }
    return R;
}

// Relative velocity of two free equal spheres (a = 1) in simple shear,
// minus the ambient relative velocity E.r + W x r: the isolated drag and
// torque plus the two-body law, force- and torque-free
vector relativeDisturbance
(
    const fdm::twoSphereResistance& law,
    const vector& r
)
{
    const vector d = r/mag(r);
    matrix R = resistanceOf(law, d, mag(r) - 2);
    for (label k = 0; k < n; ++k)
    {
        R(k, k) += (k % 6) < 3 ? 6*pi : 8*pi;
    }
    const column strain =
        loadsOf(law, d, mag(r) - 2, column::Zero(), shearE);
    const column x = R.partialPivLu().solve(strain);
    return vector(x[6] - x[0], x[7] - x[1], x[8] - x[2]);
}

} // namespace


TEST(twoSphereResistance, freePairInShearFollowsBatchelorGreen)
{
    // V = W x r + E.r - [A dd + B (I - dd)].E.r: A from r along (1, 1, 0)
    // (E.r parallel to r), B from r along x (E.r normal to r).  Golden A,
    // B from the direct 12 x 12 solve of fdmResistance.pairShear; the
    // table's interpolation error is below 5e-5 of the isolated scale
    const scalar golden[][3] =
    {
        {1e-3, 0.9959597348, 0.2905809418},
        {1e-2, 0.9619459294, 0.2460805824},
        {0.1,  0.7324359922, 0.1555506598},
        {1.0,  0.1866626359, 0.0222799832},
        {3.0,  0.0390057918, 0.0017138181}
    };
    const fdm::twoSphereResistance law(twoBody());
    for (const auto& g : golden)
    {
        const scalar r = 2 + g[0];
        const vector dA = vector(1, 1, 0)/std::sqrt(2.0);
        const vector rA = r*dA;
        const scalar A = -(relativeDisturbance(law, rA) & dA)
                        /((shearE & rA) & dA);
        const vector rB(r, 0, 0);
        const vector e = shearE & rB;
        const scalar B = -(relativeDisturbance(law, rB) & e)/(e & e);
        EXPECT_NEAR(A, g[1], 2e-4*(1 - g[1]) + 1e-6) << "xi " << g[0];
        EXPECT_NEAR(B, g[2], 2e-4) << "xi " << g[0];
    }
}


TEST(twoSphereResistance, resistanceIsSymmetricAndRelabels)
{
    const fdm::twoSphereResistance law(twoBody());
    const vector d = vector(0.3, -0.5, 0.8)/mag(vector(0.3, -0.5, 0.8));
    for (const scalar gap : {1e-4, 0.05, 0.7, 4.0})
    {
        // Lorentz reciprocity: the B~, G~ columns from the B, G rows
        const matrix R = resistanceOf(law, d, gap);
        for (label i = 0; i < n; ++i)
        {
            for (label j = 0; j < i; ++j)
            {
                EXPECT_NEAR(R(i, j), R(j, i), 1e-10*(1 + std::abs(R(i, j))))
                    << "gap " << gap << " entry " << i << ' ' << j;
            }
        }

        // Relabelling: the same pair seen from sphere 2 (d reversed)
        column x;
        for (label k = 0; k < n; ++k) x[k] = std::sin(1.0 + 3*k);
        column swapped;
        for (label k = 0; k < 6; ++k)
        {
            swapped[k] = x[k + 6];
            swapped[k + 6] = x[k];
        }
        const column c = loadsOf(law, d, gap, x, shearE);
        const column s = loadsOf(law, -d, gap, swapped, shearE);
        for (label k = 0; k < 6; ++k)
        {
            EXPECT_NEAR(c[k], s[k + 6], 1e-10*(1 + std::abs(c[k])));
            EXPECT_NEAR(c[k + 6], s[k], 1e-10*(1 + std::abs(c[k])));
        }
    }
}


TEST(twoSphereResistance, squeezeTermIsTheLubricatedContactsForm)
{
    // withSqueeze false leaves out 3/2 pi eta a*^2/u_n times the whole
    // relative normal velocity, ambient strain included (thesis 2,
    // article 1, eq 4 for equal spheres), a* = 2 a1 a2/(a1 + a2)
    const fdm::twoSphereResistance law(twoBody());
    const vector d = vector(1, 2, 0)/std::sqrt(5.0);
    const vector v(0.2, -0.7, 0.1);
    for (const scalar a2 : {1.0, 1.1})
    {
        for (const scalar un : {3e-3, 2.0})
        {
            const fdm::twoSphereLoads full = law.loads
            (
                d, un, 1, a2, Zero, Zero, v, Zero, shearE, true
            );
            const fdm::twoSphereLoads regular = law.loads
            (
                d, un, 1, a2, Zero, Zero, v, Zero, shearE, false
            );
            const scalar aStar = 2*a2/(1 + a2);
            const vector r = (1 + a2 + un)*d;
            const vector squeeze =
                1.5*pi*sqr(aStar)/un*((v + (shearE & r)) & d)*d;
            for (label i = 0; i < 2; ++i)
            {
                const vector diff = full.force[i] - regular.force[i];
                EXPECT_LT(mag(diff - (i == 0 ? squeeze : -squeeze)),
                    1e-9*mag(squeeze)) << "a2 " << a2 << " gap " << un;
                EXPECT_LT(mag(full.torque[i] - regular.torque[i]), 1e-12);
                EXPECT_LT
                (
                    mag
                    (
                        full.translationDamping[i]
                      - regular.translationDamping[i]
                      - 1.5*pi*sqr(aStar)/un*sqr(d)
                    ),
                    1e-9*1.5*pi*sqr(aStar)/un
                );
            }
        }
    }
}


TEST(twoSphereResistance, rejectsOtherTables)
{
    const std::string msg = unitTest::errorOf([]()
    {
        const dictionary dict(unitTest::parse
        (
            "kind pair; lambda 1; gapVariable xi; gap (0 0.5);"
            " functions { XA21 { singular (1 0 0); remainder (0 0); }"
            " YA21 { singular (1 0 0); remainder (0 0); }"
            " YB21 { singular (1 0 0); remainder (0 0); }"
            " XC21 { singular (1 0 0); remainder (0 0); }"
            " YC11 { singular (1 0 0); remainder (0 0); }"
            " XG11 { singular (1 0 0); remainder (0 0); }"
            " YG11 { singular (1 0 0); remainder (0 0); }"
            " YH21 { singular (1 0 0); remainder (0 0); }"
            " XP12 { singular (1 0 0); remainder (0 0); }"
            " XP21 { singular (1 0 0); remainder (0 0); } }"
        ));
        fdm::twoSphereResistance law(fdm::resistanceTable(dict), 1);
    });
    EXPECT_NE(msg.find("is not a twoBody table"), std::string::npos) << msg;
}


TEST(twoSphereResistance, commonTranslationIsProjectedOut)
{
    // Spheres moving together feel no two-body load, and the forces on
    // the two are opposite whatever the motion (see Description)
    const fdm::twoSphereResistance law(twoBody());
    const vector d = vector(0.2, 0.9, -0.4)/mag(vector(0.2, 0.9, -0.4));
    const vector u(0.3, -1.1, 0.6);
    for (const scalar gap : {1e-3, 0.5, 3.0})
    {
        const fdm::twoSphereLoads together = law.loads
        (
            d, gap, 1, 1.1, u, Zero, u, Zero, symmTensor::zero, true
        );
        for (label i = 0; i < 2; ++i)
        {
            EXPECT_LT(mag(together.force[i]), 1e-12) << gap;
            EXPECT_LT(mag(together.torque[i]), 1e-12) << gap;
        }
        const fdm::twoSphereLoads any = law.loads
        (
            d, gap, 1, 1.1, u, vector(0.1, 0.2, 0.3), -0.5*u,
            vector(-0.3, 0, 0.2), shearE, false
        );
        EXPECT_LT(mag(any.force[0] + any.force[1]),
            1e-12*mag(any.force[0]));
    }
}


TEST(twoSphereResistance, denseClusterResistanceIsPositiveDefinite)
{
    // A sphere and its 12 face-centred cubic neighbours, all gaps 1e-3
    // between touching neighbours: isolated drag plus every pair within
    // a gap of 2 a.  The 78 x 78 resistance has no eigenvalue <= 0
    const fdm::twoSphereResistance law(twoBody());
    const scalar s = 2.001/std::sqrt(2.0);
    DynamicList<point> x(1, point::zero);
    for (const label i : {-1, 1})
    {
        for (const label j : {-1, 1})
        {
            x.append(s*point(i, j, 0));
            x.append(s*point(i, 0, j));
            x.append(s*point(0, i, j));
        }
    }
    const label m = 6*x.size();
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(m, m);
    forAll(x, p)
    {
        for (label k = 0; k < 3; ++k)
        {
            R(6*p + k, 6*p + k) += 6*pi;
            R(6*p + 3 + k, 6*p + 3 + k) += 8*pi;
        }
        for (label q = p + 1; q < x.size(); ++q)
        {
            const vector l = x[q] - x[p];
            if (mag(l) - 2 > 2) continue;
            const matrix Rpq = resistanceOf(law, l/mag(l), mag(l) - 2);
            const label at[2] = {6*p, 6*q};
            for (label a = 0; a < 2; ++a)
            {
                for (label b = 0; b < 2; ++b)
                {
                    R.block<6, 6>(at[a], at[b]) += Rpq.block<6, 6>(6*a, 6*b);
                }
            }
        }
    }
    typedef Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigenSolver;
    const scalar smallest = eigenSolver(R).eigenvalues().minCoeff();
    EXPECT_GT(smallest, 0);
}
