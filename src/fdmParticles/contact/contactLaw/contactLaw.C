/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"
#include "mathematicalConstants.H"
#include "readBounded.H"
#include "checkKeywords.H"

namespace Foam
{
namespace fdm
{
    defineTypeNameAndDebug(contactLaw, 0);
    defineRunTimeSelectionTable(contactLaw, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The contact dictionary after the check that it holds no keyword but
//  the common ones and the law's own (before anything is read from it, so
//  a misspelling is named as such rather than as a missing keyword)
const Foam::dictionary& checked
(
    const Foam::dictionary& dict,
    const Foam::wordList& extraKeywords
)
{
    Foam::wordList allowed
    ({
        "model", "roughness", "friction", "kn", "shearRate",
        "meanDeformation"
    });
    allowed.append(extraKeywords);
    Foam::fdm::checkKeywords(dict, allowed, "contact block");
    return dict;
}

} // namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::contactLaw::contactLaw
(
    const dictionary& dict,
    const scales& s,
    const wordList& extraKeywords
)
:
    roughness_
    (
        s.a1*readBounded
        (
            checked(dict, extraKeywords), "roughness", VSMALL, 0.1,
            "asperity height h_r/a_1, a_1 the smallest radius; thesis 5e-3"
        )
    ),
    kn_(0),
    friction_
    (
        readBounded(dict, "friction", 0, GREAT, "Coulomb coefficient mu")
    ),
    shearRate_(0)
{
    const bool direct = dict.found("kn");
    const bool rule = dict.found("meanDeformation");
    if (direct == rule)
    {
        FatalIOErrorInFunction(dict)
            << "Give the contact stiffness in " << dict.name() << " either"
            << " as kn [N/m^1.5] or as shearRate and meanDeformation"
            << " (thesis 2.6: 6 pi eta shearRate a_1^2 = kn (meanDeformation"
            << " h_r)^1.5, meanDeformation < 0.2 typical), not "
            << (direct ? "both" : "neither") << exit(FatalIOError);
    }
    if (direct)
    {
        kn_ = readBounded(dict, "kn", VSMALL, GREAT, "Hertz stiffness k_n");
    }
    else
    {
        shearRate_ =
            readBounded
            (
                dict, "shearRate", VSMALL, GREAT,
                "reference shear rate gammaDot_0 of the stiffness rule"
            );
        const scalar eps =
            readBounded
            (
                dict, "meanDeformation", VSMALL, 1,
                "mean asperity deformation over h_r, thesis < 0.2"
            );
        kn_ =
            6*constant::mathematical::pi*s.eta*shearRate_*sqr(s.a1)
           /pow(eps*roughness_, 1.5);
    }
}


// * * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fdm::contactLaw> Foam::fdm::contactLaw::New
(
    const dictionary& dict,
    const scales& s
)
{
    const word model(dict.getOrDefault<word>("model", "hertz"));

    checkChoice
    (
        dict, "contact model", model,
        dictionaryConstructorTablePtr_->sortedToc()
    );
    return dictionaryConstructorTablePtr_->cfind(model)()(dict, s);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //


Foam::fdm::contactLaw::barrierTerms Foam::fdm::contactLaw::barrier
(
    const scalar gap,
    const scalar floorGap
) const
{
    // Eq 2.57: F = k_n delta^1.5 A/D, A = 1 - exp[10(d - 1)],
    // D = 1 - exp(-10 x), x = gap/h_r - d the distance to the floor in
    // units of h_r, kept positive: at 1e-6 the barrier multiplies the Hertz
    // force by about 1e5
    const scalar d = floorGap/roughness_;
    const scalar x = max(gap/roughness_ - d, 1e-6);
    return barrierTerms
    {
        roughness_ - gap,
        1 - std::exp(10*(d - 1)),
        -std::expm1(-10*x),
        std::exp(-10*x)
    };
}


Foam::scalar Foam::fdm::contactLaw::elasticNormalForce
(
    const scalar gap,
    const scalar floorGap
) const
{
    if (!touching(gap))
    {
        return 0;
    }
    const barrierTerms b = barrier(gap, floorGap);
    return kn_*pow(b.delta, 1.5)*b.A/b.D;
}


Foam::scalar Foam::fdm::contactLaw::normalStiffness
(
    const scalar gap,
    const scalar floorGap
) const
{
    if (!touching(gap))
    {
        return 0;
    }
    // -dF/d(gap) = k_n A [1.5 delta^0.5/D + delta^1.5 (10/h_r) exp(-10x)/D^2]
    const barrierTerms b = barrier(gap, floorGap);
    return
        kn_*b.A
       *(
            1.5*std::sqrt(b.delta)/b.D
          + pow(b.delta, 1.5)*(10/roughness_)*b.expX/sqr(b.D)
        );
}


Foam::fdm::contactForce Foam::fdm::contactLaw::evaluate
(
    const contactGeometry& g,
    vector& slip
) const
{
    contactForce c{Zero, Zero, 0, false, g.gap < g.floorGap, 0};
    if (!touching(g.gap))
    {
        slip = Zero;
        return c;
    }

    c.elasticNormal = elasticNormalForce(g.gap, g.floorGap);
    const scalar net = c.elasticNormal - adhesionForce();

    // Spring on the slip (eqs 2.59-2.60), Coulomb cap on the elastic part
    // (eqs 2.63, 5.2)
    slip = rotateIntoTangentPlane(slip, g.normal);
    const scalar delta = roughness_ - g.gap;
    const scalar limit = friction_*c.elasticNormal;
    if (delta > 0 && c.elasticNormal > 0)
    {
        const scalar kt = (2.0/7.0)*c.elasticNormal/delta;
        c.tangential = -kt*slip;
        const scalar magFt = mag(c.tangential);
        if (magFt > limit)
        {
            c.sliding = true;
            c.tangential *= limit/magFt;
            slip = -c.tangential/kt;
        }
        else
        {
            c.tangentialStiffness = kt;
        }
    }
    else
    {
        // At the onset (delta = 0) there is no stiffness yet
        slip = Zero;
    }

    // The normal force pushes i away from j
    c.force = -net*g.normal + c.tangential;
    return c;
}


void Foam::fdm::contactLaw::writeInfo(Ostream& os) const
{
    os  << "    contact " << type() << ": h_r = " << roughness_
        << ", k_n = " << kn_ << ", mu = " << friction_;
    if (adhesionForce() > 0)
    {
        os  << ", F_adh = " << adhesionForce();
    }
    os  << nl;
}


// * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fdm::slipVelocity
(
    const vector& n,
    const vector& Ui,
    const vector& Omegai,
    const scalar li,
    const vector& Uj,
    const vector& Omegaj,
    const scalar lj
)
{
    const vector dU = Ui - Uj;
    return dU - (dU & n)*n + ((li*Omegai + lj*Omegaj) ^ n);
}


Foam::vector Foam::fdm::rotateIntoTangentPlane
(
    const vector& slip,
    const vector& n
)
{
    const vector t = slip - (slip & n)*n;
    const scalar magT = mag(t);
    return magT > VSMALL ? (mag(slip)/magT)*t : vector(Zero);
}


// ************************************************************************* //
