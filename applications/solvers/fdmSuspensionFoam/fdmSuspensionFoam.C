/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Application
    fdmSuspensionFoam

Group
    grpIncompressibleSolvers

Description
    Stokes-flow solver for particle-resolved suspensions by the Fictitious
    Domain Method (Orsi 2022, chapter 2).  Each time step is a quasi-steady
    Stokes problem solved by outer iterations of SIMPLEC (momentum
    prediction with the explicit dev(T(grad U)) term, under-relaxation, two
    pressure corrections) with the particle force density lambda as source.

    Flow is driven by moving walls (Couette), cyclic patches and an imposed
    uniform mean pressure gradient (constant/flowProperties).

    Rigid spheres (constant/particleProperties) enter through lambda: after
    each SIMPLEC iteration the particle velocities are solved (eq 2.43) and
    lambda and U corrected (eq 2.53).  Particles move between steps by
    Adams-Bashforth.  A fresh start first solves at the initial positions so
    that every written time holds positions, velocities and fields of the
    same configuration.  Without particles lambda stays zero and the solver
    is a plain Stokes solver.

    Each time step ends with one summary line (Step N  Time = t  strain
    outer lambdaResidual contacts smallestGap stepTime timeLeft); -quiet
    leaves only these lines, the set-up and the warnings.

Usage
    fdmSuspensionFoam [-parallel] [-case dir] [-quiet]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "fdmOuterLoopControl.H"
#include "meanPressureGradient.H"
#include "relativeChange.H"
#include "fdmParticleCloud.H"
#include "momentumBalance.H"
#include "clockTime.H"
#include "andersonAcceleration.H"
#include "sumOverRanks.H"
#include "outerState.H"
#include "checkKeywords.H"
#include "checkTimeControls.H"
#include "incompleteWrites.H"
#include "readableDictionaries.H"
#include "layerMeanCorrection.H"
#include "transposeViscousTerm.H"
#include "shareLeesEdwardsCoupling.H"
#include "evaluateCoupledPatches.H"
#include "leesEdwardsShear.H"
#include "schemeEntries.H"
#include "heapReuse.H"
#include "planeWalls.H"
#include "remainingTime.H"
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- Whether runTime.loop() takes another step (Time::run's own test, without
//  its calls to the function objects).  The velocities of a solve that no
//  step follows move nothing: the single steady solve at endTime 0 of
//  subGridCalibration and of the validations, whose deltaT is not a step
static bool stepFollows(const Foam::Time& runTime)
{
    return
        runTime.value()
      < runTime.endTime().value() - 0.5*runTime.deltaTValue();
}


//- The application's note and its own option (-quiet)
static void addOptions()
{
    Foam::argList::addNote
    (
        "Stokes-flow solver for particle-resolved suspensions"
        " (Fictitious Domain Method, SIMPLEC)"
    );

    Foam::argList::addBoolOption
    (
        "quiet",
        "One summary line per time step: no linear-solver, outer-iteration,"
        " contact or timing lines (warnings and errors stay)"
    );
}


int main(int argc, char *argv[])
{
    addOptions();

    // Temporary fields reuse freed heap memory instead of fresh pages
    fdm::keepFreedMemory();

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    fdm::checkDictionariesReadable(args.rootPath()/args.globalCaseName());
    fdm::setAsideIncompleteWrites(args);
    #include "createTime.H"
    fdm::checkTimeControls(runTime);
    fdm::checkDictionariesReadable(runTime.timePath(), {"U", "p", "lambda"});
    #include "createMesh.H"
    #include "createFields.H"
    #include "initContinuityErrs.H"

    // Function objects read (and their keywords checked) now rather than
    // at the first runTime.loop(), after the initial solve; loop() keeps
    // them (functionObjectList::read re-reads only changed dictionaries)
    runTime.functionObjects().start();

    #include "createRunControls.H"

    particles.prepare(lambda);
    if (!particles.empty() && !particles.solved())
    {
        Info<< "Solving at the initial particle positions, time = "
            << runTime.timeName() << nl << endl;
        #include "stokesSolve.H"
        // The start time shows the particles too (paraFoam, .foam)
        particles.writeLagrangian();
    }
    else if (!particles.empty() && stepFollows(runTime))
    {
        // Velocities read from the start time, perhaps written with another
        // deltaT: the first step moves by them
        particles.checkMotionResolved(runTime.deltaTValue());
    }
    // State at the start time: solved above or read from a restart
    particles.writeTimeSeries();
    particles.writeVTK();

    Info<< "\nStarting time loop\n" << endl;
    #include "createTimeLeft.H"

    while (runTime.loop())
    {
        if (!quiet)
        {
            Info<< "Time = " << runTime.timeName() << nl << endl;
        }

        particles.move(runTime.deltaTValue(), lambda);

        #include "stokesSolve.H"

        if (!quiet)
        {
            #include "continuityErrs.H"
        }

        #include "writeResults.H"

        #include "reportTimings.H"
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
