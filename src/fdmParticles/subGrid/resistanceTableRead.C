/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    Reading and checking a resistance table (resistanceTable.H).

\*---------------------------------------------------------------------------*/

#include "resistanceTable.H"
#include "IFstream.H"
#include "error.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::word Foam::fdm::resistanceTable::readKind(const dictionary& dict)
{
    const word kind(dict.get<word>("kind"));
    if (kind == "pair")
    {
        kind_ = tableKind::pair;
    }
    else if (kind == "wall")
    {
        kind_ = tableKind::wall;
    }
    else if (kind == "twoBody")
    {
        kind_ = tableKind::twoBody;
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Resistance table " << name_ << ": kind " << kind
            << " is not one of pair, wall, twoBody" << exit(FatalIOError);
    }

    const bool pairGap = kind_ != tableKind::wall;
    const word gapVariable(dict.get<word>("gapVariable"));
    const word expected(pairGap ? "xi" : "epsilon");
    if (gapVariable != expected)
    {
        FatalIOErrorInFunction(dict)
            << "Resistance table " << name_ << ": gapVariable "
            << gapVariable << " for kind " << kind << ", expected "
            << expected << exit(FatalIOError);
    }

    if (pairGap)
    {
        lambda_ = dict.get<scalar>("lambda");
        if (lambda_ <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "Resistance table " << name_ << ": lambda = " << lambda_
                << " must be positive" << exit(FatalIOError);
        }
    }
    return kind;
}


void Foam::fdm::resistanceTable::readGaps(const dictionary& dict)
{
    if (xMin_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Resistance table " << name_ << ": gap floor xMin = " << xMin_
            << " must be positive (the singular terms diverge at 0)"
            << exit(FatalIOError);
    }

    dict.readEntry("gap", gap_);
    if (gap_.size() < 2)
    {
        FatalIOErrorInFunction(dict)
            << "Resistance table " << name_ << ": keyword gap needs at least"
            << " two points, got " << gap_.size() << exit(FatalIOError);
    }
    for (label i = 1; i < gap_.size(); ++i)
    {
        if (!(gap_[i] > gap_[i-1]))
        {
            FatalIOErrorInFunction(dict)
                << "Resistance table " << name_ << ": keyword gap is not"
                << " strictly increasing at index " << i << " ("
                << gap_[i-1] << ", " << gap_[i] << ")" << exit(FatalIOError);
        }
    }
    if (gap_.last() < xMin_)
    {
        FatalIOErrorInFunction(dict)
            << "Resistance table " << name_ << ": last gap " << gap_.last()
            << " is below the gap floor " << xMin_ << exit(FatalIOError);
    }
}


void Foam::fdm::resistanceTable::readFunction
(
    const dictionary& fd,
    const label fi,
    const word& fn
)
{
    const scalarList g(fd.get<scalarList>("singular"));
    if (g.size() != 3)
    {
        FatalIOErrorInFunction(fd)
            << "Resistance table " << name_ << ": " << fn
            << "/singular needs 3 coefficients (1/x, ln(1/x),"
            << " x ln(1/x)), got " << g.size() << exit(FatalIOError);
    }
    for (label k = 0; k < 3; ++k)
    {
        singular_[fi][k] = g[k];
    }

    fd.readEntry("remainder", remainder_[fi]);
    if (remainder_[fi].size() != gap_.size())
    {
        FatalIOErrorInFunction(fd)
            << "Resistance table " << name_ << ": " << fn
            << "/remainder has " << remainder_[fi].size()
            << " values but gap has " << gap_.size()
            << exit(FatalIOError);
    }

    // A two-body table has no cut-off of its own (the pair law has one)
    cutoff_[fi] = fd.getOrDefault<scalar>
    (
        "cutoff",
        kind_ == tableKind::twoBody ? GREAT : defaultCutoff(fn)
    );
    if (cutoff_[fi] <= 0)
    {
        FatalIOErrorInFunction(fd)
            << "Resistance table " << name_ << ": " << fn
            << "/cutoff = " << cutoff_[fi] << " must be positive"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::resistanceTable::resistanceTable
(
    const dictionary& dict,
    const scalar xMin
)
:
    name_(dict.name()),
    kind_(tableKind::pair),
    lambda_(0),
    xMin_(xMin)
{
    const word kind(readKind(dict));
    readGaps(dict);

    const dictionary* funcsPtr = dict.findDict("functions");
    if (!funcsPtr)
    {
        FatalIOErrorInFunction(dict)
            << "Resistance table " << name_ << ": missing sub-dictionary"
            << " functions" << exit(FatalIOError);
    }
    const dictionary& funcs = *funcsPtr;

    const wordList& names = functionNames();
    singular_.setSize(names.size());
    remainder_.setSize(names.size());
    cutoff_.setSize(names.size());

    forAll(names, fi)
    {
        const word& fn = names[fi];
        const dictionary* fPtr = funcs.findDict(fn);
        if (!fPtr)
        {
            FatalIOErrorInFunction(funcs)
                << "Resistance table " << name_ << ": missing function "
                << fn << " (a " << kind << " table needs " << names << ")"
                << exit(FatalIOError);
        }
        readFunction(*fPtr, fi, fn);
    }
}


Foam::fdm::resistanceTable Foam::fdm::resistanceTable::read
(
    const fileName& file,
    const scalar xMin
)
{
    IFstream is(file);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot open resistance table " << file
            << exit(FatalError);
    }
    const dictionary dict(is);
    return resistanceTable(dict, xMin);
}



// ************************************************************************* //
