// Unit tests for the rough contact laws (thesis 1, section 2.6 and
// chapter 5): Hertz with barrier (eqs 2.56-2.57), tangential spring and
// Coulomb (eqs 2.59-2.63), loads (eqs 2.64, 2.69)

#include "contactLawTestHelpers.H"
#include "contactLoads.H"
#include "unitTestHelpers.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

// Golden table of eq 2.57, rows (h_r, floor gap, gap, F_el/k_n); the
// Python contact law (fdmResistance.pairContact) is tested on it too
std::string goldenTable()
{
    return unitTest::projectFile("tests/golden/contactBarrier.dat");
}

std::vector<std::vector<double>> readGolden(const std::string& file)
{
    std::vector<std::vector<double>> rows;
    std::ifstream is(file);
    std::string line;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#')
        {
            continue;
        }
        std::istringstream ls(line);
        std::vector<double> row(4);
        ls >> row[0] >> row[1] >> row[2] >> row[3];
        rows.push_back(row);
    }
    return rows;
}

// The rows of the table: onset, Hertz range, near the floor, at and below
// it, for two roughnesses and two floor gaps
std::vector<std::vector<double>> goldenRows()
{
    std::vector<std::vector<double>> rows;
    for (const double h : {5e-3, 1e-2})
    for (const double floor : {1e-5, 1.2e-5})
    for
    (
        const double gap
      : {2*h, h, 0.9*h, 0.5*h, 0.1*h, 0.01*h, 3e-5, 2*floor,
         1.5*floor, floor + 1e-9*h, floor, 0.5*floor}
    )
    {
        std::ostringstream entries;
        entries.precision(17);
        entries << "roughness " << h << "; friction 0.5; kn 1;";
        const double f = law(entries.str())->elasticNormalForce(gap, floor);
        rows.push_back({h, floor, gap, f});
    }
    return rows;
}

} // namespace


TEST(contactLaw, normalForceFollowsHertzWithBarrier)
{
    const auto c = law(thesis);
    EXPECT_EQ(c->type(), "hertz");
    EXPECT_DOUBLE_EQ(c->roughness(), hr);

    // No force at and beyond the onset delta' = h_r
    EXPECT_EQ(c->elasticNormalForce(hr, floorGap), 0);
    EXPECT_EQ(c->elasticNormalForce(2*hr, floorGap), 0);

    // Far from the floor the barrier is 1 to 1e-3: plain Hertz
    EXPECT_NEAR
    (
        c->elasticNormalForce(0.5*hr, floorGap)/(kn*std::pow(0.5*hr, 1.5)),
        1, 1e-2
    );
}


TEST(contactLaw, barrierMatchesTheGoldenTable)
{
    // FDM_WRITE_GOLDEN=1 fdmUnitTests rewrites the table after a deliberate
    // change of eq 2.57 (and the Python law must follow)
    const std::vector<std::vector<double>> rows(goldenRows());
    if (unitTest::writingGolden())
    {
        std::ofstream os(goldenTable());
        os.precision(17);
        os  << "# Eq 2.57 (thesis 1): F_el/k_n of the rough Hertz contact with"
            << " barrier,\n# written by"
            << " tests/unit/contact/contactLaw/contactLawTest.C"
            << " (FDM_WRITE_GOLDEN=1)\n# roughness floorGap gap F_el/k_n\n";
        for (const auto& r : rows)
        {
            os << r[0] << ' ' << r[1] << ' ' << r[2] << ' ' << r[3] << '\n';
        }
    }
    const std::vector<std::vector<double>> golden(readGolden(goldenTable()));
    ASSERT_EQ(golden.size(), rows.size()) << goldenTable();
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        for (label k = 0; k < 3; ++k)
        {
            EXPECT_EQ(golden[i][k], rows[i][k]) << "row " << i;
        }
        EXPECT_NEAR(rows[i][3], golden[i][3], 1e-14*golden[i][3])
            << "row " << i;
    }
}


TEST(contactLaw, barrierKeepsGapsAboveTheFloor)
{
    const auto c = law(thesis);

    // F_el grows monotonically as the gap closes and exceeds any load
    // before the floor: the equilibrium gap under a load is above it
    scalar previous = 0;
    for (scalar gap = hr; gap > floorGap*(1 + 1e-6); gap = 0.5*(gap + floorGap))
    {
        const scalar f = c->elasticNormalForce(gap, floorGap);
        EXPECT_GE(f, previous);
        previous = f;
    }
    for (const scalar load : {1.0, 1e2, 1e4})
    {
        scalar lo = floorGap, hi = hr;
        for (int it = 0; it < 200; ++it)
        {
            const scalar mid = 0.5*(lo + hi);
            (c->elasticNormalForce(mid, floorGap) > load ? lo : hi) = mid;
        }
        EXPECT_GT(lo, floorGap) << "load " << load;
    }

    // Overdamped approach under a load far above the Hertz scale
    // k_n h_r^1.5 = 3.5: d(gap)/dt = -(F - F_el)/R, explicit steps
    const scalar load = 1e3, R = 6*constant::mathematical::pi/1e-3;
    scalar gap = 2*hr;
    for (int step = 0; step < 20000; ++step)
    {
        gap -= 1e-5*(load - c->elasticNormalForce(gap, floorGap))/R;
        ASSERT_GT(gap, floorGap) << "step " << step;
    }
}


TEST(contactLaw, normalStiffnessIsTheDerivativeOfTheForce)
{
    const auto c = law(thesis);
    for (const scalar gap : {0.9*hr, 0.5*hr, 0.1*hr, 0.01*hr, 3e-5})
    {
        const scalar h = 1e-7*gap;
        const scalar fd =
            (c->elasticNormalForce(gap - h, floorGap)
           - c->elasticNormalForce(gap + h, floorGap))/(2*h);
        EXPECT_NEAR(c->normalStiffness(gap, floorGap)/fd, 1, 1e-6) << gap;
    }
    EXPECT_EQ(c->normalStiffness(1.1*hr, floorGap), 0);
}


TEST(contactLaw, stiffnessFromTheDeformationRule)
{
    // 6 pi eta gammaDot a_1^2 = k_n (eps h_r)^1.5 (thesis 2.6.3)
    const auto c =
        law("roughness 5e-3; friction 0.5; shearRate 2; meanDeformation 0.2;");
    const scalar F0 = 6*constant::mathematical::pi*2;
    EXPECT_NEAR(c->kn()*std::pow(0.2*hr, 1.5)/F0, 1, 1e-12);
    // At the mean deformation the force is F0 (barrier 1 + 3e-4)
    EXPECT_NEAR(c->elasticNormalForce(0.8*hr, floorGap)/F0, 1, 1e-3);
}


TEST(contactLaw, tangentialLoadingSlidingAndUnloading)
{
    const auto c = law(thesis);
    const scalar gap = 0.5*hr, delta = hr - gap;
    const scalar Fel = c->elasticNormalForce(gap, floorGap);
    const scalar kt = (2.0/7.0)*Fel/delta;
    const vector t(0, 1, 0);

    // Loading: F_t = -k_t Y while below the Coulomb cap
    vector slip = 0.1*mu*Fel/kt*t;
    fdm::contactForce f = c->evaluate(geometry(gap), slip);
    EXPECT_FALSE(f.sliding);
    EXPECT_NEAR(f.tangential.y(), -0.1*mu*Fel, 1e-12*Fel);
    EXPECT_NEAR(f.force.x(), -Fel, 1e-12*Fel);

    // Beyond the cap: |F_t| = mu F_el and the spring is truncated
    slip = 3*mu*Fel/kt*t;
    f = c->evaluate(geometry(gap), slip);
    EXPECT_TRUE(f.sliding);
    EXPECT_NEAR(mag(f.tangential), mu*Fel, 1e-12*Fel);
    EXPECT_NEAR(mag(slip), mu*Fel/kt, 1e-12*mu*Fel/kt);

    // Unloading: a reversed slip increment sticks at once with slope k_t
    slip -= 0.2*mu*Fel/kt*t;
    f = c->evaluate(geometry(gap), slip);
    EXPECT_FALSE(f.sliding);
    EXPECT_NEAR(f.tangential.y(), -0.8*mu*Fel, 1e-12*Fel);

    // Out of contact: no force and the slip is forgotten
    slip = t;
    f = c->evaluate(geometry(1.5*hr), slip);
    EXPECT_EQ(mag(f.force), 0);
    EXPECT_EQ(mag(slip), 0);
}


TEST(contactLaw, slipTurnsWithThePair)
{
    const vector slip(0, 3, 4);
    const vector n = normalised(vector(1, 1, 0));
    const vector turned = fdm::rotateIntoTangentPlane(slip, n);
    EXPECT_NEAR(turned & n, 0, 1e-15);
    EXPECT_NEAR(mag(turned), 5, 1e-14);

    // Slip velocity (eq 2.62): counter-rotating spheres roll on each
    // other, co-rotating ones slide; a sphere rolling on a wall has none
    const vector e(1, 0, 0), W(0, 0, 1);
    EXPECT_NEAR
    (
        mag(fdm::slipVelocity(e, Zero, W, 1, Zero, -W, 1)), 0, 1e-15
    );
    EXPECT_NEAR
    (
        mag(fdm::slipVelocity(e, Zero, W, 1, Zero, W, 1.0)), 2, 1e-15
    );
    EXPECT_NEAR
    (
        mag(fdm::slipVelocity(e, vector(0, -1, 0), W, 1, Zero, Zero, 0)),
        0, 1e-15
    );
}


TEST(contactLaw, pairLoadsConserveMomentumAndAngularMomentum)
{
    const auto c = law(thesis);
    const scalar ai = 1, aj = 1.4;
    const vector xi(0.3, -0.2, 0.1);
    const vector n = normalised(vector(1, 2, -0.5));
    const scalar gap = 0.4*hr, r = ai + aj + gap;
    const vector xj = xi + r*n;

    vector slip = 1e-4*normalised(vector(0, 0.5, 2) - (vector(0, 0.5, 2) & n)*n);
    const fdm::contactForce f =
        c->evaluate(fdm::contactGeometry{n, gap, 1e-5*(ai + aj)/2}, slip);
    ASSERT_GT(mag(f.tangential), 0);

    fdm::particleLoads loads(2);
    const List<vector>& F = loads.force;
    const List<vector>& T = loads.torque;
    const List<symmTensor>& S = loads.stresslet;
    fdm::addContactLoads
    (
        f, n, ai*r/(ai + aj), aj*r/(ai + aj), 0, 1, loads
    );

    // Newton's third law and no net moment about the origin
    EXPECT_NEAR(mag(F[0] + F[1]), 0, 1e-15*mag(F[0]));
    const vector moment = (xi ^ F[0]) + (xj ^ F[1]) + T[0] + T[1];
    EXPECT_NEAR(mag(moment), 0, 1e-12*mag(F[0]));

    // The pair stresslet is symm(F (x) r), shared in the ratio a_i : a_j
    const symmTensor pair = symm(f.force*(r*n));
    EXPECT_NEAR(mag(S[0] + S[1] - pair), 0, 1e-12*mag(pair));
    EXPECT_NEAR(mag(S[0]/ai - S[1]/aj), 0, 1e-12*mag(pair));

    // Repulsion along n gives a compressive (negative-trace) stresslet
    EXPECT_LT(tr(S[0] + S[1]), 0);
}


TEST(contactLaw, badInputNamesTheKeyword)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    for
    (
        const std::string& bad :
        {
            std::string("friction 0.5; kn 1e4;"),
            std::string("roughness 0.5; friction 0.5; kn 1e4;"),
            std::string("roughness 5e-3; friction -1; kn 1e4;"),
            std::string("roughness 5e-3; friction 0.5;"),
            std::string(thesis + " shearRate 1; meanDeformation 0.2;"),
            std::string(thesis + " model sticky;"),
            std::string(thesis + " model adhesiveHertz;")
        }
    )
    {
        EXPECT_THROW(law(bad), Foam::error) << bad;
    }
}
