/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "resistanceTable.H"
#include "error.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

constexpr Foam::scalar Foam::fdm::resistanceTable::defaultXMin;

const Foam::wordList Foam::fdm::resistanceTable::pairFunctionNames
({
    "XA21", "YA21", "YB21", "XC21", "YC11",
    "XG11", "YG11", "YH21", "XP12", "XP21"
});

const Foam::wordList Foam::fdm::resistanceTable::wallFunctionNames
({
    "XA", "YA", "YB", "XC", "YC", "XG", "XP"
});

const Foam::wordList Foam::fdm::resistanceTable::twoBodyFunctionNames
({
    "XA11", "XA12", "YA11", "YA12", "YB11", "YB12", "XC11", "XC12",
    "YC11", "YC12", "XG11", "XG12", "YG11", "YG12", "YH11", "YH12"
});


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::fdm::resistanceTable::defaultCutoff(const word& name)
{
    // Thesis section 3.2: X functions for gap <= 0.3, Y functions <= 0.15
    return (!name.empty() && name[0] == 'Y') ? 0.15 : 0.3;
}


Foam::label Foam::fdm::resistanceTable::lengthPower(const word& name)
{
    // Force ~ eta a U (A), torque/stresslet ~ eta a^2 U (B, G, P),
    // torque/stresslet ~ eta a^3 Omega (C, H)
    const char c = name.size() > 1 ? name[1] : ' ';
    switch (c)
    {
        case 'A': return 1;
        case 'B': case 'G': case 'P': return 2;
        case 'C': case 'H': return 3;
    }

    FatalErrorInFunction
        << "Unknown resistance function name " << name
        << abort(FatalError);
    return 0;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::fdm::resistanceTable::functionNames() const
{
    switch (kind_)
    {
        case tableKind::wall: return wallFunctionNames;
        case tableKind::twoBody: return twoBodyFunctionNames;
        default: return pairFunctionNames;
    }
}


Foam::label Foam::fdm::resistanceTable::index(const word& name) const
{
    const wordList& names = functionNames();
    forAll(names, fi)
    {
        if (names[fi] == name)
        {
            return fi;
        }
    }

    FatalErrorInFunction
        << "Resistance table " << name_ << " has no function " << name
        << "; available: " << names << exit(FatalError);
    return -1;
}


Foam::scalar Foam::fdm::resistanceTable::cutoff(const word& name) const
{
    return cutoff_[index(name)];
}


Foam::label Foam::fdm::resistanceTable::interval
(
    const scalar xc,
    scalar& w
) const
{
    // Linear interpolation of the remainder, constant below the first point
    if (xc <= gap_.first())
    {
        w = 0;
        return 1;
    }
    // First point > xc; xc <= gap.last() so i is in [1, size-1]
    label i = label(std::upper_bound(gap_.begin(), gap_.end(), xc)
                    - gap_.begin());
    i = min(i, gap_.size() - 1);
    w = (xc - gap_[i-1])/(gap_[i] - gap_[i-1]);
    return i;
}


Foam::scalar Foam::fdm::resistanceTable::evaluate
(
    const label fi,
    const scalar xc,
    const label i,
    const scalar w
) const
{
    // Singular part, thesis B.1/B.2 forms
    const FixedList<scalar, 3>& g = singular_[fi];
    const scalar lnInv = -std::log(xc);
    const scalar f = g[0]/xc + g[1]*lnInv + g[2]*xc*lnInv;
    const scalarList& rem = remainder_[fi];
    return f + ((1 - w)*rem[i-1] + w*rem[i]);
}


Foam::scalar Foam::fdm::resistanceTable::value
(
    const word& name,
    const scalar x,
    const scalar a1
) const
{
    const label fi = index(name);

    // Switched off beyond the cut-off (the FDM resolves the interaction)
    if (x > cutoff_[fi])
    {
        return 0;
    }

    const scalar xc = min(max(x, xMin_), gap_.last());
    scalar w;
    const label i = interval(xc, w);
    return std::pow(a1, lengthPower(name))*evaluate(fi, xc, i, w);
}


const Foam::FixedList<Foam::scalar, 3>& Foam::fdm::resistanceTable::singular
(
    const word& name
) const
{
    return singular_[index(name)];
}


void Foam::fdm::resistanceTable::values
(
    const scalar x,
    const scalar a1,
    UList<scalar>& f
) const
{
    const wordList& names = functionNames();
    if (f.size() != names.size())
    {
        FatalErrorInFunction
            << "Resistance table " << name_ << " has " << names.size()
            << " functions, asked for " << f.size() << abort(FatalError);
    }
    const scalar xc = min(max(x, xMin_), gap_.last());
    scalar w;
    const label i = interval(xc, w);
    forAll(names, fi)
    {
        f[fi] =
            x > cutoff_[fi]
          ? 0
          : std::pow(a1, lengthPower(names[fi]))
           *evaluate(fi, xc, i, w);
    }
}


void Foam::fdm::resistanceTable::requireKind
(
    const tableKind kind,
    const char* name
) const
{
    if (kind_ != kind)
    {
        FatalErrorInFunction
            << "Resistance table " << name_ << " is not a " << name
            << " table" << exit(FatalError);
    }
}


Foam::fdm::pairBaseFunctions Foam::fdm::resistanceTable::pairFunctions
(
    const scalar xi,
    const scalar a1
) const
{
    requireKind(tableKind::pair, "pair");
    pairBaseFunctions f;
    f.XA21 = value("XA21", xi, a1);
    f.YA21 = value("YA21", xi, a1);
    f.YB21 = value("YB21", xi, a1);
    f.XC21 = value("XC21", xi, a1);
    f.YC11 = value("YC11", xi, a1);
    f.XG11 = value("XG11", xi, a1);
    f.YG11 = value("YG11", xi, a1);
    f.YH21 = value("YH21", xi, a1);
    f.XP12 = value("XP12", xi, a1);
    f.XP21 = value("XP21", xi, a1);
    return f;
}


Foam::fdm::wallBaseFunctions Foam::fdm::resistanceTable::wallFunctions
(
    const scalar epsilon,
    const scalar a
) const
{
    requireKind(tableKind::wall, "wall");
    wallBaseFunctions f;
    f.XA = value("XA", epsilon, a);
    f.YA = value("YA", epsilon, a);
    f.YB = value("YB", epsilon, a);
    f.XC = value("XC", epsilon, a);
    f.YC = value("YC", epsilon, a);
    f.XG = value("XG", epsilon, a);
    f.XP = value("XP", epsilon, a);
    return f;
}


// ************************************************************************* //
