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

    Particle coupling (indicator functions, lambda correction, particle
    velocity solve) enters at the marked place of the outer loop; without
    particles lambda stays zero and the solver is a plain Stokes solver.

Usage
    fdmSuspensionFoam [-parallel] [-case dir]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "fdmOuterLoopControl.H"
#include "meanPressureGradient.H"
#include "relativeChange.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Stokes-flow solver for particle-resolved suspensions"
        " (Fictitious Domain Method, SIMPLEC)"
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createFields.H"
    #include "initContinuityErrs.H"

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.loop())
    {
        Info<< "Time = " << runTime.timeName() << nl << endl;

        outerLoop.start();

        while (outerLoop.loop())
        {
            // Initial residuals of this outer iteration (convergence control)
            scalar residualU = GREAT;
            scalar residualp = GREAT;
            U.storePrevIter();

            #include "UEqn.H"
            #include "pEqn.H"

            outerLoop.setResiduals
            (
                fdm::relativeChange(U.primitiveField(), U.prevIter()),
                residualU,
                residualp
            );

            // Particle sub-problem (eqs 2.41-2.45) enters here.
        }

        #include "continuityErrs.H"

        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
