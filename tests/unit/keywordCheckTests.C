/*---------------------------------------------------------------------------*\
  Unit tests of strict input (src/inputChecks): the edit distance, the
  nearest valid keyword, checkKeywords' message, the keyword lists of the
  run-time selected models and the defaults noted by inputDefaults.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "keywordCheck.H"
#include "inputDefaults.H"
#include "equationOfState.H"
#include "plasticModel.H"
#include "yieldStress.H"
#include "failureModel.H"
#include "OStringStream.H"
#include "unitTestTools.H"

#include <string>

using namespace Foam;
using namespace unitTestTools;

namespace
{

//- The message of the FatalIOError checkKeywords throws ("" if none)
std::string checkMessage(const std::string& text, const wordList& valid)
{
    try
    {
        checkKeywords(dictFrom(text), valid, "Phase copper, plasticity");
    }
    catch (const Foam::error& err)
    {
        return err.message();
    }
    return "";
}

bool hasNote(const std::string& line)
{
    for (const string& note : inputDefaults::notes())
    {
        if (note == line)
        {
            return true;
        }
    }
    return false;
}

} // End anonymous namespace


TEST(keywordCheck, editDistanceCountsEachEdit)
{
    // Exact values: identity, one insertion, deletion, substitution,
    // transposition of neighbours, and words with nothing in common
    EXPECT_EQ(editDistance("tau", "tau"), 0);
    EXPECT_EQ(editDistance("", ""), 0);
    EXPECT_EQ(editDistance("", "failure"), 7);
    EXPECT_EQ(editDistance("failure", ""), 7);
    EXPECT_EQ(editDistance("failur", "failure"), 1);
    EXPECT_EQ(editDistance("pVacum", "pVacuum"), 1);
    EXPECT_EQ(editDistance("spallTime", "spallTim"), 1);
    EXPECT_EQ(editDistance("sigmaY", "sigmaX"), 1);
    EXPECT_EQ(editDistance("tua", "tau"), 1);
    EXPECT_EQ(editDistance("predictorRelaxaton", "predictorRelaxation"), 1);
    EXPECT_EQ(editDistance("kitten", "sitting"), 3);
    EXPECT_EQ(editDistance("abc", "xyz"), 3);
    EXPECT_EQ(editDistance("ca", "abc"), 3);

    // Symmetric
    EXPECT_EQ(editDistance("riemanSolver", "riemannSolver"), 1);
    EXPECT_EQ(editDistance("riemannSolver", "riemanSolver"), 1);
    EXPECT_EQ(editDistance("gamma", "Gamma0"), editDistance("Gamma0", "gamma"));
}


TEST(keywordCheck, nearestKeywordIsTheClosest)
{
    const wordList phase
    ({
        "material", "writeTemperature", "passiveScalars", "type",
        "equationOfState", "elasticity", "pressureRelaxation", "inelastic",
        "plasticity", "failure"
    });
    EXPECT_EQ(nearestKeyword("failur", phase), "failure");
    EXPECT_EQ(nearestKeyword("plastcity", phase), "plasticity");
    EXPECT_EQ(nearestKeyword("equationofState", phase), "equationOfState");
    EXPECT_EQ(nearestKeyword("writeTemperatur", phase), "writeTemperature");
    EXPECT_EQ(nearestKeyword("tpye", phase), "type");

    // Ties go to the first in the list; an empty list gives an empty word
    EXPECT_EQ(nearestKeyword("ab", wordList({"ac", "bb"})), "ac");
    EXPECT_EQ(nearestKeyword("ab", wordList({"bb", "ac"})), "bb");
    EXPECT_EQ(nearestKeyword("ab", wordList({"bx", "ac"})), "ac");
    EXPECT_EQ(nearestKeyword("tau", wordList()), "");
}


TEST(keywordCheck, unknownEntryStopsWithTheNearestValidOne)
{
    const wordList valid({"type", "tau", "n", "sigmaY"});

    EXPECT_EQ(checkMessage("type vonMises; tau 0; sigmaY 3e8;", valid), "");
    EXPECT_EQ(checkMessage("", valid), "");

    const std::string msg(checkMessage("type vonMises; tua 0;", valid));
    EXPECT_NE(msg.find("Phase copper, plasticity: unknown entry tua"),
        std::string::npos) << msg;
    EXPECT_NE(msg.find("did you mean tau?"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Valid entries: (type tau n sigmaY)"),
        std::string::npos) << msg;

    const std::string none(checkMessage("tau 0;", wordList()));
    EXPECT_NE(none.find("takes no entries"), std::string::npos) << none;
}


TEST(keywordCheck, modelsListTheirEntries)
{
    // A misspelled optional entry of a run-time selected model stops the
    // run (it was silently ignored, the default taken)
    try
    {
        equationOfState::New
        (
            "copper",
            dictFrom("type stiffenedGas; gamma 4.22; pInf 3.42e10; Cw 383;")
        );
        ADD_FAILURE() << "equationOfState with Cw accepted";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find("Phase copper, equationOfState: unknown entry Cw"),
            std::string::npos) << msg;
        EXPECT_NE(msg.find("did you mean Cv?"), std::string::npos) << msg;
    }

    try
    {
        failureModel::New
        (
            "copper",
            dictFrom("failure { type spall; sigmaSpall 1e9; spallTim 1e-7; }")
        );
        ADD_FAILURE() << "failure with spallTim accepted";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find("Phase copper, failure: unknown entry spallTim"),
            std::string::npos) << msg;
        EXPECT_NE(msg.find("did you mean spallTime?"), std::string::npos)
            << msg;
    }

    // The lists of the models that read more than their base
    EXPECT_TRUE
    (
        yieldStress::New
        (
            "copper",
            dictFrom
            (
                "type JohnsonCook; A 9e7; B 2.92e8; n 0.31; m 1.09;"
                " Tr 298; Tm 1356;"
            )
        )->keywords().found("epsDot0")
    );
    EXPECT_TRUE
    (
        plasticModel::New
        (
            "copper", dictFrom("type vonMises; sigmaY 3e8; tau 0;")
        )->keywords().found("n")
    );
    EXPECT_EQ
    (
        plasticModel::New("copper", dictFrom("type none;"))->keywords(),
        wordList({"type"})
    );
}


TEST(keywordCheck, defaultsAreNotedOnce)
{
    inputDefaults::print(Info);      // forget earlier notes

    const dictionary dict(dictFrom("given 2;"));
    EXPECT_EQ(inputDefaults::get<scalar>(dict, "given", 5, "test"), 2);
    EXPECT_EQ(inputDefaults::get<scalar>(dict, "missing", 5, "test"), 5);
    EXPECT_EQ(inputDefaults::get<scalar>(dict, "missing", 5, "test"), 5);
    EXPECT_EQ(inputDefaults::get<word>(dict, "solver", "HLLC", "test"), "HLLC");
    EXPECT_EQ(inputDefaults::notes().size(), 2);
    EXPECT_TRUE(hasNote("test: missing 5"));
    EXPECT_TRUE(hasNote("test: solver HLLC"));
    EXPECT_FALSE(hasNote("test: given 5"));

    // Defaults of a model: n of vonMises, C and epsDot0 of Johnson-Cook
    plasticModel::New
    (
        "copper",
        dictFrom
        (
            "type vonMises; tau 0; yieldStress { type JohnsonCook; A 9e7;"
            " B 2.92e8; n 0.31; m 1.09; Tr 298; Tm 1356; }"
        )
    );
    EXPECT_TRUE(hasNote("Phase copper, plasticity: n 0"));
    EXPECT_TRUE(hasNote("Phase copper, plasticity yieldStress: C 0"));
    EXPECT_TRUE(hasNote("Phase copper, plasticity yieldStress: epsDot0 1"));

    // Printed as one block, then forgotten
    OStringStream os;
    inputDefaults::print(os);
    const std::string block(os.str());
    EXPECT_EQ(block.find("Defaults used (not given in the input):\n"), 0u)
        << block;
    EXPECT_NE(block.find("\n    test: missing 5\n"), std::string::npos)
        << block;
    EXPECT_TRUE(inputDefaults::notes().empty());
}


// ************************************************************************* //
