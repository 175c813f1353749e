/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Application
    particleSystemScaling

Description
    Benchmark (issue 6, item 3): cost of the particle sub-problem without
    fluid for 10^3, 10^4 and 10^5 particles in a dense periodic packing
    (jittered simple cubic lattice, spacing 2.3 a, phi = 0.34): pair search
    (cell-linked list, gap < 0.3 a), assembly of the particle system
    (pseudo-mass of eq 2.53 for a = 5 Delta plus the frame-invariant
    sub-grid matrix of every near pair, evaluated from the shipped table
    data/resistance/subGridPair_lambda1) and its preconditioned-CG solve
    (tolerance 1e-6).  Prints a table of wall times, times per particle
    and the process' peak resident memory after each size (the sizes
    ascend, so it is that size's peak): what every rank holds today, when
    each holds all particles (issue 38's replicated baseline).

\*---------------------------------------------------------------------------*/

#include "pairSearch.H"
#include "pairSubGridMatrix.H"
#include "resistanceTable.H"
#include "particleVelocitySystem.H"
#include "rigidBodyMoments.H"
#include "clockTime.H"
#include "constants.H"
#include "IOstreams.H"
#include "peakMemory.H"

#include <random>

using namespace Foam;

int main()
{
    const scalar a = 1, spacing = 2.3, delta = a/5, alpha = delta*delta;
    const scalar pi = constant::mathematical::pi;

    // Pseudo-mass of an isolated sphere: volume and (2/5) V a^2 inertia
    fdm::rigidBodyMoments sphere;
    sphere.volume = 4.0/3.0*pi*a*a*a;
    sphere.inertia = 0.4*sphere.volume*a*a*symmTensor::I;

    const fdm::resistanceTable table = fdm::resistanceTable::read
    (
        fileName("$FDM_PROJECT_DIR/data/resistance/subGridPair_lambda1")
       .expand()
    );

    Info<< "| N | near pairs | pair search s | assembly s | solve s |"
        << " CG its | total us per particle | peak memory MiB |" << nl
        << "|---|---|---|---|---|---|---|---|" << nl;

    for (const label n : {10, 22, 47})
    {
        const label N = n*n*n;
        const scalar L = n*spacing;
        const fdm::periodicBox box(point::zero, point(L, L, L),
            FixedList<bool, 3>(true));

        std::mt19937 gen(1);
        std::uniform_real_distribution<scalar> jitter(-0.1, 0.1);
        pointField x(N);
        scalarField radius(N, a);
        label p = 0;
        for (label k = 0; k < n; ++k)
        for (label j = 0; j < n; ++j)
        for (label i = 0; i < n; ++i)
        {
            x[p++] = box.wrap(spacing*point(i + 0.5, j + 0.5, k + 0.5)
              + vector(jitter(gen), jitter(gen), jitter(gen)));
        }

        clockTime clock;
        DynamicList<labelPair> pairs;
        fdm::findNearPairs(box, x, radius, 0.3*a, pairs);
        const scalar tSearch = clock.timeIncrement();

        fdm::particleVelocitySystem sys(N);
        std::uniform_real_distribution<scalar> load(-1, 1);
        for (label q = 0; q < N; ++q)
        {
            sys.addMass(q, sphere, 1/alpha);
            sys.addRhs(q, vector(load(gen), load(gen), load(gen)),
                vector(load(gen), load(gen), load(gen)));
        }
        for (const labelPair& pq : pairs)
        {
            const vector d = box.minimumImage(x[pq.second()] - x[pq.first()]);
            const scalar r = mag(d);
            fdm::pairSubGridMatrix(table.pairFunctions(r/a - 2, a), r, d/r)
               .addTo(sys, pq.first(), pq.second(), 1);
        }
        const scalar tAssembly = clock.timeIncrement();

        List<vector> U(N, Zero), W(N, Zero);
        const auto info = sys.solve(1e-6, 1000, U, W);
        const scalar tSolve = clock.timeIncrement();

        Info<< "| " << N << " | " << pairs.size() << " | " << tSearch
            << " | " << tAssembly << " | " << tSolve << " | "
            << info.iterations << " | "
            << 1e6*(tSearch + tAssembly + tSolve)/N << " | "
            << fdm::peakResidentBytes()/1048576 << " |" << endl;
    }

    return 0;
}
