/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demVTK.H"
#include "Time.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::demVTK::demVTK(const Time& runTime, const dictionary& output)
:
    writer_(runTime.globalPath()/"VTK", runTime.value()),
    interval_(fdm::particleVTKWriter::readInterval(output))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::demVTK::write
(
    const lubricatedDEM& dem,
    const Time& runTime,
    const label step
)
{
    if
    (
        step > 0
     && !fdm::particleVTKWriter::due(interval_, step, runTime.writeTime())
    )
    {
        return;
    }
    List<vector> U(dem.size());
    forAll(U, i)
    {
        U[i] = dem.labVelocity(i);
    }
    symmTensorField S(dem.size(), Zero);
    for (label p = 0; p < fdm::lubricatedInteraction::nStressParts; ++p)
    {
        S += dem.stresslets(p);
    }
    auto file = writer_.particles
    (
        runTime.timeName(), runTime.value(), dem.positions()
    );
    file.write("id", labelList(identity(dem.size())));
    file.write("radius", dem.radii());
    file.write("velocity", U);
    file.write("angularVelocity", dem.spins());
    file.write("force", dem.forces());
    file.write("torque", dem.torques());
    file.write("stresslet", S);
    for (label p = 0; p < fdm::lubricatedInteraction::nStressParts; ++p)
    {
        file.write
        (
            "stresslet_" + word(fdm::lubricatedInteraction::stressPartName(p)),
            dem.stresslets(p)
        );
    }
    file.close();
    writer_.contacts
    (
        runTime.timeName(), runTime.value(), dem.positions(),
        dem.network()
    );
}


// ************************************************************************* //
