/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "leesEdwardsSide.H"
#include "fvMesh.H"
#include "Time.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::leesEdwardsSide::leesEdwardsSide
(
    const scalar shearRate,
    const bool jumps
)
:
    shearRate_(shearRate),
    jumps_(jumps),
    mapTimeIndex_(-1)
{}


Foam::fdm::leesEdwardsSide::leesEdwardsSide(const leesEdwardsSide& s)
:
    shearRate_(s.shearRate_),
    jumps_(s.jumps_),
    mapTimeIndex_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fdm::leesEdwardsSide::upper(const fvPatch& p)
{
    return p.size() && sum(p.Sf()).y() > 0;
}


Foam::scalar Foam::fdm::leesEdwardsSide::offset(const fvPatch& p) const
{
    return leesEdwardsOffset
    (
        shearRate_, p.boundaryMesh().mesh().bounds(),
        p.boundaryMesh().mesh().time().value()
    );
}


Foam::vector Foam::fdm::leesEdwardsSide::velocityJump(const fvPatch& p) const
{
    if (!jumps_)
    {
        return Zero;
    }
    const scalar du = shearRate_*p.boundaryMesh().mesh().bounds().span().y();
    return vector(upper(p) ? du : -du, 0, 0);
}


const Foam::fdm::leesEdwardsRowMap& Foam::fdm::leesEdwardsSide::map
(
    const fvPatch& p,
    const vectorField& rowCf,
    const word& fieldName
) const
{
    const label timeIndex = p.boundaryMesh().mesh().time().timeIndex();
    if (!map_.valid() || mapTimeIndex_ != timeIndex)
    {
        mapTimeIndex_ = timeIndex;
        map_.reset
        (
            new leesEdwardsRowMap
            (
                rowCf, p.Cf(), (upper(p) ? -1 : 1)*offset(p),
                p.boundaryMesh().mesh().bounds().span().x(),
                "Patch " + p.name() + " of field " + fieldName
            )
        );
    }
    return *map_;
}


// ************************************************************************* //
