/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Application
    distributedSolve

Description
    Benchmark and check of issue 38's particle solve by subdomain: the
    packing of particleSystemScaling (jittered cubic lattice, spacing 2.3 a,
    pairs with gap < 0.3 a, the shipped sub-grid table, pseudo-mass of
    a = 5 Delta) cut into slabs along x, one per rank; each rank owns the
    particles whose centres lie in its slab, holds as ghosts their pair
    partners owned elsewhere, assembles the rows of its own particles and
    solves with the others (fdm::distributedParticleSystem).  Prints per
    lattice size the owned and ghost particles of the busiest rank, the
    assembly and solve times, the solve's CPU time and the peak memory
    (each the largest over ranks) and the CG iterations;
    with -compare, the master also solves the whole system
    (fdm::particleVelocitySystem, today's scheme, every rank alike) to the
    same tolerance and the largest difference of the velocities is printed
    relative to the largest velocity.

        distributedSolve [-lattice "(10 22 47)"] [-tolerance 1e-6]
                         [-compare] [-parallel]

    The packing itself and its pair search are made whole on every rank
    here (a stand-in for the owned scheme's own search, timed apart).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "pairSearch.H"
#include "pairSubGridMatrix.H"
#include "resistanceTable.H"
#include "particleVelocitySystem.H"
#include "distributedParticleSystem.H"
#include "rigidBodyMoments.H"
#include "clockTime.H"
#include "cpuTime.H"
#include "peakMemory.H"
#include "constants.H"
#include "IOstreams.H"

#include <random>

using namespace Foam;

namespace
{

//- The loads on all particles, the same on every rank
void loads(const label N, List<vector>& F, List<vector>& T)
{
    std::mt19937 gen(2);
    std::uniform_real_distribution<scalar> load(-1, 1);
    F.setSize(N);
    T.setSize(N);
    for (label q = 0; q < N; ++q)
    {
        F[q] = vector(load(gen), load(gen), load(gen));
        T[q] = vector(load(gen), load(gen), load(gen));
    }
}


//- Add the masses, loads and pair blocks of the particles 'local' numbers
//  (-1: not held) into sys
void assemble
(
    fdm::particleSystemSink& sys,
    const labelUList& local,
    const pointField& x,
    const fdm::periodicBox& box,
    const UList<labelPair>& pairs,
    const fdm::resistanceTable& table
)
{
    const scalar a = 1, alpha = sqr(a/5);
    fdm::rigidBodyMoments sphere;
    sphere.volume = 4.0/3.0*constant::mathematical::pi*pow3(a);
    sphere.inertia = 0.4*sphere.volume*a*a*symmTensor::I;
    List<vector> F, T;
    loads(x.size(), F, T);
    forAll(local, q)
    {
        if (local[q] >= 0)
        {
            sys.addMass(local[q], sphere, 1/alpha);
            sys.addRhs(local[q], F[q], T[q]);
        }
    }
    for (const labelPair& pq : pairs)
    {
        const label p = local[pq.first()], q = local[pq.second()];
        if (p >= 0 && q >= 0)
        {
            const vector d = box.minimumImage(x[pq.second()] - x[pq.first()]);
            const scalar r = mag(d);
            fdm::pairSubGridMatrix(table.pairFunctions(r/a - 2, a), r, d/r)
               .addTo(sys, p, q, 1);
        }
    }
}

} // namespace


int main(int argc, char* argv[])
{
    argList::noCheckProcessorDirectories();
    argList::addOption("lattice", "list", "particles per lattice edge");
    argList::addOption("tolerance", "value", "CG tolerance (1e-6)");
    argList::addBoolOption("compare", "solve the whole system on the master");
    argList args(argc, argv);
    labelList sizes({10, 22, 47});
    scalar tol = 1e-6;
    args.readIfPresent("lattice", sizes);
    args.readIfPresent("tolerance", tol);
    const label nRanks = Pstream::nProcs(), me = Pstream::myProcNo();

    const fdm::resistanceTable table = fdm::resistanceTable::read
    (
        fileName("$FDM_PROJECT_DIR/data/resistance/subGridPair_lambda1")
       .expand()
    );

    Info<< "| N | ranks | owned (largest) | ghosts (largest) | search s |"
        << " assembly s | solve s | CG its | difference | solve cpu s |"
        << " peak MiB |" << nl
        << "|---|---|---|---|---|---|---|---|---|---|---|" << nl;

    for (const label n : sizes)
    {
        const label N = n*n*n;
        const scalar L = 2.3*n;
        const fdm::periodicBox box(point::zero, point(L, L, L),
            FixedList<bool, 3>(true));
        std::mt19937 gen(1);
        std::uniform_real_distribution<scalar> jitter(-0.1, 0.1);
        pointField x(N);
        labelList owner(N);
        forAll(x, p)
        {
            const label i = p % n, j = (p/n) % n, k = p/(n*n);
            x[p] = box.wrap(2.3*point(i + 0.5, j + 0.5, k + 0.5)
              + vector(jitter(gen), jitter(gen), jitter(gen)));
            owner[p] = min(nRanks - 1, label(x[p].x()/L*nRanks));
        }

        clockTime clock;
        DynamicList<labelPair> pairs;
        fdm::findNearPairs(box, x, scalarField(N, 1.0), 0.3, pairs);
        scalar tSearch = clock.timeIncrement();

        // Local numbers: owned in global order, then the ghosts
        labelList local(N, -1), ownerIndex(N, -1), ranksCount(nRanks, 0);
        forAll(owner, p)
        {
            ownerIndex[p] = ranksCount[owner[p]]++;
        }
        label nOwned = ranksCount[me];
        forAll(owner, p)
        {
            local[p] = owner[p] == me ? ownerIndex[p] : -1;
        }
        DynamicList<label> ghostOwner, ghostIndex;
        for (const labelPair& pq : pairs)
        {
            for (const label s : {0, 1})
            {
                const label p = s ? pq.second() : pq.first();
                const label q = s ? pq.first() : pq.second();
                if (owner[p] == me && local[q] < 0)
                {
                    local[q] = nOwned + ghostOwner.size();
                    ghostOwner.append(owner[q]);
                    ghostIndex.append(ownerIndex[q]);
                }
            }
        }

        fdm::distributedParticleSystem sys(nOwned, ghostOwner, ghostIndex);
        assemble(sys, local, x, box, pairs, table);
        scalar tAssembly = clock.timeIncrement();
        const label nLocal = nOwned + ghostOwner.size();
        List<vector> U(nLocal, Zero), W(nLocal, Zero);
        cpuTime cpu;
        const auto info = sys.solve(tol, 1000, U, W);
        scalar tSolve = clock.timeIncrement();
        scalar cpuSolve = cpu.cpuTimeIncrement();
        scalar peak = fdm::peakResidentBytes()/1048576;

        // The owned velocities on the master, against the whole system
        scalar difference = -1;
        if (args.found("compare"))
        {
            vectorField Ug(N, Zero), Wg(N, Zero);
            forAll(local, p)
            {
                if (owner[p] == me)
                {
                    Ug[p] = U[local[p]];
                    Wg[p] = W[local[p]];
                }
            }
            reduce(Ug, sumOp<vectorField>());
            reduce(Wg, sumOp<vectorField>());
            fdm::particleVelocitySystem whole(N);
            assemble(whole, identity(N), x, box, pairs, table);
            List<vector> Uw(N, Zero), Ww(N, Zero);
            whole.solve(tol, 1000, Uw, Ww);
            scalar largest = 0;
            difference = 0;
            forAll(Uw, p)
            {
                largest = max(largest, max(mag(Uw[p]), mag(Ww[p])));
                difference = max(difference,
                    max(mag(Ug[p] - Uw[p]), mag(Wg[p] - Ww[p])));
            }
            difference /= largest;
        }

        label nGhosts = ghostOwner.size();
        reduce(nOwned, maxOp<label>());
        reduce(nGhosts, maxOp<label>());
        reduce(tSearch, maxOp<scalar>());
        reduce(tAssembly, maxOp<scalar>());
        reduce(tSolve, maxOp<scalar>());
        reduce(cpuSolve, maxOp<scalar>());
        reduce(peak, maxOp<scalar>());
        Info<< "| " << N << " | " << nRanks << " | " << nOwned << " | "
            << nGhosts << " | " << tSearch << " | " << tAssembly << " | "
            << tSolve << " | " << info.iterations << " | " << difference
            << " | " << cpuSolve << " | " << peak << " |" << endl;
    }

    return 0;
}


// ************************************************************************* //
