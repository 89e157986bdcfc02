/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Application
    plasticReturnBench

Description
    Cost of the shared plastic return (vonMisesReturn) with each flow-stress
    law: the same set of yielding copper states (random rotations and
    principal log-strains, trial stress 0.6-3 GPa, above every law's
    surface; epsP 0-1, T 298-900 K, dt 1e-9-1e-6 s) returned with constant,
    linear, table, Johnson-Cook OFHC (n 0.31, C 0.025, m 1.09) and
    Johnson-Cook with the shortcuts (n 1, m 1, C 0); the fastest of several
    repeats, in ns per return, its ratio to the linear law's, and the law
    evaluations per return (counted through a wrapper law, in a separate
    pass). Then the cost of one law evaluation alone.

    Not a test: it asserts nothing. Build and run:
    \verbatim
        . etc/bashrc
        wmake bench/plasticReturn
        plasticReturnBench [-states N] [-repeats R]
    \endverbatim
    On a shared machine run it twice; the ratios are steadier than the
    times.

\*---------------------------------------------------------------------------*/

#include "vonMisesReturn.H"
#include "yieldStress.H"
#include "elasticModel.H"
#include "IStringStream.H"
#include "argList.H"

#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

dictionary dictFrom(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

//- A law that counts its evaluations
class countingLaw
:
    public yieldStress
{
    const yieldStress& law_;

public:

    mutable long n;

    explicit countingLaw(const yieldStress& law)
    :
        yieldStress(law.phaseName()),
        law_(law),
        n(0)
    {}

    virtual scalar sigmaY
    (
        const scalar epsP,
        const scalar epsPDot,
        const scalar T
    ) const
    {
        ++n;
        return law_.sigmaY(epsP, epsPDot, T);
    }
};

struct sample
{
    cobasis::matrix A;
    scalar epsP, T, dt;
};

double seconds()
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now().time_since_epoch()
    ).count();
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::noBanner();
    argList::addOption("states", "N", "number of states (default 20000)");
    argList::addOption("repeats", "R", "repeats (default 7)");
    argList args(argc, argv, false, false, false);

    const label nStates = args.getOrDefault<label>("states", 20000);
    const label nRepeats = args.getOrDefault<label>("repeats", 7);

    auto elastic = elasticModel::New
    (
        "copper", dictFrom("type separable; rho0 8930; mu 4.6e10; a 0.5;")
    );

    const std::vector<std::pair<std::string, std::string>> laws
    {
        {"constant", "type constant; sigmaY 4e8;"},
        {"linear", "type linear; sigmaY0 4e8; H 1e8;"},
        {"table (3 pairs)",
         "type table; values ((0 9e7) (0.1 2.2e8) (0.5 3.3e8));"},
        {"JohnsonCook OFHC",
         "type JohnsonCook; A 9e7; B 2.92e8; n 0.31; C 0.025; m 1.09;"
         " Tr 298; Tm 1356;"},
        {"JohnsonCook n=m=1 C=0",
         "type JohnsonCook; A 9e7; B 2.92e8; n 1; m 1; Tr 298; Tm 1356;"}
    };

    // The states: trial stress in [6e8, 3e9]
    std::mt19937 gen(1);
    std::uniform_real_distribution<double> U(-1, 1), U01(0, 1);
    std::normal_distribution<double> N(0, 1);
    std::vector<sample> states;
    while (label(states.size()) < nStates)
    {
        Eigen::Quaterniond q(N(gen), N(gen), N(gen), N(gen));
        const cobasis::matrix R(q.normalized().toRotationMatrix());
        const scalar m = std::exp(std::log(1e-3) + U01(gen)*std::log(100.0));
        const cobasis::vector l
        (
            std::exp(m*U(gen)), std::exp(m*U(gen)), std::exp(m*U(gen))
        );
        const cobasis::matrix A(R*l.asDiagonal()*R.transpose());
        const scalar trial = std::sqrt(1.5)*elastic->SofA(A).norm();
        if (trial < 6e8 || trial > 3e9)
        {
            continue;
        }
        states.push_back
        (
            {
                A, U01(gen), 298 + 600*U01(gen),
                std::exp(std::log(1e-9) + U01(gen)*std::log(1e3))
            }
        );
    }

    const vonMisesReturn ideal;
    std::printf
    (
        "plastic return, %ld yielding copper states, fastest of %ld"
        " repeats\n%-24s %12s %10s %14s\n",
        long(nStates), long(nRepeats), "law", "ns/return", "",
        "law calls/ret"
    );

    // The laws and their counted wrappers
    std::vector<autoPtr<yieldStress>> lawPtrs;
    for (const auto& l : laws)
    {
        lawPtrs.push_back(yieldStress::New("copper", dictFrom(l.second)));
    }

    // Repeats interleaved over the laws (a busy spell of the machine hits
    // them all alike), fastest kept
    std::vector<double> times(laws.size(), GREAT);
    scalar sink = 0;
    for (label r = 0; r < nRepeats; ++r)
    {
        forAll(lawPtrs, li)
        {
            const yieldStress& law = lawPtrs[li]();
            const double t0 = seconds();
            for (const sample& s : states)
            {
                cobasis::matrix A(s.A);
                sink += ideal.correct(A, s.epsP, *elastic, law, s.dt, s.T).dEpsP;
            }
            times[li] = std::min(times[li], (seconds() - t0)/nStates);
        }
    }

    double linearTime = 0;
    forAll(lawPtrs, li)
    {
        countingLaw counting(lawPtrs[li]());
        for (const sample& s : states)
        {
            cobasis::matrix A(s.A);
            sink += ideal.correct(A, s.epsP, *elastic, counting, s.dt, s.T).dEpsP;
        }
        if (laws[li].first == "linear")
        {
            linearTime = times[li];
        }
        std::printf
        (
            "%-24s %12.0f %10s %14.1f\n", laws[li].first.c_str(),
            1e9*times[li], "", double(counting.n)/nStates
        );
    }
    std::printf("ratio to linear:\n");
    for (size_t i = 0; i < laws.size(); ++i)
    {
        std::printf("%-24s %12.3f\n", laws[i].first.c_str(), times[i]/linearTime);
    }

    // One evaluation of the law alone
    std::printf
    (
        "\none law evaluation (ns), 1e7 calls, T changing at every call:\n"
    );
    for (const auto& l : laws)
    {
        auto law = yieldStress::New("copper", dictFrom(l.second));
        const yieldStress& ys = *law;
        double best = GREAT;
        for (label r = 0; r < 3; ++r)
        {
            const double t0 = seconds();
            scalar acc = 0;
            for (long i = 0; i < 10000000; ++i)
            {
                const scalar e = 1e-7*(i % 10000000);
                acc += ys.sigmaY(e, 1e3 + e*1e4, 300 + 500*e);
            }
            sink += acc;
            best = std::min(best, seconds() - t0);
        }
        std::printf("%-24s %12.1f\n", l.first.c_str(), 1e9*best/1e7);
    }

    std::printf("(checksum %g)\n", sink);
    return 0;
}
