/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleList.H"
#include "IFstream.H"
#include "ITstream.H"
#include "OSspecific.H"
#include "pairSearch.H"
#include "fpTrapsOff.H"
#include "isFinite.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

void expectPunctuation
(
    Istream& is,
    const token::punctuationToken p,
    const string& what
)
{
    token t(is);
    if (!(t.isPunctuation() && t.pToken() == p))
    {
        FatalIOErrorInFunction(is)
            << "Expected '" << char(p) << "' " << what << " in "
            << is.name() << " but found " << t.info() << nl
            << "    each particle is a row (group (x y z) radius)"
            << exit(FatalIOError);
    }
}


//- The stream of the inline list or of the particlesFile
autoPtr<Istream> openParticleList
(
    const dictionary& dict,
    const fileName& constantDir,
    const bool inlineList
)
{
    autoPtr<Istream> isPtr;
    if (inlineList)
    {
        isPtr.reset(new ITstream(dict.lookup("particles")));
    }
    else
    {
        const fileName file =
            constantDir/dict.get<fileName>("particlesFile");
        if (!isFile(file))
        {
            FatalIOErrorInFunction(dict)
                << "particlesFile " << file << " named in " << dict.name()
                << " does not exist" << exit(FatalIOError);
        }
        isPtr.reset(new IFstream(file));
    }
    return isPtr;
}


//- Read the rows (group (x y z) radius) of the list into list; returns the
//  count written before the list, -1 without one
label readRows(Istream& is, fdm::particleList& list)
{
    token first(is);
    label count = -1;
    if (first.isLabel())
    {
        // Optional count before the list, as OpenFOAM writes lists
        count = first.labelToken();
        first = token(is);
    }
    if (!(first.isPunctuation() && first.pToken() == token::BEGIN_LIST))
    {
        FatalIOErrorInFunction(is)
            << "Expected a list of particles in " << is.name()
            << " but found " << first.info() << nl
            << "    each particle is a row (group (x y z) radius)"
            << exit(FatalIOError);
    }

    while (true)
    {
        token t(is);
        if (t.isPunctuation() && t.pToken() == token::END_LIST)
        {
            break;
        }
        if (!t.good() || is.eof())
        {
            FatalIOErrorInFunction(is)
                << "Unterminated particle list in " << is.name()
                << exit(FatalIOError);
        }
        is.putBack(t);
        expectPunctuation(is, token::BEGIN_LIST, "at the start of a row");
        word g;
        point x;
        scalar a;
        is >> g >> x >> a;
        expectPunctuation(is, token::END_LIST, "at the end of a row");

        if (!fdm::isFinite(a) || !fdm::isFinite(x))
        {
            FatalIOErrorInFunction(is)
                << "Particle " << list.group.size() << " in " << is.name()
                << " has a position or radius that is not a finite number"
                << " (" << x << ' ' << a << ")" << exit(FatalIOError);
        }

        list.group.append(g);
        list.position.append(x);
        list.radius.append(a);
    }
    return count;
}


} // namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::fdm::particleList Foam::fdm::readParticleList
(
    const dictionary& dict,
    const fileName& constantDir
)
{
    const bool inlineList = dict.found("particles");
    const bool fromFile = dict.found("particlesFile");
    if (inlineList == fromFile)
    {
        FatalIOErrorInFunction(dict)
            << dict.name() << " needs exactly one of the keywords"
            << " 'particles' (inline list) and 'particlesFile' (file name"
            << " relative to constant/)" << exit(FatalIOError);
    }

    // A number out of range is the parser's error, not a trap
    fpTrapsOff trapsOff;
    autoPtr<Istream> isPtr(openParticleList(dict, constantDir, inlineList));
    Istream& is = isPtr();

    particleList list;
    list.source = inlineList ? fileName(dict.name()) : is.name();
    const label count = readRows(is, list);

    if (count >= 0 && count != list.group.size())
    {
        FatalIOErrorInFunction(is)
            << "The particle list in " << is.name() << " announces " << count
            << " particles but holds " << list.group.size() << " rows" << nl
            << "    correct the count before the list or remove it"
            << exit(FatalIOError);
    }
    if (list.group.empty())
    {
        FatalIOErrorInFunction(is)
            << "The particle list in " << is.name() << " is empty" << nl
            << "    for a particle-free flow remove constant/"
            << "particleProperties; otherwise list rows (group (x y z) radius)"
            << exit(FatalIOError);
    }

    return list;
}


void Foam::fdm::checkParticleList
(
    const UList<point>& positions,
    const UList<scalar>& radii,
    const periodicBox& box,
    const fileName& file
)
{
    List<point> wrapped(positions.size());
    forAll(positions, p)
    {
        const scalar a = radii[p];
        if (!(a > 0))
        {
            FatalErrorInFunction
                << "Particle " << p << " in " << file << " has radius " << a
                << ": allowed values are > 0" << exit(FatalError);
        }
        for (direction d = 0; d < 3; ++d)
        {
            const scalar lo = box.min()[d];
            const scalar hi = lo + box.span()[d];
            const scalar x = positions[p][d];
            if (!box.periodic(d) && (x - a < lo || x + a > hi))
            {
                FatalErrorInFunction
                    << "Particle " << p << " in " << file << " at "
                    << positions[p] << " with radius " << a
                    << " is not inside the domain: along direction "
                    << vector::componentNames[d] << " it must lie within ["
                    << lo + a << ", " << hi - a << "] (the domain spans ["
                    << lo << ", " << hi << "])." << exit(FatalError);
            }
        }
        wrapped[p] = box.wrap(positions[p]);
    }

    DynamicList<labelPair> overlapping;
    findNearPairs(box, wrapped, radii, 0, overlapping);
    if (overlapping.empty())
    {
        return;
    }
    const label p = overlapping.first().first();
    const label q = overlapping.first().second();
    const scalar distance =
        mag(box.minimumImage(wrapped[q] - wrapped[p]));
    FatalErrorInFunction
        << overlapping.size() << " overlapping particle pair(s) in " << file
        << ", the first: particles " << p << " at " << positions[p]
        << " (radius " << radii[p] << ") and " << q << " at " << positions[q]
        << " (radius " << radii[q] << "), centre distance " << distance
        << " < " << radii[p] + radii[q]
        << (distance < SMALL*radii[p] ? " (the same row twice?)" : "")
        << nl << "    Move them apart: an initial list may not overlap"
        << " (fdmPackParticles keeps a clearance --gap)" << exit(FatalError);
}


// ************************************************************************* //
