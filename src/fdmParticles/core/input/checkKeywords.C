/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "checkKeywords.H"
#include "OSspecific.H"
#include <algorithm>
#include <cctype>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

std::vector<std::string> toStrings(const Foam::wordList& words)
{
    return std::vector<std::string>(words.begin(), words.end());
}

} // namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

std::size_t Foam::fdm::editDistance(const std::string& a, const std::string& b)
{
    // One row of the Wagner-Fischer table
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
    {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const bool same =
                std::tolower(static_cast<unsigned char>(a[i - 1]))
             == std::tolower(static_cast<unsigned char>(b[j - 1]));
            const std::size_t next = std::min
            (
                {row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)}
            );
            diagonal = row[j];
            row[j] = next;
        }
    }
    return row[b.size()];
}


std::string Foam::fdm::nearestSpelling
(
    const std::string& word,
    const std::vector<std::string>& candidates
)
{
    std::string best;
    std::size_t bestDistance = std::string::npos;
    for (const std::string& c : candidates)
    {
        const std::size_t d = editDistance(word, c);
        if (d < bestDistance)
        {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}


void Foam::fdm::checkKeywords
(
    const dictionary& dict,
    const wordList& allowed,
    const string& where
)
{
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (key == "FoamFile" || allowed.found(key))
        {
            continue;
        }
        FatalIOErrorInFunction(dict)
            << "Unknown keyword '" << key << "' in " << dict.name()
            << (where.empty() ? "" : " (") << where.c_str()
            << (where.empty() ? "" : ")") << nl
            << "    nearest valid spelling: '"
            << nearestSpelling(key, toStrings(allowed)).c_str() << "'" << nl
            << "    allowed keywords: " << allowed
            << exit(FatalIOError);
    }
}


void Foam::fdm::checkChoice
(
    const dictionary& dict,
    const word& key,
    const word& value,
    const wordList& allowed
)
{
    if (allowed.found(value))
    {
        return;
    }
    FatalIOErrorInFunction(dict)
        << "Unknown " << key << " '" << value << "' in " << dict.name() << nl
        << "    nearest valid spelling: '"
        << nearestSpelling(value, toStrings(allowed)).c_str() << "'" << nl
        << "    allowed: " << allowed << exit(FatalIOError);
}


void Foam::fdm::requireHeader(const fileName& file)
{
    if (isFile(file))
    {
        FatalErrorInFunction
            << file << " exists but cannot be read as an OpenFOAM"
            << " dictionary: it needs the FoamFile header" << nl
            << "    FoamFile { version 2.0; format ascii; class dictionary;"
            << " object " << file.name() << "; }" << nl
            << "    before its entries (OpenFOAM would otherwise treat the"
            << " file as absent)" << exit(FatalError);
    }
}


// ************************************************************************* //
