/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "fdmOuterLoopControl.H"
#include "OStringStream.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdmOuterLoopControl::fdmOuterLoopControl
(
    const fvMesh& mesh,
    const word& algorithmName
)
:
    mesh_(mesh),
    algorithmName_(algorithmName),
    nCorrectors_(2),
    nCorrectorsBetweenRecords_(2),
    momentumPredictor_(true),
    momentumPredictorBetweenRecords_(true),
    nOuterCorrectors_(1),
    outerTolerance_(0),
    accelerationDepth_(0),
    accelerationRestart_(false),
    layerMeanCorrection_(false),
    layerMeanViscosityRatio_(16),
    RhieChowFactor_(0),
    iteration_(0),
    changeU_(GREAT),
    residualU_(GREAT),
    residualp_(GREAT),
    hasLambda_(false),
    lambdaResidual_(GREAT),
    lambdaTolerance_(0),
    particleIterations_(0),
    verbose_(true),
    smallestMeasure_(GREAT),
    velocityScale_(0)
{
    read();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::dictionary& Foam::fdmOuterLoopControl::dict() const
{
    return mesh_.solutionDict().subDict(algorithmName_);
}


const Foam::dictionary& Foam::fdmOuterLoopControl::solverDict
(
    const word& field,
    const bool betweenRecords
) const
{
    const word loose(field + "BetweenRecords");
    const bool found =
        betweenRecords
     && mesh_.solutionDict().subDict("solvers").found(loose);
    return mesh_.solverDict(found ? loose : field);
}


void Foam::fdmOuterLoopControl::start()
{
    read();
    iteration_ = 0;
    changeU_ = GREAT;
    residualU_ = GREAT;
    residualp_ = GREAT;
    hasLambda_ = false;
    lambdaResidual_ = GREAT;
    smallestMeasure_ = GREAT;
    velocityScale_ = 0;
}


void Foam::fdmOuterLoopControl::checkDivergence
(
    const scalar measure,
    const char* name
)
{
    smallestMeasure_ = min(smallestMeasure_, measure);
    const scalar growth = 1e4;
    const bool grown = measure > 1 && measure > growth*smallestMeasure_;
    if (std::isfinite(measure) && !grown)
    {
        return;
    }
    OStringStream what;
    what<< name << ' ' << measure << ", its smallest value in this step "
        << smallestMeasure_;
    diverged(what.str());
}


void Foam::fdmOuterLoopControl::diverged(const string& what) const
{
    const bool relaxed = mesh_.relaxEquation("U");
    FatalErrorInFunction
        << algorithmName_ << " outer iteration diverged at time "
        << mesh_.time().timeName() << ", outer iteration " << iteration_
        << ": " << what.c_str() << "." << nl
        << "    Nothing of this step is written; the last written time is"
        << " the last good state." << nl
        // The file by its path: on the other ranks the dictionary came
        // through a stream and is named after it
        << "    Lower the U relaxation factor in "
        << mesh_.time().globalPath()/mesh_.time().system()/"fvSolution"
        << " (now " << (relaxed ? mesh_.equationRelaxationFactor("U") : 1)
        << ", thesis 0.9)"
        << (
               accelerationDepth_ > 0 ? ""
             : ", set acceleration anderson in its " + algorithmName_
             + " block (now none)"
           )
        << ", or lower deltaT (now " << mesh_.time().deltaTValue()
        << ")." << exit(FatalError);
}


void Foam::fdmOuterLoopControl::setResiduals
(
    const scalar changeU,
    const scalar residualU,
    const scalar residualp,
    const scalar maxU
)
{
    if (velocityScale_ == 0)
    {
        velocityScale_ = maxU;
    }
    else if (!(maxU < 1e6*velocityScale_))
    {
        OStringStream what;
        what<< "largest cell velocity " << maxU << ", 1e6 times that of"
            << " the step's first outer iteration (" << velocityScale_ << ")";
        diverged(what.str());
    }
    changeU_ = changeU;
    residualU_ = residualU;
    residualp_ = residualp;

    if (!hasLambda_)
    {
        checkDivergence(changeU_, "relative change of U");
    }
    const scalar all = changeU_ + residualU_ + residualp_;
    if (!std::isfinite(all))
    {
        checkDivergence(all, "relative change of U or a linear residual");
    }
}


void Foam::fdmOuterLoopControl::setLambdaResidual
(
    const scalar residual,
    const scalar tolerance,
    const label particleIterations
)
{
    hasLambda_ = true;
    lambdaResidual_ = residual;
    lambdaTolerance_ = tolerance;
    particleIterations_ = particleIterations;

    checkDivergence(residual, "force-density residual (eq 2.54)");
}


bool Foam::fdmOuterLoopControl::converged() const
{
    return
        hasLambda_
      ? lambdaResidual_ < lambdaTolerance_
      : changeU_ < outerTolerance_;
}


bool Foam::fdmOuterLoopControl::loop()
{
    if (iteration_ > 0 && verbose_)
    {
        Info<< algorithmName_ << ": outer iteration " << iteration_;
        if (hasLambda_)
        {
            Info<< ", lambda residual " << lambdaResidual_
                << ", particle solve " << particleIterations_ << " its";
        }
        Info<< ", relative change U " << changeU_ << " (initial residuals ";
        if (momentumPredictor_)
        {
            Info<< "U " << residualU_ << ", ";
        }
        Info<< "p " << residualp_ << ")" << endl;
    }

    if (iteration_ > 0 && converged())
    {
        if (verbose_)
        {
            Info<< algorithmName_ << ": converged in " << iteration_
                << " outer iterations" << nl << endl;
        }
        return false;
    }

    const scalar tolerance = hasLambda_ ? lambdaTolerance_ : outerTolerance_;
    if (iteration_ >= nOuterCorrectors_ && tolerance == 0)
    {
        if (verbose_)
        {
            Info<< algorithmName_ << ": fixed count of " << iteration_
                << " outer iterations done" << nl << endl;
        }
        return false;
    }
    if (iteration_ >= nOuterCorrectors_)
    {
        WarningInFunction
            << algorithmName_ << " not converged after " << iteration_
            << " outer iterations (nOuterCorrectors in " << dict().name()
            << "): "
            << (hasLambda_ ? "lambda residual " : "relative change of U ")
            << (hasLambda_ ? lambdaResidual_ : changeU_) << " above "
            << (hasLambda_ ? "lambdaTolerance " : "outerTolerance ")
            << tolerance << ". Raise nOuterCorrectors or the tolerance."
            << nl << endl;
        return false;
    }

    ++iteration_;
    return true;
}


// ************************************************************************* //
