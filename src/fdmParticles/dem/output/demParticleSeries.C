/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demParticleSeries.H"
#include "particleList.H"
#include "Time.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::particleHDF5Metadata::description
Foam::fdm::demParticleSeries::description(const lubricatedDEM& dem) const
{
    const periodicBox& box = dem.box();
    const point hi = box.min() + box.span();
    std::string groupNames;
    for (const word& g : groupNames_)
    {
        groupNames += g + "\n";
    }
    particleHDF5Metadata::description d;
    d.text =
    {
        {"solver", "lubricatedDEMFoam (libfdmParticles)"},
        {"openfoamApi", std::to_string(OPENFOAM)},
        {"case", runTime_.globalPath()},
        {"groupNames", groupNames},
        {"particleProperties", properties_}
    };
    d.numbers =
    {
        {"viscosity", {dem.model().viscosity()}},
        {"shearRate", {dem.shearRate()}},
        {"boxMin", {box.min().x(), box.min().y(), box.min().z()}},
        {"boxMax", {hi.x(), hi.y(), hi.z()}},
        {
            "periodic",
            {
                double(box.periodic(0)), double(box.periodic(1)),
                double(box.periodic(2))
            }
        }
    };
    return d;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::demParticleSeries::demParticleSeries
(
    const Time& runTime,
    const dictionary& props
)
:
    runTime_(runTime)
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
    dictionary parameters(props);
    parameters.remove("particles");
    OStringStream entries;
    parameters.write(entries, false);
    properties_ = entries.str();
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
            dem.stresslets(lubricatedDEM::normalLubrication)[i]
          + dem.stresslets(lubricatedDEM::shearLubrication)[i];
        trace[i] = tr(S);
        lubrication[i] = dev(S);
        contact[i] =
            dem.stresslets(lubricatedDEM::normalContact)[i]
          + dem.stresslets(lubricatedDEM::shearContact)[i];
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
