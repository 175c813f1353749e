/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demParticleSeries.H"
#include "particleList.H"
#include "Time.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::particleHDF5Metadata::description
Foam::fdm::demParticleSeries::description(const lubricatedDEM& dem) const
{
    const periodicBox& box = dem.box();
    return particleHDF5Metadata::runDescription
    (
        "lubricatedDEMFoam (libfdmParticles)", runTime_.globalPath(),
        groupNames_, properties_, dem.model().viscosity(), dem.shearRate(),
        boundBox(box.min(), box.min() + box.span()), box.periodic()
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::demParticleSeries::demParticleSeries
(
    const Time& runTime,
    const dictionary& props
)
:
    runTime_(runTime),
    properties_(props)
{
    const particleList list =
        readParticleList(props, runTime.globalPath()/runTime.constant());
    group_.setSize(list.group.size());
    forAll(group_, i)
    {
        group_[i] = groupNames_.find(list.group[i]);
        if (group_[i] < 0)
        {
            group_[i] = groupNames_.size();
            groupNames_.append(list.group[i]);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::demParticleSeries::append(const lubricatedDEM& dem)
{
    const label n = dem.size();
    if (!writer_)
    {
        // A continued run recomputes the records after its start time;
        // the one at the start time, the state it starts from, stays
        writer_.reset
        (
            new particleHDF5Writer
            (
                runTime_.globalPath()/"postProcessing"/"particles.h5",
                scalarField(dem.radii()), group_,
                runTime_.startTime().value() + 0.5*runTime_.deltaTValue(),
                description(dem)
            )
        );
    }

    List<vector> U(n), lubricationForce(n), lubricationTorque(n);
    List<symmTensor> lubrication(n), contact(n);
    List<scalar> trace(n);
    forAll(U, i)
    {
        U[i] = dem.labVelocity(i);
        lubricationForce[i] =
            dem.forces()[i] - dem.bodyForces()[i] - dem.contactForces()[i];
        lubricationTorque[i] = dem.torques()[i] - dem.contactTorques()[i];
        const symmTensor S =
            dem.stresslets(lubricatedInteraction::normalLubrication)[i]
          + dem.stresslets(lubricatedInteraction::shearLubrication)[i];
        trace[i] = tr(S);
        lubrication[i] = dev(S);
        contact[i] =
            dem.stresslets(lubricatedInteraction::normalContact)[i]
          + dem.stresslets(lubricatedInteraction::shearContact)[i];
    }
    writer_->append
    (
        runTime_.value(),
        {
            dem.positions(), U, dem.spins(), lubricationForce,
            lubricationTorque, lubrication, trace, dem.contactForces(),
            dem.contactTorques(), contact
        }
    );
}


void Foam::fdm::demParticleSeries::commit()
{
    if (writer_)
    {
        writer_->commit();
    }
}


// ************************************************************************* //
