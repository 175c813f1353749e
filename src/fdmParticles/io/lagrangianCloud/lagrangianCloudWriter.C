/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "lagrangianCloudWriter.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lagrangianCloudWriter::lagrangianCloudWriter
(
    const fvMesh& mesh,
    const word& cloudName,
    const UList<point>& positions
)
:
    mesh_(mesh),
    cloud_(mesh, cloudName, IDLList<passiveParticle>())
{
    DynamicList<label> owned(positions.size());
    forAll(positions, i)
    {
        const label celli = mesh.findCell(positions[i]);
        if (celli >= 0)
        {
            cloud_.addParticle(new passiveParticle(mesh, positions[i], celli));
            owned.append(i);
        }
    }
    owned_.transfer(owned);

    // Positions (and, v1912 and later, the barycentric coordinates)
    cloud_.write();
}


// ************************************************************************* //
