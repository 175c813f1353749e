/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Application
    demCost

Description
    Benchmark (issue 8): cost of the lubrication-only DEM (lubricatedDEM,
    the core of lubricatedDEMFoam) for 10^3, 10^4 and 10^5 spheres in a
    sheared Lees-Edwards cell: a jittered simple cubic lattice (phi 0.4,
    spacing 2.19 a), the tutorial's lubricatedContact (stiffness 1e6,
    roughness 1e-2, friction 0.4) at the article 3 cut-off 2a and at 1a,
    with article 2's Delaunay neighbours triangulated every step and
    every 25 steps, and with lubrication twoSphere (the exact two-body
    hydrodynamics and the isolated drag) at cut-off 2a,
    shear rate 1, deltaT 0.2 sqrt(m/g), Stokes number 1e-2.  After 50
    steps to fill the interactions, times `steps` steps and prints a table
    of particle-steps per second and the time per particle-step, which is
    constant when the cost is linear in N.

        demCost [steps]         (default 200)

\*---------------------------------------------------------------------------*/

#include "lubricatedDEM.H"
#include "clockTime.H"
#include "IOstreams.H"

#include <cstdlib>
#include <random>

using namespace Foam;

int main(int argc, char* argv[])
{
    const label steps = argc > 1 ? std::atoi(argv[1]) : 200;
    const scalar spacing = 2.19, rho = 1e-2, g = 1e6;

    Info<< "| pairs | N | interactions per sphere | contacts |"
        << " steps | wall s | particle-steps/s | us per particle-step |"
        << nl << "|---|---|---|---|---|---|---|---|" << nl;

    // Pair selections: the cut-off (Verlet list), and the Delaunay
    // neighbours (article 2; cut-off 4a keeps every edge) triangulated
    // every step or every 25
    // every step or every 25; and the complete pair law at cut-off 2a
    struct selection
    {
        const char* name;
        scalar cutoff;
        label interval;
        bool twoSphere;
    };
    for
    (
        const selection& sel :
        {
            selection{"cut-off 2a", 2, 0, false},
            selection{"cut-off 1a", 1, 0, false},
            selection{"Delaunay, every step", 4, 1, false},
            selection{"Delaunay, every 25 steps", 4, 25, false},
            selection{"lubrication twoSphere, cut-off 2a", 2, 0, true}
        }
    )
    {
        for (const label n : {10, 22, 47})
        {
            const label N = n*n*n;
            const scalar L = n*spacing;
            fdm::lubricatedContact law(1, g, 1, 0.5, 1e-2, 0.4, sel.cutoff);
            if (sel.twoSphere)
            {
                law.useTwoSphereHydrodynamics();
            }
            fdm::lubricatedDEM dem
            (
                fdm::periodicBox(point::zero, point(L, L, L),
                    FixedList<bool, 3>(true)),
                1,
                law
            );
            if (sel.twoSphere)
            {
                dem.setDrag(1);
            }
            if (sel.interval > 0)
            {
                dem.setDelaunayNeighbours(sel.interval);
            }
            std::mt19937 gen(1);
            std::uniform_real_distribution<scalar> jitter(-0.05, 0.05);
            List<point> lattice(N);
            label m = 0;
            for (label i = 0; i < n; ++i)
            {
                for (label j = 0; j < n; ++j)
                {
                    for (label k = 0; k < n; ++k)
                    {
                        lattice[m++] =
                            spacing*point(i + 0.5, j + 0.5, k + 0.5)
                          + point(jitter(gen), jitter(gen), jitter(gen));
                    }
                }
            }
            dem.addParticles
            (
                lattice, scalarList(N, scalar(1)), rho, boolList(N, true)
            );
            const scalar dt = 0.2*dem.criticalTimeStep();
            for (label s = 0; s < 50; ++s)
            {
                dem.step(dt);
            }
            clockTime clock;
            for (label s = 0; s < steps; ++s)
            {
                dem.step(dt);
            }
            const scalar wall = clock.elapsedTime();
            const scalar rate = N*steps/wall;
            Info<< "| " << sel.name << " | " << N << " | "
                << scalar(dem.nInteractions())/N << " | "
                << dem.nContacts() << " | " << steps << " | " << wall
                << " | " << rate << " | " << 1e6/rate << " |" << endl;
        }
    }
    return 0;
}
