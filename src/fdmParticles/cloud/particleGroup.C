/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleGroup.H"
#include "token.H"
#include "checkKeywords.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::particleGroup::motionMode Foam::particleGroup::readMotion
(
    const dictionary& dict,
    const word& key,
    vector& value
)
{
    value = Zero;
    const entry* ePtr = dict.findEntry(key, keyType::LITERAL);
    if (!ePtr)
    {
        return motionMode::free;
    }

    ITstream& is = ePtr->stream();
    token first(is);
    if (first.isWord())
    {
        if (first.wordToken() == "free")
        {
            return motionMode::free;
        }
        if (first.wordToken() == "fixed")
        {
            return motionMode::prescribed;
        }
    }
    else if (first.isPunctuation() && first.pToken() == token::BEGIN_LIST)
    {
        is.putBack(first);
        is >> value;
        return motionMode::prescribed;
    }

    FatalIOErrorInFunction(dict)
        << key << " in " << dict.name() << " is " << first.info() << nl
        << "    allowed values: free, fixed or a velocity vector (x y z)"
        << exit(FatalIOError);
    return motionMode::free;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleGroup::particleGroup(const word& name, const scalar rhoFluid)
:
    name_(name),
    density_(rhoFluid),
    translationMode_(motionMode::free),
    translation_(Zero),
    rotationMode_(motionMode::free),
    rotation_(Zero),
    force_(Zero),
    torque_(Zero)
{}


Foam::particleGroup::particleGroup
(
    const word& name,
    const dictionary& dict,
    const scalar rhoFluid
)
:
    name_(name),
    density_(dict.getOrDefault<scalar>("density", rhoFluid)),
    translationMode_(motionMode::free),
    translation_(Zero),
    rotationMode_(motionMode::free),
    rotation_(Zero),
    force_(dict.getOrDefault<vector>("force", Zero)),
    torque_(dict.getOrDefault<vector>("torque", Zero))
{
    translationMode_ = readMotion(dict, "translation", translation_);
    rotationMode_ = readMotion(dict, "rotation", rotation_);

    if (!(density_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "density " << density_ << " in " << dict.name()
            << ": allowed values are > 0" << exit(FatalIOError);
    }

    fdm::checkKeywords
    (
        dict,
        {"density", "translation", "rotation", "force", "torque"},
        "particle group " + name
    );
}


// ************************************************************************* //
