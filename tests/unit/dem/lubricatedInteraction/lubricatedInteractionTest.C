// Unit tests for Foam::fdm::lubricatedInteraction: the implicit lubricated
// contact run through the pair-interaction steps gives the law's loads of
// each pair, carries the pair history across neighbour lists, takes the
// affine shear into the relative velocity and keeps its stress parts and
// restart state

#include "lubricatedInteraction.H"
#include "unitTestHelpers.H"
#include "OStringStream.H"
#include "IStringStream.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const fdm::periodicBox box20
(
    point::zero, point(20, 20, 20), FixedList<bool, 3>({true, true, true})
);

fdm::lubricatedContact law()
{
    // eta 1, g 1e4, k_n/g 1, k_t/g 0.5, eps 1e-2, mu 0.4, cut-off 2a
    return fdm::lubricatedContact(1, 1e4, 1, 0.5, 1e-2, 0.4, 2);
}

// The pair-interaction steps of one time step, as the lubricated DEM runs
// them
struct oneStep
{
    pointField x;
    scalarField radii;
    List<vector> U;
    List<vector> Omega;
    fdm::particleLoads loads;

    oneStep(const List<point>& positions, const List<scalar>& r)
    :
        x(positions),
        radii(r),
        U(x.size(), Zero),
        Omega(x.size(), Zero),
        loads(x.size())
    {}

    void run
    (
        pairInteraction& pi,
        const UList<labelPair>& near,
        const scalar dt,
        const scalar shearRate = 0
    )
    {
        const fdm::positionStep euler(fdm::positionStep::euler(dt));
        pi.update({x, radii, box20, near, euler, U, shearRate, labelList()});
        pi.advance(U, Omega, dt);
        loads = fdm::particleLoads(x.size());
        List<scalar> dipoleTrace;
        pi.addSolvedLoads(U, Omega, {1, 1}, loads, dipoleTrace);
    }
};

} // namespace


TEST(lubricatedInteraction, pairLoadsAreTheLawsLoadsForTheStep)
{
    // An approaching, sliding and spinning pair: the force on each sphere
    // is that of lubricatedContact::step on the pair's own motion, opposite
    // on the two (Newton's third law)
    oneStep s
    (
        List<point>({point(5, 5, 5), point(5, 7.3, 5.2)}),
        List<scalar>({1, 1.4})
    );
    s.U[0] = vector(0.1, 0.2, -0.05);
    s.U[1] = vector(-0.3, -0.4, 0.1);
    s.Omega[0] = vector(0.2, 0, 0.5);
    s.Omega[1] = vector(0, -0.3, 0.1);
    fdm::lubricatedInteraction pairs(law());
    const List<labelPair> near({labelPair(0, 1)});
    s.run(pairs, near, 1e-3);

    const fdm::lubricatedContact model(law());
    const vector l = s.x[1] - s.x[0];
    const vector n = l/mag(l);
    const scalar un = mag(l) - 2.4;
    fdm::lubricatedPairState state = model.start(un, 1.2);
    const vector w = s.Omega[1] - s.Omega[0];
    const fdm::lubricatedPairLoads expected = model.step
    (
        {
            n, un, 1.2,
            model.surfaceVelocity
            (
                s.U[1] - s.U[0], n, un, 1, 1.4, s.Omega[0], s.Omega[1]
            ),
            w, 0.5*(s.Omega[0] + s.Omega[1])
        },
        1e-3,
        state
    );
    ASSERT_GT(mag(expected.force(n)), 0);
    EXPECT_LT(mag(s.loads.force[0] - expected.force(n)), 1e-14);
    EXPECT_LT(mag(s.loads.force[0] + s.loads.force[1]), 1e-14);
    EXPECT_EQ(pairs.nPairs(), 1);

    // The torques of the shear force at the mid-gap arms and of the
    // rolling damping, and the moment of the pair about the first centre
    const vector Fs = expected.shearContact + expected.shearLubrication;
    const vector Tv = expected.rollingDamping*(w - (w & n)*n)
      + expected.twistingDamping*(w & n)*n;
    EXPECT_LT
    (
        mag(s.loads.torque[0] - ((1 + 0.5*un)*(n ^ Fs) + Tv)), 1e-14
    );
    const vector moment =
        s.loads.torque[0] + s.loads.torque[1] + (l ^ s.loads.force[1]);
    EXPECT_LT(mag(moment), 1e-12);
}


TEST(lubricatedInteraction, historyIsCarriedWhileAPairStaysListed)
{
    // A pair pressed together keeps its gap state through a new list that
    // adds a pair; dropped from the list and listed again it starts afresh
    oneStep s
    (
        List<point>({point(5, 5, 5), point(5, 7.001, 5), point(12, 5, 5)}),
        List<scalar>({1, 1, 1})
    );
    s.U[1] = vector(0, -1, 0);
    fdm::lubricatedInteraction pairs(law());
    const List<labelPair> one({labelPair(0, 1)});
    const List<labelPair> two({labelPair(0, 1), labelPair(1, 2)});
    const List<labelPair> other({labelPair(1, 2)});
    for (label k = 0; k < 5; ++k)
    {
        s.run(pairs, one, 1e-3);
    }
    const vector kept = s.loads.force[0];

    // The same step from the listed history and from a fresh one differ
    fdm::lubricatedInteraction carried(pairs);
    s.run(carried, two, 1e-3);
    const vector withHistory = s.loads.force[0];
    fdm::lubricatedInteraction restarted(pairs);
    s.run(restarted, other, 1e-3);
    s.run(restarted, two, 1e-3);
    const vector fresh = s.loads.force[0];
    fdm::lubricatedInteraction fromStart(law());
    s.run(fromStart, two, 1e-3);

    ASSERT_GT(mag(kept), 0);
    EXPECT_EQ(fresh, s.loads.force[0]);
    EXPECT_GT(mag(withHistory - fresh), 1e-6*mag(fresh));
    EXPECT_EQ(carried.pairs().size(), 2);
}


TEST(lubricatedInteraction, listedPairsBeyondTheCutoffAddNothing)
{
    oneStep s
    (
        List<point>({point(5, 5, 5), point(5, 9.05, 5)}),
        List<scalar>({1, 1})
    );
    s.U[1] = vector(0.3, -1, 0);
    fdm::lubricatedInteraction pairs(law());
    s.run(pairs, List<labelPair>({labelPair(0, 1)}), 1e-3);
    EXPECT_EQ(pairs.nPairs(), 0);
    EXPECT_EQ(s.loads.force[0], vector::zero);
    EXPECT_EQ(s.loads.torque[1], vector::zero);
    EXPECT_EQ(pairs.network(s.x, box20).size(), 0);
}


TEST(lubricatedInteraction, affineShearEntersTheRelativeVelocity)
{
    // Velocities relative to the affine flow gammaDot y e_x give the same
    // loads as the lab velocities with no shear rate
    const pointField x({point(5, 5, 5), point(5.3, 7.1, 5)});
    const scalar gammaDot = 0.7;
    const List<scalar> radii({1, 1});
    oneStep relative(x, radii);
    oneStep lab(x, radii);
    forAll(x, i)
    {
        lab.U[i] = vector(gammaDot*x[i].y(), 0, 0);
        lab.Omega[i] = relative.Omega[i] = vector(0, 0, -0.5*gammaDot);
    }
    fdm::lubricatedInteraction a(law());
    fdm::lubricatedInteraction b(law());
    const List<labelPair> near({labelPair(0, 1)});
    relative.run(a, near, 1e-3, gammaDot);
    lab.run(b, near, 1e-3);
    ASSERT_GT(mag(lab.loads.force[0]), 0);
    EXPECT_LT
    (
        mag(relative.loads.force[0] - lab.loads.force[0]),
        1e-12*mag(lab.loads.force[0])
    );
}


TEST(lubricatedInteraction, stressletsAreTheSumOfTheParts)
{
    oneStep s
    (
        List<point>({point(5, 5, 5), point(5.2, 7.005, 5)}),
        List<scalar>({1, 1})
    );
    s.U[1] = vector(1, -1, 0);
    fdm::lubricatedInteraction pairs(law());
    s.run(pairs, List<labelPair>({labelPair(0, 1)}), 1e-3);
    for (label i = 0; i < 2; ++i)
    {
        symmTensor sum(Zero);
        for (label p = 0; p < fdm::lubricatedInteraction::nStressParts; ++p)
        {
            sum += pairs.stresslets(p)[i];
        }
        ASSERT_GT(mag(sum), 0);
        EXPECT_LT(mag(s.loads.stresslet[i] - sum), 1e-14*mag(sum));
    }
    // Each part l_i symm(F_part (x) n): the pair's total is the force
    // dipole of the force on the first sphere over the mid-gap arms
    const vector l = s.x[1] - s.x[0];
    const symmTensor dipole = symm(s.loads.force[0]*l);
    EXPECT_LT
    (
        mag(s.loads.stresslet[0] + s.loads.stresslet[1] - dipole),
        1e-12*mag(dipole)
    );
}


TEST(lubricatedInteraction, restartDropsPairsOfTwoFixedSpheres)
{
    oneStep s
    (
        List<point>({point(5, 5, 5), point(5, 7.01, 5), point(5, 2.99, 5)}),
        List<scalar>({1, 1, 1})
    );
    s.U[1] = vector(0, -1, 0);
    fdm::lubricatedInteraction pairs(law());
    const List<labelPair> near({labelPair(0, 1), labelPair(0, 2)});
    s.run(pairs, near, 1e-3);

    OStringStream os;
    os.precision(17);
    pairs.writePairs(os);
    IStringStream is(os.str());
    const dictionary state(is);
    fdm::lubricatedInteraction read(law());
    read.readPairs(state, boolList({false, true, false}));
    ASSERT_EQ(read.pairs().size(), 1);
    EXPECT_EQ(read.pairs()[0], labelPair(0, 1));

    // The kept pair continues as the one that never stopped
    s.run(pairs, near, 1e-3);
    const vector straight = s.loads.force[1];
    s.run(read, read.pairs(), 1e-3);
    EXPECT_EQ(s.loads.force[1], straight);
}


TEST(lubricatedInteraction, pairForcesAddToTheExternalForceInTurn)
{
    // A sphere pressed by two neighbours under a weight: its force is the
    // weight plus the first pair's force plus the second's, summed in that
    // order (the order of a DEM that adds each pair force to the loads),
    // and addSolvedLoads adds it all
    oneStep s
    (
        List<point>({point(5, 5, 5), point(5, 7.001, 5), point(5, 3, 5.2)}),
        List<scalar>({1, 1, 1.3})
    );
    s.U[1] = vector(0.1, -1, 0);
    s.U[2] = vector(0, 0.7, -0.2);
    vector pairForce[2];
    for (label k = 1; k < 3; ++k)
    {
        fdm::lubricatedInteraction alone(law());
        s.run(alone, List<labelPair>({labelPair(0, k)}), 1e-3);
        pairForce[k - 1] = s.loads.force[0];
    }

    const List<vector> weight(3, vector(1.0/3, -1e3/7, std::sqrt(2.0)));
    fdm::lubricatedInteraction pairs(law());
    pairs.setExternalForce(weight);
    s.run(pairs, List<labelPair>({labelPair(0, 1), labelPair(0, 2)}), 1e-3);
    const vector inTurn = (weight[0] + pairForce[0]) + pairForce[1];
    ASSERT_NE(inTurn, weight[0] + (pairForce[0] + pairForce[1]));
    EXPECT_EQ(s.loads.force[0], inTurn);
}


// ************************************************************************* //
