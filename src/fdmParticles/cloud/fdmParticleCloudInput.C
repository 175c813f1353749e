/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    Reading of constant/particleProperties: coupling parameters, groups and
    the particle list (inline or from a file), and of the particle state of
    the start time.

\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "particleList.H"
#include "particleStateFile.H"
#include "checkKeywords.H"
#include "readBounded.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

void requirePositive
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const bool allowZero = false
)
{
    if (!(value > 0 || (allowZero && value == 0)))
    {
        FatalIOErrorInFunction(dict)
            << key << ' ' << value << " in " << dict.name()
            << ": allowed values are " << (allowZero ? ">= 0" : "> 0")
            << exit(FatalIOError);
    }
}


} // namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdmParticleCloud::readCoupling()
{
    const dictionary& c = dict_.subDict("coupling");
    fdm::checkKeywords
    (
        c,
        {
            "lambdaTolerance", "lambdaToleranceFirstStep",
            "lambdaToleranceBetweenRecords",
            "particleSolveTolerance", "alphaLambdaFactor", "overlaps",
            "maxParticleCourant", "positionScheme", "parallelParticleSolve"
        },
        "coupling block"
    );

    const word overlaps(c.getOrDefault<word>("overlaps", "thesis"));
    fdm::checkChoice(c, "overlaps", overlaps, {"thesis", "consistent"});
    consistentOverlaps_ = (overlaps == "consistent");

    const word scheme
    (
        c.getOrDefault<word>("positionScheme", "adamsBashforth2")
    );
    fdm::checkChoice
    (
        c, "positionScheme", scheme, {"adamsBashforth2", "euler"}
    );
    positionScheme_ =
        scheme == "euler"
      ? fdm::positionScheme::euler
      : fdm::positionScheme::adamsBashforth2;

    const word solve
    (
        c.getOrDefault<word>("parallelParticleSolve", "replicated")
    );
    fdm::checkChoice
    (
        c, "parallelParticleSolve", solve, {"replicated", "distributed"}
    );
    distributedSolve_ = (solve == "distributed");

    fdm::lambdaTolerances& t = lambdaTolerances_;
    t.recorded = c.get<scalar>("lambdaTolerance");
    requirePositive(c, "lambdaTolerance", t.recorded, true);
    t.firstSolve =
        c.getOrDefault<scalar>("lambdaToleranceFirstStep", t.recorded);
    requirePositive(c, "lambdaToleranceFirstStep", t.firstSolve, true);
    t.betweenRecords = fdm::readBoundedOrDefault
    (
        c, "lambdaToleranceBetweenRecords", t.recorded, t.recorded, GREAT,
        "at least lambdaTolerance: the steps that write nothing are solved"
        " as tightly as the others or less"
    );
    solveTolerance_ = c.get<scalar>("particleSolveTolerance");
    requirePositive(c, "particleSolveTolerance", solveTolerance_);

    maxCourant_ = c.getOrDefault<scalar>("maxParticleCourant", 1);
    requirePositive(c, "maxParticleCourant", maxCourant_);

    const scalar factor = c.getOrDefault<scalar>("alphaLambdaFactor", 1);
    requirePositive(c, "alphaLambdaFactor", factor);

    // alpha_lambda: viscous diffusion time over one cell (eq 2.41)
    alphaLambda_ = factor*sqr(delta_)/nu_;

    const dictionary ind(dict_.subOrEmptyDict("indicator"));
    fdm::checkKeywords(ind, {"b", "c"}, "indicator block");
    const scalar b = ind.getOrDefault<scalar>("b", 5);
    const scalar cc = ind.getOrDefault<scalar>("c", 0.3);
    requirePositive(ind, "b", b);
    requirePositive(ind, "c", cc, true);
    indicator_ = fdm::indicatorFunctions(b, cc, delta_);
}


void Foam::fdmParticleCloud::readGroups()
{
    groups_.clear();
    const dictionary* gPtr = dict_.findDict("groups");
    if (gPtr)
    {
        for (const entry& e : *gPtr)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(*gPtr)
                    << "Entry " << e.keyword() << " in " << gPtr->name()
                    << " is not a dictionary: each group is"
                    << " name { density ..; translation ..; ... }"
                    << exit(FatalIOError);
            }
            groups_.append(particleGroup(e.keyword(), e.dict(), rhoFluid_));
        }
    }
}


Foam::label Foam::fdmParticleCloud::groupIndex
(
    const word& name,
    const dictionary& where
) const
{
    forAll(groups_, g)
    {
        if (groups_[g].name() == name)
        {
            return g;
        }
    }

    wordList names(groups_.size());
    forAll(groups_, g)
    {
        names[g] = groups_[g].name();
    }
    FatalIOErrorInFunction(where)
        << "Particle group " << name << " used in " << where.name()
        << " is not defined in its groups dictionary" << nl
        << "    defined groups: " << names << exit(FatalIOError);
    return -1;
}


void Foam::fdmParticleCloud::readParticles()
{
    fdm::particleList list =
        fdm::readParticleList
        (
            dict_, mesh_.time().globalPath()/mesh_.time().constant()
        );

    // The list is the state of time 0: a Lees-Edwards box's images at
    // offset 0 (a restart has moved them on; its particleState follows)
    fdm::periodicBox listBox(box_);
    if (box_.shearOffset() != 0)
    {
        listBox.setShearOffset(0);
    }
    state_.group.setSize(list.group.size());
    forAll(list.group, i)
    {
        state_.group[i] = groupIndex(list.group[i], dict_);
        list.position[i] = listBox.wrap(list.position[i]);
    }
    fdm::checkParticleList(list.position, list.radius, listBox, list.source);
    state_.radius.transfer(list.radius);
    state_.position.transfer(list.position);
}


void Foam::fdmParticleCloud::readState()
{
    const fileName file =
        mesh_.time().globalPath()/mesh_.time().timeName()/"particleState";
    if (!fdm::continuesFromParticleState(mesh_.time(), file, dict_.name()))
    {
        return;
    }

    Info<< "    continuing from " << file << nl;
    const dictionary state(fdm::readParticleStateFile(file));

    const label n = state.get<label>("nParticles");
    if (n != size())
    {
        FatalIOErrorInFunction(state)
            << file << " holds " << n << " particles but "
            << dict_.name() << " lists " << size() << exit(FatalIOError);
    }

    const scalarField radius(state.get<scalarField>("radius"));
    const scalar change = max(mag(radius - state_.radius));
    const bool accept = dict_.getOrDefault("acceptChangedRadii", false);
    if (change > 1e-12*max(state_.radius) && !accept)
    {
        FatalIOErrorInFunction(dict_)
            << "The particle radii in " << dict_.name() << " differ from"
            << " those of the run being continued, " << file
            << " (largest change " << change << ")." << nl
            << "    Restore the list, start at time 0, or set"
            << " acceptChangedRadii true; in " << dict_.name()
            << " to continue with the new radii" << exit(FatalIOError);
    }

    state_.position = state.get<pointField>("position");
    state_.U = state.get<List<vector>>("velocity");
    state_.Omega = state.get<List<vector>>("angularVelocity");
    state_.Uold = state.get<List<vector>>("previousVelocity");
    hydro_.force = state.get<List<vector>>("force");
    hydro_.torque = state.get<List<vector>>("torque");
    state.readIfPresent("stresslet", hydro_.stresslet);
    state.readIfPresent("dipoleTrace", dipoleTrace_);
    // With the contact loads at the solved state (explicit part plus the
    // implicit stiffness' share), so that the record at the restart time is
    // the one the interrupted run wrote
    contacts_->readState(state, contact_);
    solved_ = state.get<bool>("solved");
    // The step of the previous velocities; a state written before it was
    // kept took the current one
    historyDeltaT_ = state.get<bool>("hasHistory")
      ? state.getOrDefault<scalar>("historyDeltaT", mesh_.time().deltaTValue())
      : 0;
    // coldFluid: a state restored from a particle checkpoint with the
    // fields of time 0 (fdmPost.checkpoint): the Stokes flow has no memory,
    // but its first solve starts cold and is converged as at time 0
    firstSolveDone_ = solved_ && !state.getOrDefault("coldFluid", false);
}


// ************************************************************************* //
