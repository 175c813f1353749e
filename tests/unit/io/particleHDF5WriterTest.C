// Unit test of the particle time series (particleHDF5Writer, with the HDF5
// calls of particleHDF5Files): records read back from particles.h5 through
// its virtual datasets as appended; only committed records are published;
// a restart at t0 drops the records at or after t0 and continues; an
// unreadable particles.h5 is moved aside, never overwritten.

#include "particleHDF5Writer.H"
#include "particleHDF5Files.H"
#include "OSspecific.H"
#include "OFstream.H"
#include "unitTestCase.H"
#include "unitTestHDF5.H"
#include <gtest/gtest.h>
#include <vector>

using namespace Foam;

namespace
{

const label N = 3;

//- A record whose values all derive from its time, so that what is read
//  back identifies the record it came from
struct recordAt
{
    List<vector> x, U, W, F, T, Fc, Tc;
    List<symmTensor> S, Sc;
    List<scalar> s;

    explicit recordAt(const scalar t)
    :
        x(N), U(N), W(N), F(N), T(N), Fc(N), Tc(N), S(N), Sc(N), s(N)
    {
        for (label p = 0; p < N; ++p)
        {
            x[p] = vector(t, p, -t*p);
            U[p] = 2*x[p]; W[p] = 3*x[p]; F[p] = 4*x[p]; T[p] = 5*x[p];
            Fc[p] = 6*x[p]; Tc[p] = 7*x[p];
            S[p] = symmTensor(t, p, 1, 2, 3, -t - 2);
            Sc[p] = 2*S[p];
            s[p] = t + p;
        }
    }

    particleHDF5Writer::record get() const
    {
        return {x, U, W, F, T, S, s, Fc, Tc, Sc};
    }
};

//- The series of a scratch case's postProcessing/particles.h5
struct series
{
    unitTest::scratchCase sc;
    fileName dir;
    fileName h5;
    scalarField radius;
    labelList group;

    explicit series(const word& name)
    :
        sc(name),
        dir(sc.path()/"postProcessing"),
        h5(dir/"particles.h5"),
        radius(List<scalar>({1.0, 1.2, 0.9})),
        group({0, 1, 0})
    {
        mkDir(dir);
    }

    void write(const scalar start, const scalarList& times, label commitAt)
    {
        particleHDF5Writer w(h5, radius, group, start);
        forAll(times, k)
        {
            if (k == commitAt)
            {
                w.commit();
            }
            w.append(times[k], recordAt(times[k]).get());
        }
    }
};

} // End anonymous namespace


TEST(particleHDF5Writer, recordsReadBackThroughTheMasterFile)
{
    series s("readBack");
    {
        particleHDF5Writer w(s.h5, s.radius, s.group, 0);
        EXPECT_FALSE(isFile(s.h5));          // nothing before a record
        w.append(0.1, recordAt(0.1).get());
        w.append(0.2, recordAt(0.2).get());
        w.commit();
        EXPECT_EQ(w.nCommitted(), 2);
        w.append(0.3, recordAt(0.3).get());
        EXPECT_EQ(w.nCommitted(), 2);        // not published yet
    }                                       // the end of a run commits

    EXPECT_EQ(unitTest::readDataset(s.h5, "time"), std::vector<double>({0.1, 0.2, 0.3}));
    const std::vector<double> x = unitTest::readDataset(s.h5, "position");
    const std::vector<double> S = unitTest::readDataset(s.h5, "contactStresslet");
    ASSERT_EQ(x.size(), size_t(3*N*3));
    const scalarList times({0.1, 0.2, 0.3});
    forAll(times, k)
    {
        const recordAt r(times[k]);
        for (label p = 0; p < N; ++p)
        {
            for (direction d = 0; d < 3; ++d)
            {
                EXPECT_EQ(x[(k*N + p)*3 + d], r.x[p][d]);
            }
            for (direction d = 0; d < 6; ++d)
            {
                EXPECT_EQ(S[(k*N + p)*6 + d], r.Sc[p][d]);
            }
        }
    }
    EXPECT_EQ(unitTest::readDataset(s.h5, "radius"), std::vector<double>({1, 1.2, 0.9}));
}


TEST(particleHDF5Writer, restartDropsRecordsFromItsStartAndContinues)
{
    series s("restart");
    s.write(0, {0.1, 0.2, 0.3, 0.4}, 2);    // segments {0.1 0.2} {0.3 0.4}
    s.write(0.2, {0.2, 0.25}, -1);          // restart inside a segment

    EXPECT_EQ
    (
        unitTest::readDataset(s.h5, "time"), std::vector<double>({0.1, 0.2, 0.25})
    );
    const std::vector<double> x = unitTest::readDataset(s.h5, "position");
    EXPECT_EQ(x[3*N], 0.2);                 // the restarted run's record
}


TEST(particleHDF5Writer, unreadableSeriesIsMovedAsideNotOverwritten)
{
    series s("unreadable");
    OFstream(s.h5)() << "not an HDF5 file" << endl;
    s.write(0, {0.5}, -1);

    EXPECT_EQ(unitTest::readDataset(s.h5, "time"), std::vector<double>({0.5}));
    fileNameList aside = readDir(s.dir, fileName::FILE);
    label nAside = 0;
    for (const fileName& f : aside)
    {
        if (f.find("unreadable") != string::npos)
        {
            ++nAside;
        }
    }
    EXPECT_EQ(nAside, 1);
}
