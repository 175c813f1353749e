/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "fdmOuterLoopControl.H"
#include "checkKeywords.H"
#include "OStringStream.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A count >= 1 of d: required (deflt < 0) or with the default deflt
Foam::label readCount
(
    const Foam::dictionary& d,
    const Foam::word& key,
    const Foam::label deflt,
    const char* note
)
{
    const Foam::label n =
        deflt < 0
      ? d.get<Foam::label>(key)
      : d.getOrDefault<Foam::label>(key, deflt);
    if (n < 1)
    {
        FatalIOErrorInFunction(d)
            << key << ' ' << n << " in " << d.name()
            << ": allowed values are integers >= 1" << note
            << Foam::exit(Foam::FatalIOError);
    }
    return n;
}

} // namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdmOuterLoopControl::read()
{
    const dictionary& d = dict();
    fdm::checkKeywords
    (
        d,
        {
            "nCorrectors", "nCorrectorsBetweenRecords",
            "nOuterCorrectors", "outerTolerance",
            "pRefCell", "pRefValue", "pRefPoint", "acceleration",
            "accelerationDepth", "layerMeanCorrection",
            "layerMeanViscosityRatio", "RhieChowFactor"
        },
        algorithmName_ + " block"
    );

    nCorrectors_ = readCount(d, "nCorrectors", -1, " (thesis: 2)");
    nCorrectorsBetweenRecords_ = readCount
    (
        d, "nCorrectorsBetweenRecords", nCorrectors_, " (default: nCorrectors)"
    );
    nOuterCorrectors_ = readCount(d, "nOuterCorrectors", -1, "");

    outerTolerance_ = d.get<scalar>("outerTolerance");
    if (!(outerTolerance_ >= 0))
    {
        FatalIOErrorInFunction(d)
            << "outerTolerance " << outerTolerance_ << " in " << d.name()
            << ": allowed values are >= 0" << exit(FatalIOError);
    }

    checkBetweenRecordsSolvers();
    readAcceleration(d);
    readLayerMeanCorrection(d);
    checkURelaxation();
    readRhieChowFactor(d);
}


void Foam::fdmOuterLoopControl::checkBetweenRecordsSolvers() const
{
    // Stock OpenFOAM ignores solvers no field asks for: a misspelt
    // UBetweenRecords would silently leave the steps at the U solver
    const dictionary& solvers = mesh_.solutionDict().subDict("solvers");
    const std::vector<std::string> allowed
        {"UBetweenRecords", "pBetweenRecords"};
    for (const entry& e : solvers)
    {
        const keyType& key = e.keyword();
        const bool looksLike =
            !key.isPattern()
         && (
                key.find("etween") != std::string::npos
             || key.find("ecord") != std::string::npos
            );
        const bool known =
            std::find(allowed.begin(), allowed.end(), key) != allowed.end();
        if (looksLike && !known)
        {
            FatalIOErrorInFunction(solvers)
                << "Unknown solver " << key << " in " << solvers.name()
                << ": did you mean "
                << word(fdm::nearestSpelling(key, allowed))
                << "? Allowed: UBetweenRecords, pBetweenRecords"
                << exit(FatalIOError);
        }
    }
}


void Foam::fdmOuterLoopControl::readAcceleration(const dictionary& d)
{
    const word acceleration = d.getOrDefault<word>("acceleration", "none");
    if (acceleration == "none")
    {
        accelerationDepth_ = 0;
    }
    else if (acceleration == "anderson")
    {
        accelerationDepth_ = d.getOrDefault<label>("accelerationDepth", 8);
        if (accelerationDepth_ < 1)
        {
            FatalIOErrorInFunction(d)
                << "accelerationDepth " << accelerationDepth_ << " in "
                << d.name() << ": allowed values are integers >= 1"
                << exit(FatalIOError);
        }
    }
    else
    {
        FatalIOErrorInFunction(d)
            << "acceleration " << acceleration << " in " << d.name()
            << ": allowed values are none (thesis outer iteration) and"
            << " anderson" << exit(FatalIOError);
    }
}


void Foam::fdmOuterLoopControl::readLayerMeanCorrection(const dictionary& d)
{
    layerMeanCorrection_ = d.getOrDefault<bool>("layerMeanCorrection", false);
    layerMeanViscosityRatio_ =
        d.getOrDefault<scalar>("layerMeanViscosityRatio", 16);
    if (!(layerMeanViscosityRatio_ >= 1 && layerMeanViscosityRatio_ < GREAT))
    {
        FatalIOErrorInFunction(d)
            << "layerMeanViscosityRatio " << layerMeanViscosityRatio_
            << " in " << d.name() << ": allowed values are finite numbers"
            << " >= 1 (16: validation/benchmarks/frozenCouette)"
            << exit(FatalIOError);
    }
}


void Foam::fdmOuterLoopControl::readRhieChowFactor(const dictionary& d)
{
    RhieChowFactor_ = d.getOrDefault<scalar>("RhieChowFactor", 0);
    const bool valid = RhieChowFactor_ > 0 && RhieChowFactor_ <= 1;
    if (d.found("RhieChowFactor") && !valid)
    {
        FatalIOErrorInFunction(d)
            << "RhieChowFactor " << RhieChowFactor_ << " in " << d.name()
            << ": allowed values are 0 < RhieChowFactor <= 1 (1: the"
            << " unrelaxed momentum diagonal; leave it out for the U"
            << " relaxation factor, the thesis scheme)"
            << exit(FatalIOError);
    }
}


void Foam::fdmOuterLoopControl::checkURelaxation() const
{
    const dictionary& solDict = mesh_.solutionDict();
    const bool relaxed = mesh_.relaxEquation("U");
    const scalar alpha = relaxed ? mesh_.equationRelaxationFactor("U") : 1;
    if (!(alpha > 0 && alpha < 1))
    {
        FatalIOErrorInFunction(solDict)
            << "relaxationFactors { equations { U ... } } in "
            << solDict.name() << (relaxed ? " is " : " is missing")
            << (relaxed ? Foam::name(alpha) : word::null) << nl
            << "    allowed values: 0 < U < 1 (thesis: 0.9). Without inertia"
            << " SIMPLEC's a_C - H_1 vanishes (thesis eq 2.36) and only"
            << " under-relaxation keeps it finite."
            << exit(FatalIOError);
    }
}


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
    nOuterCorrectors_(1),
    outerTolerance_(0),
    accelerationDepth_(0),
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
        << "    Lower the U relaxation factor in "
        << mesh_.solutionDict().name() << " (now "
        << (relaxed ? mesh_.equationRelaxationFactor("U") : 1)
        << ", thesis 0.9), set acceleration anderson in its "
        << algorithmName_ << " block (now "
        << (accelerationDepth_ > 0 ? "anderson" : "none")
        << "), or lower deltaT." << exit(FatalError);
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
        Info<< ", relative change U " << changeU_
            << " (initial residuals U " << residualU_
            << ", p " << residualp_ << ")" << endl;
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
