#include "THINC.H"
#include "error.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::THINC::THINC(const scalar beta)
:
    beta_(beta),
    eBeta_(std::exp(beta)),
    eMinusBeta_(std::exp(-beta))
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::THINC::lnCosh(const scalar x)
{
    const scalar ax = std::fabs(x);
    return ax + std::log1p(std::exp(-2*ax)) - M_LN2;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::THINC::jump(const scalar aBar) const
{
    const scalar B = std::exp(beta_*(2*aBar - 1));
    return std::log((eBeta_ - B)/(B - eMinusBeta_))/(2*beta_);
}


Foam::scalar Foam::THINC::mean
(
    const scalar xi1,
    const scalar xi2,
    const scalar xiJ
) const
{
    const scalar w = xi2 - xi1;
    if (w < 1e-6)
    {
        return 0.5*(1 + std::tanh(beta_*(0.5*(xi1 + xi2) - xiJ)));
    }
    return
        0.5
      + (lnCosh(beta_*(xi2 - xiJ)) - lnCosh(beta_*(xi1 - xiJ)))
       /(2*beta_*w);
}


// ************************************************************************* //
