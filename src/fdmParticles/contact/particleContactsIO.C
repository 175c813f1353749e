/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleContacts.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::particleContacts::checkGaps
(
    const key& closest,
    const bool acrossShear
) const
{
    const auto between = [&]()
    {
        OStringStream os;
        os  << "particle " << closest.first() << " and ";
        if (closest.second() >= 0)
        {
            os  << "particle " << closest.second();
        }
        else
        {
            os  << "wall " << -1 - closest.second();
        }
        os  << (acrossShear ? " (across the sheared faces)" : "");
        return os.str();
    };
    if (nContacts() && minGap_ < -law_->roughness())
    {
        FatalErrorInFunction
            << "Runaway overlap at time " << mesh_.time().timeName()
            << ": surfaces of " << between().c_str() << " overlap by "
            << -minGap_ << ", more than the"
            << " asperity height h_r = " << law_->roughness() << nl
            << "    The contact barrier (eq 2.57) was crossed within one"
            << " time step.  Reduce deltaT in system/controlDict, or"
            << " soften the contacts (larger meanDeformation or smaller kn"
            << " in constant/particleProperties contact).  The last written"
            << " time is the last good state." << exit(FatalError);
    }
    if (nBelowFloor_)
    {
        WarningInFunction
            << nBelowFloor_ << " contact gap(s) below the barrier floor"
            << " (gapFloor) at time " << mesh_.time().timeName()
            << ", smallest gap " << minGap_ << " (" << between().c_str()
            << "): their force is evaluated"
            << " at the floor.  Reduce deltaT if this repeats." << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleContacts::report() const
{
    const label nSliding =
        sharedCounts_ ? returnReduce(nSliding_, sumOp<label>()) : nSliding_;
    Info<< "Contacts: " << nPairs_ << " pairs, " << nWalls_ << " with walls, "
        << nSliding << " sliding";
    if (nContacts())
    {
        Info<< ", smallest gap " << minGap_;
    }
    Info<< endl;
}


Foam::fdm::pairHistory<Foam::vector>
Foam::particleContacts::wholeHistory() const
{
    DynamicList<labelPair> pairs;
    DynamicList<vector> slips;
    for (const contactEntry& e : contacts_)
    {
        if (e.counted)
        {
            pairs.append(e.k);
            slips.append(slip_[slip_.find(e.k)]);
        }
    }
    fdm::pairHistory<vector> whole;
    whole.reset(onMaster(pairs), onMaster(slips));
    return whole;
}


void Foam::particleContacts::readSlip(const dictionary& state)
{
    slip_.clear();
    if (!state.found("contactPairs"))
    {
        return;
    }
    const List<labelPair> keys(state.get<List<labelPair>>("contactPairs"));
    const List<vector> slips(state.get<List<vector>>("contactSlip"));
    if (keys.size() != slips.size())
    {
        FatalIOErrorInFunction(state)
            << "contactPairs and contactSlip in " << state.name()
            << " differ in length" << exit(FatalIOError);
    }
    if (!slip_.reset(keys, slips))
    {
        FatalIOErrorInFunction(state)
            << "contactPairs in " << state.name() << " lists a pair twice"
            << exit(FatalIOError);
    }
}


void Foam::particleContacts::writeState
(
    Ostream& os,
    const fdm::particleLoads& loads,
    const fdm::pairHistory<vector>& slip
) const
{
    os.writeEntry("contactForce", loads.force);
    os.writeEntry("contactTorque", loads.torque);
    os.writeEntry("contactStresslet", loads.stresslet);
    os.writeEntry("contactPairs", slip.pairs());
    os.writeEntry("contactSlip", slip.states());
}


void Foam::particleContacts::readState
(
    const dictionary& state,
    fdm::particleLoads& loads
)
{
    readSlip(state);
    loads.force = state.get<List<vector>>("contactForce");
    loads.torque = state.get<List<vector>>("contactTorque");
    loads.stresslet = state.get<List<symmTensor>>("contactStresslet");
}


// ************************************************************************* //
