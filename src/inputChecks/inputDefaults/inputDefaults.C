#include "inputDefaults.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

Foam::DynamicList<Foam::string> Foam::inputDefaults::notes_;


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::inputDefaults::note
(
    const string& owner,
    const word& key,
    const string& value
)
{
    const string line(owner + ": " + key + ' ' + value);
    if (!notes_.found(line))
    {
        notes_.append(line);
    }
}


void Foam::inputDefaults::print(Ostream& os)
{
    if (notes_.empty())
    {
        return;
    }
    os  << "Defaults used (not given in the input):" << nl;
    for (const string& line : notes_)
    {
        os  << "    " << line.c_str() << nl;
    }
    os  << endl;
    notes_.clear();
}


// ************************************************************************* //
