/*---------------------------------------------------------------------------*\
  Unit tests of the generic equation-of-state services (docs/model.md
  section 10.1): the relaxation paths, isentropes and helpers that
  equationOfState builds on the primitives of any model, against the closed
  forms of the stiffened gas; the temperature of the stiffened gas.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "stiffenedGas.H"
#include "primitivesOnly.H"
#include "unitTestTools.H"

#include <string>
#include <vector>

using namespace Foam;
using namespace unitTestTools;

namespace
{

autoPtr<equationOfState> eosFrom(const std::string& text)
{
    return equationOfState::New("copper", dictFrom(text));
}


//- A stiffened gas and the states its relaxation paths start from
struct material
{
    std::string name;
    std::string dict;
    std::vector<scalar> rho;
    std::vector<scalar> p;
};


std::vector<material> materials()
{
    return
    {
        {
            "copper",
            "type stiffenedGas; gamma 4.22; pInf 3.42e10;",
            {5000, 8930, 11000, 16000},
            {-2e10, -1e9, 0, 1e5, 1e9, 3e10}
        },
        {
            "air",
            "type stiffenedGas; gamma 1.4; pInf 0;",
            {1e-3, 1.2, 50},
            {1e2, 1e5, 1e7, 1e9}
        }
    };
}


//- Interface pressures from near pMin to 1e10: fractions of the way from
//  pMin to the start pressure, and fixed values above pMin
std::vector<scalar> pStars(const equationOfState& eos, const scalar pOld)
{
    const scalar pMin = eos.pMin(1);
    std::vector<scalar> ps;
    for (const scalar f : {1e-3, 1e-2, 0.1, 0.5, 1.0, 2.0})
    {
        ps.push_back(pMin + f*(pOld - pMin));
    }
    for (const scalar p : {-3e10, -1e10, 0.0, 1.0, 1e5, 1e8, 1e9, 1e10})
    {
        if (p > pMin + 1e-3*(pOld - pMin))
        {
            ps.push_back(p);
        }
    }
    return ps;
}



const scalar tol = 1e-12;

} // End anonymous namespace


TEST(equationOfStateServices, relaxedPathMatchesClosedForm)
{
    for (const material& m : materials())
    {
        auto eos = eosFrom(m.dict);
        const primitivesOnly generic(eos());
        for (const scalar rhoOld : m.rho)
        {
            for (const scalar pOld : m.p)
            {
                const scalar eOld = eos->e(rhoOld, pOld);
                for (const scalar pStar : pStars(eos(), pOld))
                {
                    SCOPED_TRACE
                    (
                        m.name + " rhoOld " + std::to_string(rhoOld)
                      + " pOld " + std::to_string(pOld)
                      + " p* " + std::to_string(pStar)
                    );
                    EXPECT_TRUE
                    (
                        relClose
                        (
                            generic.vRelaxed(pStar, rhoOld, eOld),
                            eos->vRelaxed(pStar, rhoOld, eOld),
                            tol
                        )
                    );
                    EXPECT_TRUE
                    (
                        relClose
                        (
                            generic.dvRelaxeddp(pStar, rhoOld, eOld),
                            eos->dvRelaxeddp(pStar, rhoOld, eOld),
                            tol
                        )
                    );
                    // The generic algorithm on the model's own primitives
                    EXPECT_TRUE
                    (
                        relClose
                        (
                            eos->equationOfState::vRelaxed
                            (
                                pStar, rhoOld, eOld
                            ),
                            eos->vRelaxed(pStar, rhoOld, eOld),
                            tol
                        )
                    );
                }
            }
        }
    }
}


TEST(equationOfStateServices, isentropesMatchClosedForm)
{
    for (const material& m : materials())
    {
        auto eos = eosFrom(m.dict);
        const primitivesOnly generic(eos());
        for (const scalar rhoOld : m.rho)
        {
            for (const scalar pOld : m.p)
            {
                const scalar eOld = eos->e(rhoOld, pOld);
                for (const scalar pStar : pStars(eos(), pOld))
                {
                    SCOPED_TRACE
                    (
                        m.name + " rhoOld " + std::to_string(rhoOld)
                      + " pOld " + std::to_string(pOld)
                      + " p* " + std::to_string(pStar)
                    );
                    EXPECT_TRUE
                    (
                        relClose
                        (
                            generic.vIsentropic(pStar, rhoOld, eOld),
                            eos->vIsentropic(pStar, rhoOld, eOld),
                            tol
                        )
                    );
                    EXPECT_TRUE
                    (
                        relClose
                        (
                            generic.dvIsentropicdp(pStar, rhoOld, eOld),
                            eos->dvIsentropicdp(pStar, rhoOld, eOld),
                            tol
                        )
                    );
                }
                for (const scalar f : {0.25, 0.5, 0.9, 1.0, 1.1, 1.5, 2.0})
                {
                    const scalar rho = f*rhoOld;
                    SCOPED_TRACE
                    (
                        m.name + " rhoRef " + std::to_string(rhoOld)
                      + " pRef " + std::to_string(pOld)
                      + " rho " + std::to_string(rho)
                    );
                    EXPECT_TRUE
                    (
                        relClose
                        (
                            generic.eIsentropic(rho, rhoOld, eOld),
                            eos->eIsentropic(rho, rhoOld, eOld),
                            tol
                        )
                    );
                    EXPECT_TRUE
                    (
                        relClose
                        (
                            eos->equationOfState::eIsentropic
                            (
                                rho, rhoOld, eOld
                            ),
                            eos->eIsentropic(rho, rhoOld, eOld),
                            tol
                        )
                    );
                }
            }
        }
    }
}


TEST(equationOfStateServices, lowestPressuresOfThePaths)
{
    // Both paths of a stiffened gas reach every pressure above -pInf (v
    // grows without bound as p* falls to it): the lower bracket of the
    // interface-pressure root
    for (const material& m : materials())
    {
        auto eos = eosFrom(m.dict);
        const primitivesOnly generic(eos());
        for (const scalar rhoOld : m.rho)
        {
            for (const scalar pOld : m.p)
            {
                SCOPED_TRACE
                (
                    m.name + " rho " + std::to_string(rhoOld)
                  + " p " + std::to_string(pOld)
                );
                const scalar eOld = eos->e(rhoOld, pOld);
                const scalar pMin = eos->pMin(rhoOld);
                const scalar scale = eos->pScale(rhoOld, pOld);
                EXPECT_EQ(eos->pRelaxedMin(rhoOld, eOld), pMin);
                EXPECT_EQ(eos->pIsentropicMin(rhoOld, eOld), pMin);
                EXPECT_NEAR
                (
                    generic.pRelaxedMin(rhoOld, eOld), pMin, tol*scale
                );
                EXPECT_NEAR
                (
                    generic.pIsentropicMin(rhoOld, eOld), pMin, tol*scale
                );
                EXPECT_GE(generic.pRelaxedMin(rhoOld, eOld), pMin);
                EXPECT_GE(generic.pIsentropicMin(rhoOld, eOld), pMin);
            }
        }
    }
}


TEST(equationOfStateServices, fundamentalDerivativeAndGrueneisen)
{
    for (const material& m : materials())
    {
        auto eos = eosFrom(m.dict);
        const primitivesOnly generic(eos());
        const auto& sg = refCast<const equationsOfState::stiffenedGas>(eos());
        for (const scalar rho : m.rho)
        {
            for (const scalar p : m.p)
            {
                // Generic: a second-order difference, about 1e-10
                EXPECT_TRUE
                (
                    relClose
                    (
                        generic.fundamentalDerivative(rho, p),
                        eos->fundamentalDerivative(rho, p),
                        1e-8
                    )
                ) << m.name << " rho " << rho << " p " << p;

                // Gamma = (1/rho) dp/de at constant rho = gamma - 1
                const scalar e = eos->e(rho, p);
                EXPECT_EQ(eos->Gamma(rho, e), sg.gamma() - 1);
                const scalar de = 1e-6*mag(e);
                const scalar dpde =
                    (eos->p(rho, e + de) - eos->p(rho, e - de))/(2*de);
                EXPECT_TRUE(relClose(dpde/rho, eos->Gamma(rho, e), 1e-8));

                // The generic round-off scale bounds |p|
                EXPECT_GE(generic.pScale(rho, p), mag(p));
            }
        }
    }
}


TEST(equationOfStateServices, stiffenedGasTemperature)
{
    const scalar gamma = 4.22, pInf = 3.42e10, Cv = 383;
    auto eos = eosFrom("type stiffenedGas; gamma 4.22; pInf 3.42e10; Cv 383;");
    ASSERT_TRUE(eos->hasTemperature());
    EXPECT_EQ(eos->Cv(), Cv);
    for (const scalar rho : {7000.0, 8930.0, 11000.0})
    {
        for (const scalar p : {-1e10, 0.0, 1e5, 1e9, 5e10})
        {
            const scalar e = eos->e(rho, p);
            const scalar T = eos->T(rho, e);
            EXPECT_TRUE
            (
                relClose(T, (p + pInf)/((gamma - 1)*rho*Cv), 1e-13)
            ) << "rho " << rho << " p " << p;

            // Heat dW at constant density raises T by dW/Cv
            const scalar dW = 1e4;
            EXPECT_TRUE(relClose(eos->T(rho, e + dW) - T, dW/Cv, 1e-9));
        }
    }

    // Through the generic forwarder too
    const primitivesOnly generic(eos());
    EXPECT_TRUE(generic.hasTemperature());
    EXPECT_EQ(generic.T(8930, 3e5), eos->T(8930, 3e5));
}


TEST(equationOfStateServices, missingOrBadHeatCapacity)
{
    // Without Cv: no temperature, and asking for it names the phase and
    // the missing keyword
    auto eos = eosFrom("type stiffenedGas; gamma 4.22; pInf 3.42e10;");
    EXPECT_FALSE(eos->hasTemperature());
    for (int which = 0; which < 2; ++which)
    {
        try
        {
            if (which == 0)
            {
                eos->T(8930, 3e5);
            }
            else
            {
                eos->Cv();
            }
            ADD_FAILURE() << (which ? "Cv" : "T") << " without Cv accepted";
        }
        catch (const Foam::error& err)
        {
            const std::string msg(err.message());
            for (const std::string key : {"copper", "Cv", "equationOfState"})
            {
                EXPECT_NE(msg.find(key), std::string::npos)
                    << "message does not contain " << key << ":\n" << msg;
            }
        }
    }

    // Cv <= 0: FatalIOError naming the phase and the entry
    for (const char* Cv : {"0", "-383"})
    {
        try
        {
            eosFrom
            (
                std::string("type stiffenedGas; gamma 4.22; pInf 3.42e10; Cv ")
              + Cv + ";"
            );
            ADD_FAILURE() << "Cv " << Cv << " accepted";
        }
        catch (const Foam::error& err)
        {
            const std::string msg(err.message());
            EXPECT_NE(msg.find("copper"), std::string::npos) << msg;
            EXPECT_NE(msg.find("Cv"), std::string::npos) << msg;
        }
    }
}
