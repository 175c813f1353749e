/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The pair history of the lubricated interaction as particleState
    entries (restart), and back.

\*---------------------------------------------------------------------------*/

#include "lubricatedInteraction.H"
#include "Ostream.H"
#include "dictionary.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::lubricatedInteraction::writePairs(Ostream& os) const
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


void Foam::fdm::lubricatedInteraction::readPairs
(
    const dictionary& dict,
    const boolList& mobile
)
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
    DynamicList<labelPair> kept(pairs.size());
    DynamicList<pairEntry> entries(pairs.size());
    forAll(pairs, k)
    {
        const labelPair& p = pairs[k];
        const bool twoParticles =
            p.first() >= 0 && p.first() < p.second()
         && p.second() < mobile.size();
        if (!twoParticles)
        {
            FatalIOErrorInFunction(dict)
                << dict.name() << ": pair " << p << " is not two particles"
                << " i < j of the " << mobile.size() << exit(FatalIOError);
        }
        if (mobile[p.first()] || mobile[p.second()])
        {
            kept.append(p);
            entries.append
            ({
                lubricatedPairState
                {
                    logGap[k], bool(contact[k]), shearForce[k]
                },
                bool(active[k])
            });
        }
    }
    if (!pairs_.reset(kept, entries))
    {
        FatalIOErrorInFunction(dict)
            << dict.name() << ": pairs lists a pair twice"
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
