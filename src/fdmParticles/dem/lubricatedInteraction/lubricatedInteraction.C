/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

\*---------------------------------------------------------------------------*/

#include "lubricatedInteraction.H"
#include "tensor.H"

#include <algorithm>

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

const char* Foam::fdm::lubricatedInteraction::stressPartName(const label part)
{
    static const char* names[nStressParts] =
        {"normalContact", "shearContact", "normalLubrication",
         "shearLubrication"};
    return names[part];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::lubricatedInteraction::lubricatedInteraction
(
    const lubricatedContact& model
)
:
    model_(model),
    shearRate_(0),
    maxRadius_(0),
    positions_(nullptr),
    radii_(nullptr),
    box_(nullptr),
    externalForce_(nullptr),
    stresslet_(nStressParts),
    nInteractions_(0),
    nContacts_(0),
    nCrushed_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdm::lubricatedInteraction::resetLoads(const label n)
{
    pairForce_.setSize(pairs_.size());
    pairForce_ = Zero;
    if (externalForce_)
    {
        force_ = *externalForce_;
    }
    else
    {
        force_.setSize(n);
        force_ = Zero;
    }
    torque_.setSize(n);
    torque_ = Zero;
    contactForce_.setSize(n);
    contactForce_ = Zero;
    contactTorque_.setSize(n);
    contactTorque_ = Zero;
    for (List<symmTensor>& s : stresslet_)
    {
        s.setSize(n);
        s = Zero;
    }
    totals_ = particleTotals
    {
        List<symmTensor>(n, Zero),
        List<symmTensor>(model_.twoSphereHydrodynamics() ? n : 0, Zero),
        labelList(n, Zero),
        scalarList(n, Zero),
        scalarList(n, Zero)
    };
    nInteractions_ = 0;
    nContacts_ = 0;
    nCrushed_ = 0;
}


void Foam::fdm::lubricatedInteraction::advancePair
(
    const label k,
    const List<vector>& U,
    const List<vector>& Omega,
    const scalar dt,
    const scalar logCrushed
)
{
    const label i = pairs_.pair(k).first();
    const label j = pairs_.pair(k).second();
    const UList<point>& x = *positions_;
    const UList<scalar>& r = *radii_;
    const vector l = box_->minimumImage(x[j] - x[i]);
    const scalar dist = mag(l);
    const scalar a = 0.5*(r[i] + r[j]);
    const scalar un = dist - r[i] - r[j];
    if (!model_.interacts(un, a))
    {
        pairs_[k].active = false;
        return;
    }
    if (!pairs_[k].active)
    {
        pairs_[k].state = model_.start(un, a);
        pairs_[k].active = true;
    }

    const vector nij = l/dist;
    const scalar armI = r[i] + 0.5*un;
    const scalar armJ = r[j] + 0.5*un;

    // Relative velocity of the surfaces, the affine shear across the branch
    // vector included (frame-invariant: zero for a pair in rigid-body
    // motion)
    vector dv = U[j] - U[i];
    dv.x() += shearRate_*l.y();
    const vector contactVelocity = model_.surfaceVelocity
    (
        dv, nij, un, r[i], r[j], Omega[i], Omega[j]
    );
    const vector w = Omega[j] - Omega[i];

    const lubricatedPairLoads loads = model_.step
    (
        {nij, un, a, contactVelocity, w, 0.5*(Omega[i] + Omega[j])},
        dt,
        pairs_[k].state
    );
    const vector F = loads.force(nij);
    force_[i] += F;
    force_[j] -= F;
    pairForce_[k] = F;
    addPairSums(loads, nij, w, armI, armJ, i, j);
    if (model_.twoSphereHydrodynamics())
    {
        pairForce_[k] += addTwoBodyLoads(k, U, Omega, nij, un, armI, armJ);
    }

    ++nInteractions_;
    if (pairs_[k].state.contact)
    {
        ++nContacts_;
        if (pairs_[k].state.logGap < logCrushed)
        {
            ++nCrushed_;
        }
    }
}


void Foam::fdm::lubricatedInteraction::addPairSums
(
    const lubricatedPairLoads& loads,
    const vector& nij,
    const vector& w,
    const scalar armI,
    const scalar armJ,
    const label i,
    const label j
)
{
    const vector Fs = loads.shearContact + loads.shearLubrication;
    const vector wn = (w & nij)*nij;
    const vector Tv = loads.rollingDamping*(w - wn) + loads.twistingDamping*wn;
    torque_[i] += armI*(nij ^ Fs) + Tv;
    torque_[j] += armJ*(nij ^ Fs) - Tv;
    const vector Fc = loads.normalContact*nij + loads.shearContact;
    contactForce_[i] += Fc;
    contactForce_[j] -= Fc;
    contactTorque_[i] += armI*(nij ^ loads.shearContact);
    contactTorque_[j] += armJ*(nij ^ loads.shearContact);

    const vector parts[nStressParts] =
    {
        loads.normalContact*nij,
        loads.shearContact,
        loads.normalLubrication*nij,
        loads.shearLubrication
    };
    for (label p = 0; p < nStressParts; ++p)
    {
        const symmTensor S = symm(parts[p]*nij);
        stresslet_[p][i] += armI*S;
        stresslet_[p][j] += armJ*S;
    }

    // The point-implicit totals
    const symmTensor nn = sqr(nij);
    const symmTensor D =
        loads.rollingDamping*(symmTensor::I - nn) + loads.twistingDamping*nn;
    totals_.damping[i] += D;
    totals_.damping[j] += D;
    const scalar kSum = loads.normalStiffness + loads.shearStiffness;
    totals_.stiffness[i] += kSum;
    totals_.stiffness[j] += kSum;
    totals_.spinStiffness[i] += loads.shearStiffness*sqr(armI);
    totals_.spinStiffness[j] += loads.shearStiffness*sqr(armJ);
    ++totals_.nNeighbours[i];
    ++totals_.nNeighbours[j];
}


Foam::vector Foam::fdm::lubricatedInteraction::addTwoBodyLoads
(
    const label k,
    const List<vector>& U,
    const List<vector>& Omega,
    const vector& nij,
    const scalar un,
    const scalar armI,
    const scalar armJ
)
{
    const label i = pairs_.pair(k).first();
    const label j = pairs_.pair(k).second();

    // Velocities relative to the ambient shear: the given velocities
    // already are (whatever the periodic image), the spins less the
    // flow's; the squeeze is the implicit normal model's
    const vector flowSpin(0, 0, -0.5*shearRate_);
    const symmTensor E(0, 0.5*shearRate_, 0, 0, 0, 0);
    const twoSphereLoads h = model_.twoBody().loads
    (
        nij, un, (*radii_)[i], (*radii_)[j],
        U[i], Omega[i] - flowSpin,
        U[j], Omega[j] - flowSpin,
        E, false
    );
    force_[i] += h.force[0];
    force_[j] += h.force[1];
    torque_[i] += h.torque[0];
    torque_[j] += h.torque[1];
    totals_.translationDamping[i] += h.translationDamping[0];
    totals_.translationDamping[j] += h.translationDamping[1];
    totals_.damping[i] += h.rotationDamping[0];
    totals_.damping[j] += h.rotationDamping[1];

    // Stress parts as for the thesis forms: each force at the mid-gap
    // point, split along n (normal lubrication) and across (shear)
    const scalar arm[2] = {armI, -armJ};
    const label particle[2] = {i, j};
    for (label s = 0; s < 2; ++s)
    {
        const vector Fn = (h.force[s] & nij)*nij;
        stresslet_[normalLubrication][particle[s]] += arm[s]*symm(Fn*nij);
        stresslet_[shearLubrication][particle[s]] +=
            arm[s]*symm((h.force[s] - Fn)*nij);
    }
    return h.force[0];
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::lubricatedInteraction::addParticles
(
    const UList<scalar>& radii
)
{
    const label n = force_.size() + radii.size();
    for (const scalar r : radii)
    {
        maxRadius_ = max(maxRadius_, r);
    }
    force_.setSize(n, Zero);
    torque_.setSize(n, Zero);
    contactForce_.setSize(n, Zero);
    contactTorque_.setSize(n, Zero);
    for (List<symmTensor>& s : stresslet_)
    {
        s.setSize(n, Zero);
    }
}


void Foam::fdm::lubricatedInteraction::update(const pairStepInput& in)
{
    shearRate_ = in.shearRate;

    // Carry the history of pairs listed before; a new pair starts
    // inactive with a defined state (written to particleState even before
    // it interacts)
    const UList<labelPair>& listed = pairs_.pairs();
    const bool sameList =
        listed.size() == in.near.size()
     && std::equal(listed.begin(), listed.end(), in.near.begin());
    if (!sameList)
    {
        pairs_.carry(in.near, {lubricatedPairState{0, false, Zero}, false});
    }

    positions_ = &in.positions;
    radii_ = &in.radii;
    box_ = &in.box;
}


void Foam::fdm::lubricatedInteraction::advance
(
    const List<vector>& U,
    const List<vector>& Omega,
    const scalar dt
)
{
    resetLoads(positions_->size());
    // Smooth spheres (roughness 0) never touch: no crushed threshold
    const scalar logCrushed =
        model_.roughness() > 0 ? std::log(0.01*model_.roughness()) : -GREAT;
    forAll(pairs_, k)
    {
        advancePair(k, U, Omega, dt, logCrushed);
    }
}


void Foam::fdm::lubricatedInteraction::addSolvedLoads
(
    const List<vector>& U,
    const List<vector>& Omega,
    const fluidProperties& fluid,
    particleLoads& loads,
    List<scalar>& dipoleTrace
) const
{
    forAll(force_, i)
    {
        loads.force[i] += force_[i];
        loads.torque[i] += torque_[i];
        for (const List<symmTensor>& s : stresslet_)
        {
            loads.stresslet[i] += s[i];
        }
    }
}


Foam::fdm::contactNetwork Foam::fdm::lubricatedInteraction::network
(
    const UList<point>& positions,
    const periodicBox& box
) const
{
    contactNetwork links;
    forAll(pairForce_, k)
    {
        const vector& F = pairForce_[k];
        if (F != vector::zero)
        {
            const label i = pairs_.pair(k).first();
            const label j = pairs_.pair(k).second();
            links.append
            (
                contactLink::split
                (
                    i, j, box.minimumImage(positions[j] - positions[i]), F
                )
            );
        }
    }
    return links;
}


// ************************************************************************* //
