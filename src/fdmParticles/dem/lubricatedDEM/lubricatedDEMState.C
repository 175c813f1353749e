/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The restart state of the lubricated DEM (particleState entries): the
    particles, the stresslets (output only) and the pair history.

\*---------------------------------------------------------------------------*/

#include "lubricatedDEM.H"
#include "Ostream.H"
#include "dictionary.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::lubricatedDEM::writePairs(Ostream& os) const
{
    boolList active(pairs_.size());
    scalarList logGap(pairs_.size());
    boolList contact(pairs_.size());
    List<vector> shearForce(pairs_.size());
    forAll(active, k)
    {
        active[k] = pairs_[k].active;
        logGap[k] = pairs_[k].state.logGap;
        contact[k] = pairs_[k].state.contact;
        shearForce[k] = pairs_[k].state.shearForce;
    }
    os.writeEntry("pairs", pairs_.pairs());
    os.writeEntry("pairActive", active);
    os.writeEntry("pairLogGap", logGap);
    os.writeEntry("pairContact", contact);
    os.writeEntry("pairShearForce", shearForce);
}


void Foam::fdm::lubricatedDEM::readPairs(const dictionary& dict)
{
    const List<labelPair> pairs(dict.get<List<labelPair>>("pairs"));
    const boolList active(dict.get<boolList>("pairActive"));
    const scalarList logGap(dict.get<scalarList>("pairLogGap"));
    const boolList contact(dict.get<boolList>("pairContact"));
    const List<vector> shearForce(dict.get<List<vector>>("pairShearForce"));
    const bool onePerPair =
        active.size() == pairs.size() && logGap.size() == pairs.size()
     && contact.size() == pairs.size() && shearForce.size() == pairs.size();
    if (!onePerPair)
    {
        FatalIOErrorInFunction(dict)
            << dict.name() << ": pairActive, pairLogGap, pairContact and"
            << " pairShearForce must list one entry per pair (" << pairs.size()
            << " pairs)" << exit(FatalIOError);
    }
    List<pairEntry> entries(pairs.size());
    forAll(entries, k)
    {
        const labelPair& p = pairs[k];
        if (p.first() < 0 || p.first() >= p.second() || p.second() >= size())
        {
            FatalIOErrorInFunction(dict)
                << dict.name() << ": pair " << p << " is not two particles"
                << " i < j of the " << size() << exit(FatalIOError);
        }
        entries[k] =
        {
            lubricatedPairState{logGap[k], bool(contact[k]), shearForce[k]},
            bool(active[k])
        };
    }
    if (!pairs_.reset(pairs, entries))
    {
        FatalIOErrorInFunction(dict)
            << dict.name() << ": pairs lists a pair twice"
            << exit(FatalIOError);
    }
}


void Foam::fdm::lubricatedDEM::writeState(Ostream& os) const
{
    os.writeEntry("time", time_);
    os.writeEntry("nParticles", size());
    os.writeEntry("position", position_);
    os.writeEntry("velocity", velocity_);
    os.writeEntry("angularVelocity", spin_);
    os.writeEntry("radius", radius_);
    os.writeEntry("mobile", mobile_);
    for (label p = 0; p < nStressParts; ++p)
    {
        // Output only (local stress profiles); not read back
        os.writeEntry
        (
            word("stresslet_" + std::string(stressPartName(p))),
            stresslet_[p]
        );
    }

    writePairs(os);
    os.writeEntry("pairSelection", pairSelectionName());
    os.writeEntry("timeSinceSearch", timeSinceSearch_);
    os.writeEntry("stepsSinceSearch", stepsSinceSearch_);
    os.writeEntry("displacementSinceSearch", displacementSinceSearch_);
}


void Foam::fdm::lubricatedDEM::readState(const dictionary& dict)
{
    const label n = dict.get<label>("nParticles");
    if (n != size())
    {
        FatalIOErrorInFunction(dict)
            << dict.name() << " holds " << n << " particles but the case"
            << " lists " << size() << exit(FatalIOError);
    }
    const scalarList radius(dict.get<scalarList>("radius"));
    forAll(radius, i)
    {
        if (mag(radius[i] - radius_[i]) > 1e-12*radius_[i])
        {
            FatalIOErrorInFunction(dict)
                << dict.name() << ": particle " << i << " has radius "
                << radius[i] << " but the particle list gives " << radius_[i]
                << "; a restart continues the spheres that started the run"
                << " (restore the list, or start again at time 0)"
                << exit(FatalIOError);
        }
    }
    position_ = dict.get<List<point>>("position");
    velocity_ = dict.get<List<vector>>("velocity");
    spin_ = dict.get<List<vector>>("angularVelocity");

    readPairs(dict);
    timeSinceSearch_ = dict.get<scalar>("timeSinceSearch");
    stepsSinceSearch_ = dict.getOrDefault<label>("stepsSinceSearch", 0);
    displacementSinceSearch_ =
        dict.get<List<vector>>("displacementSinceSearch");

    // Pairs listed by another selection (the case's neighbours changed
    // since the state was written; states before the choice existed hold
    // cut-off pairs): search again at the first step
    const word selection
    (
        dict.getOrDefault<word>("pairSelection", "cutoff")
    );
    if (selection != pairSelectionName())
    {
        Info<< "    " << dict.name() << " lists " << selection
            << " pairs; the " << pairSelectionName()
            << " pairs are searched at the first step" << nl;
        timeSinceSearch_ = GREAT;
    }
    setTime(dict.get<scalar>("time"));
}


// ************************************************************************* //
