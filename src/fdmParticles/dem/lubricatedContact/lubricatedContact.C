/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "lubricatedContact.H"
#include "mathematicalConstants.H"

#include <cmath>

using Foam::constant::mathematical::pi;

const Foam::Enum<Foam::fdm::lubricatedContact::shearArms>
Foam::fdm::lubricatedContact::shearArmsNames
({
    {shearArms::contactPoint, "contactPoint"},
    {shearArms::radius, "radius"},
});

const Foam::Enum<Foam::fdm::lubricatedContact::asperities>
Foam::fdm::lubricatedContact::asperitiesNames
({
    {asperities::outside, "outside"},
    {asperities::inside, "inside"},
});

const Foam::Enum<Foam::fdm::lubricatedContact::torqueForms>
Foam::fdm::lubricatedContact::torqueFormsNames
({
    {torqueForms::thesis, "thesis"},
    {torqueForms::article2Code, "article2Code"},
    {torqueForms::none, "none"},
});

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fdm::lubricatedContact::gapUpdate
(
    const scalar logOld,
    const scalar un,
    const scalar alphaEps,
    const scalar alpha,
    const scalar dtStar,
    scalar& gap,
    scalar& dGapdUn
)
{
    // Positive root of A x^2 - B x - C = 0 (eq 17), C > 0: the product of
    // the roots is -C/A < 0, so exactly one is positive.  For B < 0 the
    // usual form subtracts nearly equal numbers when u and u_n are tiny
    // (article 1, eq 22); the conjugate form 2C/(sqrt(B^2 + 4AC) - B) does
    // not, and taken in logs it stays exact when C underflows (a smooth pair
    // pressed for long closes as exp(-t), below the smallest double).
    const scalar A = 1 + alpha;
    const scalar B = un + alphaEps - 1/dtStar;
    const scalar C = std::exp(logOld)/dtStar;
    const scalar root = std::sqrt(B*B + 4*A*C);
    const scalar logX =
        (B >= 0)
      ? std::log((B + root)/(2*A))
      : std::log(2.0) + logOld - std::log(dtStar) - std::log(root - B);

    // Implicit differentiation of the quadratic: (2 A x - B) dx = x dB
    gap = std::exp(logX);
    dGapdUn = gap/(2*A*gap - B);
    return logX;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::lubricatedContact::lubricatedContact
(
    const scalar viscosity,
    const scalar stiffness,
    const scalar stiffnessRatio,
    const scalar tangentialStiffness,
    const scalar roughness,
    const scalar friction,
    const scalar cutoff,
    const shearArms arms,
    const asperities where
)
:
    viscosity_(viscosity),
    g_(stiffness),
    stiffnessRatio_(stiffnessRatio),
    kt_(tangentialStiffness*stiffness),
    roughness_(roughness),
    friction_(friction),
    cutoff_(cutoff),
    arms_(arms),
    asperities_(where),
    torques_(torqueForms::thesis)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fdm::lubricatedPairState Foam::fdm::lubricatedContact::start
(
    const scalar centreGap,
    const scalar meanRadius
) const
{
    const scalar u = max(centreGap/meanRadius + gapShift(), 1e-12);
    return {std::log(u), u < roughness_, Zero};
}


Foam::scalar Foam::fdm::lubricatedContact::shearLubricationCoefficient
(
    const scalar logGap,
    const scalar meanRadius
) const
{
    // ln((2a + u)/u) from ln(u/a): finite however small u is
    const scalar u = std::exp(logGap);
    return
        0.5*pi*viscosity_*meanRadius
       *(-2 + (2 + u)*(std::log(2 + u) - logGap));
}


Foam::vector Foam::fdm::lubricatedContact::surfaceVelocity
(
    const vector& dv,
    const vector& n,
    const scalar centreGap,
    const scalar radius1,
    const scalar radius2,
    const vector& spin1,
    const vector& spin2
) const
{
    if (arms_ == shearArms::contactPoint)
    {
        const scalar half = 0.5*centreGap;
        return dv - (radius2 + half)*(spin2 ^ n) - (radius1 + half)*(spin1 ^ n);
    }
    const scalar sum = radius1 + radius2;
    return sum/(sum + centreGap)*dv - radius2*(spin2 ^ n) - radius1*(spin1 ^ n);
}


Foam::scalar Foam::fdm::lubricatedContact::normalStep
(
    const lubricatedPairMotion& m,
    const scalar dt,
    lubricatedPairState& state,
    lubricatedPairLoads& loads
) const
{
    // Implicit gap update (A.5-A.7), split at a contact change
    const scalar a = m.meanRadius;
    const scalar eps = roughness_;
    const scalar un = m.centreGap/a + gapShift();
    const scalar kRatio = stiffnessRatio_;

    scalar logU = state.logGap;
    scalar u = std::exp(logU);
    bool contact = state.contact;
    scalar remaining = dt*g_/(1.5*pi*viscosity_*a);
    scalar dGapdUn = 0;

    for (label pass = 0; pass < 3; ++pass)
    {
        const scalar alpha = contact ? kRatio : 0;
        scalar x;
        const scalar logX = gapUpdate
        (
            logU, un, alpha*eps, alpha, remaining, x, dGapdUn
        );
        const bool contactNew = x < eps;
        if (contactNew == contact || pass == 2)
        {
            logU = logX;
            u = x;
            break;
        }

        // Eq 20, numerator u*- - eps (printed the other way round, which
        // makes t_c negative for an approaching pair): when u reaches eps
        const scalar tc = (u - eps)/(eps*(eps - un));
        if (!(tc > 0 && tc < remaining))
        {
            // Rounding at the threshold: redo the step in the new state
            contact = contactNew;
            continue;
        }
        logU = std::log(eps);
        u = eps;
        remaining -= tc;
        contact = contactNew;
    }

    state.logGap = logU;
    state.contact = u < eps;

    const scalar kn = kRatio*g_;
    loads.normalContact = -kn*a*max(scalar(0), eps - u);
    loads.normalLubrication = g_*a*(un - u) - loads.normalContact;
    loads.normalStiffness = g_*(1 - dGapdUn);
    return u;
}


void Foam::fdm::lubricatedContact::shearStep
(
    const lubricatedPairMotion& m,
    const scalar dt,
    lubricatedPairState& state,
    lubricatedPairLoads& loads
) const
{
    const vector& n = m.normal;
    const scalar a = m.meanRadius;

    // Tangential: turn the stored force with the pair (A.8)
    vector Fs = state.shearForce;
    const scalar magFs = mag(Fs);
    if (magFs > 0)
    {
        Fs -= (Fs & n)*n;
        const scalar magT = mag(Fs);
        Fs = (magT > VSMALL*magFs) ? Fs*(magFs/magT) : vector(Zero);

        const scalar angle = (m.meanSpin & n)*dt;
        Fs = std::cos(angle)*Fs + std::sin(angle)*(n ^ Fs);
    }

    const vector slip = (m.contactVelocity - (m.contactVelocity & n)*n)*dt;
    // twoSphere: the tangential lubrication is in the two-body
    // hydrodynamics, not in series with the spring
    const scalar nut =
        twoBody_ ? 0 : shearLubricationCoefficient(state.logGap, a);
    const scalar ktDt = kt_*dt;
    const vector trial = Fs + kt_*slip;        // eq 29 (force on 1)

    loads.shearContact = Zero;
    if (!state.contact)
    {
        // Maxwell element (eq 27)
        Fs = nut/(nut + ktDt)*trial;
        loads.shearLubrication = Fs;
        loads.shearStiffness = kt_*nut/(nut + ktDt);
    }
    else
    {
        const scalar cap = friction_*mag(loads.normalContact);
        const scalar magTrial = mag(trial);
        if (magTrial <= cap)
        {
            // Sticking: no tangential lubrication (eq 28-29)
            Fs = trial;
            loads.shearContact = Fs;
            loads.shearLubrication = Zero;
            loads.shearStiffness = kt_;
        }
        else
        {
            // Slipping (eq 33): Coulomb part along the trial force,
            // lubrication on the plastic slip for the rest
            Fs = trial*(nut + ktDt*cap/magTrial)/(nut + ktDt);
            loads.shearContact = cap/magTrial*trial;
            loads.shearLubrication = Fs - loads.shearContact;
            loads.shearStiffness = kt_*nut/(nut + ktDt);
        }
    }
    state.shearForce = Fs;
}


Foam::fdm::lubricatedPairLoads Foam::fdm::lubricatedContact::step
(
    const lubricatedPairMotion& m,
    const scalar dt,
    lubricatedPairState& state
) const
{
    const scalar a = m.meanRadius;
    lubricatedPairLoads loads;
    const scalar u = normalStep(m, dt, state, loads);
    shearStep(m, dt, state, loads);

    // Rolling and twisting resistance while u <= a (A.3); twoSphere: in
    // the two-body hydrodynamics
    if (u <= 1 && !twoBody_ && torques_ != torqueForms::none)
    {
        const scalar logInv = -state.logGap;
        const scalar leading =
            torques_ == torqueForms::thesis ? 1.5 : 0.15;
        loads.rollingDamping =
            pi*viscosity_*a*a*a*(leading + 0.126*u)*logInv;
        loads.twistingDamping = pi*viscosity_*a*a*a*u*logInv;
    }
    else
    {
        loads.rollingDamping = 0;
        loads.twistingDamping = 0;
    }

    return loads;
}


// ************************************************************************* //
