/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "lagrangianCloudWriter.H"
#include "meshSearch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lagrangianCloudWriter::lagrangianCloudWriter
(
    const fvMesh& mesh,
    const word& cloudName,
    const UList<point>& positions,
    const UList<bool>& candidates
)
:
    mesh_(mesh),
    cloud_(mesh, cloudName, IDLList<passiveParticle>())
{
    // Each position found by a walk over the cells from the last one found
    // (polyMesh::findCell builds an octree of all cells first: 7 s at 10^6
    // cells, once per run); the octree only where a walk is stopped by a
    // non-convex processor domain
    const meshSearch search(mesh);
    const boundBox& bounds = mesh.bounds();
    label seed = 0;
    DynamicList<label> owned(positions.size());
    forAll(positions, i)
    {
        if
        (
            mesh.nCells() == 0
         || (candidates.size() && !candidates[i])
         || !bounds.contains(positions[i])
        )
        {
            continue;
        }
        label celli = search.findCell(positions[i], seed, false);
        if (celli < 0)
        {
            celli = mesh.findCell(positions[i]);
        }
        if (celli >= 0)
        {
            cloud_.addParticle(new passiveParticle(mesh, positions[i], celli));
            owned.append(i);
            seed = celli;
        }
    }
    owned_.transfer(owned);

    // Positions (and, v1912 and later, the barycentric coordinates)
    cloud_.write();
}


// ************************************************************************* //
