#include "keywordCheck.H"
#include "IOstreams.H"
#include "error.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::label Foam::editDistance(const word& a, const word& b)
{
    const label n = a.size();
    const label m = b.size();

    // Three rows of the distance table: i - 2, i - 1 and i
    List<label> prev2(m + 1, 0), prev(m + 1), cur(m + 1);
    for (label j = 0; j <= m; ++j)
    {
        prev[j] = j;
    }

    for (label i = 1; i <= n; ++i)
    {
        cur[0] = i;
        for (label j = 1; j <= m; ++j)
        {
            const label cost = (a[i - 1] == b[j - 1]) ? 0 : 1;
            label d = min(min(prev[j] + 1, cur[j - 1] + 1), prev[j - 1] + cost);
            if
            (
                i > 1 && j > 1
             && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]
            )
            {
                d = min(d, prev2[j - 2] + 1);
            }
            cur[j] = d;
        }
        prev2 = prev;
        prev = cur;
    }
    return prev[m];
}


Foam::word Foam::nearestKeyword(const word& key, const wordList& valid)
{
    word best;
    label bestDistance = labelMax;
    for (const word& w : valid)
    {
        const label d = editDistance(key, w);
        if (d < bestDistance)
        {
            best = w;
            bestDistance = d;
        }
    }
    return best;
}


Foam::fileName Foam::entryOrigin(const entry& e, const dictionary& dict)
{
    // A sub-dictionary: where its entries came from (a dictionary takes
    // the name of the one it is added to; its entries keep theirs)
    if (e.isDict())
    {
        for (const entry& sub : e.dict())
        {
            const fileName file(entryOrigin(sub, e.dict()));
            if (isFile(file))
            {
                return file;
            }
        }
    }

    // An entry read from a file is named "<file>.<scope>.<keyword>" (a
    // sub-dictionary "<file>.<scope>"): the file is the longest part of the
    // name before a '.' that is a file
    string name(e.isDict() ? e.dict().name() : e.name());
    while (!name.empty())
    {
        if (isFile(name))
        {
            return name;
        }
        const auto dot = name.rfind('.');
        const auto slash = name.rfind('/');
        if
        (
            dot == string::npos
         || (slash != string::npos && dot < slash)
        )
        {
            break;
        }
        name.resize(dot);
    }
    return dict.name();
}


void Foam::checkKeywords
(
    const dictionary& dict,
    const wordList& valid,
    const string& owner
)
{
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if
        (
            key == "FoamFile"
         || key.empty()
         || key[0] == '#'
         || key[0] == '$'
         || valid.found(key)
        )
        {
            continue;
        }

        // The file the entry came from: a material library file merged
        // under a phase's dictionary is named, not the phase's file
        const fileName origin(entryOrigin(e, dict));
        const label line = e.startLineNumber();

        FatalIOError
        (
            FUNCTION_NAME,
            __FILE__,
            __LINE__,
            origin,
            line,
            e.endLineNumber()
        )   << owner.c_str() << ": unknown entry " << key
            << " (line " << line << " of " << origin.c_str() << ")";
        if (valid.size())
        {
            FatalIOError
                << "; did you mean " << nearestKeyword(key, valid) << '?'
                << nl << "Valid entries: (";
            forAll(valid, i)
            {
                FatalIOError << (i ? " " : "") << valid[i];
            }
            FatalIOError << ')';
        }
        else
        {
            FatalIOError << "; this dictionary takes no entries";
        }
        FatalIOError << exit(FatalIOError);
    }
}


// ************************************************************************* //
