/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    Reading and checking the SIMPLEC block of fvSolution, the relaxation of
    U and the solvers of the steps between records.

\*---------------------------------------------------------------------------*/

#include "fdmOuterLoopControl.H"
#include "checkKeywords.H"

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
            "nCorrectors", "nCorrectorsBetweenRecords", "momentumPredictor",
            "momentumPredictorBetweenRecords",
            "nOuterCorrectors", "outerTolerance",
            "pRefCell", "pRefValue", "pRefPoint", "acceleration",
            "accelerationDepth", "accelerationRestart",
            "layerMeanCorrection",
            "layerMeanViscosityRatio", "RhieChowFactor"
        },
        algorithmName_ + " block"
    );

    nCorrectors_ = readCount(d, "nCorrectors", -1, " (thesis: 2)");
    nCorrectorsBetweenRecords_ = readCount
    (
        d, "nCorrectorsBetweenRecords", nCorrectors_, " (default: nCorrectors)"
    );
    momentumPredictor_ = d.getOrDefault<bool>("momentumPredictor", true);
    momentumPredictorBetweenRecords_ = d.getOrDefault<bool>
    (
        "momentumPredictorBetweenRecords", momentumPredictor_
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
    const wordList allowed({"UBetweenRecords", "pBetweenRecords"});
    for (const entry& e : solvers)
    {
        const keyType& key = e.keyword();
        const bool looksLike =
            !key.isPattern()
         && (
                key.find("etween") != std::string::npos
             || key.find("ecord") != std::string::npos
            );
        if (looksLike)
        {
            fdm::checkChoice(solvers, "solver", key, allowed);
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
        accelerationDepth_ = readCount(d, "accelerationDepth", 8, "");
        accelerationRestart_ =
            d.getOrDefault<bool>("accelerationRestart", false);
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


// ************************************************************************* //
