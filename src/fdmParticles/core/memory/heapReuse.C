/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "heapReuse.H"
#include <climits>
#include <malloc.h>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::fdm::keepFreedMemory()
{
    // No block from mmap (whose pages go back to the kernel when freed),
    // and no release of the heap's free top
    const bool noMmap = mallopt(M_MMAP_MAX, 0) == 1;
    const bool noTrim = mallopt(M_TRIM_THRESHOLD, INT_MAX) == 1;
    return noMmap && noTrim;
}


// ************************************************************************* //
