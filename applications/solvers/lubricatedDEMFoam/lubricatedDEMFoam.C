/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Application
    lubricatedDEMFoam

Description
    Lubrication-only DEM (thesis 2): spheres in a Lees-Edwards cell sheared
    at an imposed rate, interacting through the implicit lubricated contact
    model only, with no fluid solve.  The cell is tri-periodic, or open in
    one direction with a floor of fixed spheres and gravity (viscous
    resuspension, thesis 2 article 3).  Same case
    conventions as fdmSuspensionFoam: system/controlDict (deltaT, endTime,
    writeInterval, function objects), constant/particleProperties, the
    particle list of fdmPackParticles, <time>/particleState for restarts.

    constant/particleProperties:
    \verbatim
    particlesFile   "particleList";
    density         0.01;           // particle density rho_p
    cell
    {
        min         (0 0 0);
        max         (20 20 20);
        shearRate   1;              // gammaDot along x, gradient along y
        open        ();             // directions without periodic images,
                                    // e.g. (y): gravity along the gradient
    }
    drag                            // Stokes drag against the affine flow
    {
        viscosity           0;      // on every particle (article 1 and
                                    // resuspension along y: eta_f)
        isolatedViscosity   0;      // extra, on particles with fewer than
        isolatedBelow       3;      // isolatedBelow interactions (art. 3)
    }
    fixedGroups     ();             // groups held fixed (rough floor made
                                    // by fdmPackParticles --attach-walls),
                                    // carried by the affine flow
    gravity                         // optional: weight (rho_p - rho_f) V g
    {
        direction       (0 -1 0);
        shieldsNumber   2;          // eta gammaDot/((rho_p - rho_f) g a)
        // acrivosNumber 0.7;       // or (9/2) a Sh/h_0 (Acrivos), with
        // packingFraction 0.58;    // h_0 = V/phi_m the settled bed
        // value        (0 -400 0); // or the acceleration itself
    }
    fluidDensity    0;              // rho_f (buoyancy)
    pressureWall                    // optional: imposed particle pressure
    {
        group       attachedUpper;  // fixed spheres moving together along
        pressure    10;             // the open direction at
        damping     1e4;            // v_w = (F - P A)/damping
    }
    lubricatedContact { ... }       // see lubricatedContact.H
    output
    {
        interval    100;            // steps between time-series rows
                                    // and particles.h5 records
        track       (0 1);          // optional: write these particles'
                                    // positions to tracks.dat
        vtkInterval 0;              // optional: VTK files every n steps
                                    // (0: at the write times)
    }
    \endverbatim

    Writes postProcessing/lubricatedDEM/<startTime>/stress.dat: time,
    strain, phi, interactions, contacts, stability number and the xx, yy,
    zz, xy stresses of the four parts NC, SC, NL, SL (compression < 0);
    with output{track}, tracks.dat: time and the positions of those
    particles.  postProcessing/particles.h5: the particle series in the
    format of fdmSuspensionFoam's (fdm::demParticleSeries), a record per
    stress.dat row, published at the write times.
    <time>/particleState also holds each particle's stresslets
    of the four parts (stresslet_<part>), for local stress profiles.
    VTK/particles_<time>.vtp and contacts_<time>.vtp with their .series
    files open in ParaView (fdm::particleVTKWriter): the particles from the
    start time on (in the lab frame), and every interaction of the last
    step as a line (none at the start time, before the first step).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "lubricatedDEM.H"
#include "demSetup.H"
#include "demRunOutput.H"
#include "checkTimeControls.H"
#include "incompleteWrites.H"
#include "readableDictionaries.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Lubrication-only DEM of a sheared suspension (thesis 2): no fluid"
        " solve, pairwise lubricated contacts in a Lees-Edwards cell"
    );
    argList::noParallel();
    #include "setRootCase.H"
    fdm::checkDictionariesReadable(args.rootPath()/args.globalCaseName());
    // A time whose particleState a killed run did not finish is set aside
    fdm::setAsideIncompleteWrites(args, wordList());
    #include "createTime.H"
    fdm::checkTimeControls(runTime);

    const autoPtr<IOdictionary> properties(fdm::readDEMProperties(runTime));
    fdm::lubricatedDEM dem = fdm::createDEM(properties(), runTime);
    const scalar dt = runTime.deltaTValue();
    fdm::checkTimeStep(dem, dt, runTime);

    fdm::demRunOutput output(runTime, dem, properties());

    Info<< nl << "Starting time loop" << nl << endl;

    while (runTime.run())
    {
        ++runTime;
        dem.step(dt);
        output.afterStep(dem, runTime);
    }
    output.end(dem);

    return 0;
}


// ************************************************************************* //
