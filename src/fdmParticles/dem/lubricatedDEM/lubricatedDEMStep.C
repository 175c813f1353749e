/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    One step of the lubricated DEM: the pair loads of the implicit
    lubricated contact model (thesis 2, article 1 eqs 14-23), the pressure
    wall, and the leapfrog with point-implicit drag and viscous torques
    (thesis 2 eqs 2.3-2.5).

\*---------------------------------------------------------------------------*/

#include "lubricatedDEM.H"
#include "mathematicalConstants.H"
#include "tensor.H"
#include "scalarField.H"
#include "isFinite.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fdm::lubricatedDEM::stepTotals
Foam::fdm::lubricatedDEM::resetLoads()
{
    const label n = size();
    force_ = bodyForce_;
    torque_ = Zero;
    contactForce_ = Zero;
    contactTorque_ = Zero;
    for (List<symmTensor>& s : stresslet_)
    {
        s = Zero;
    }
    nInteractions_ = 0;
    nContacts_ = 0;
    nCrushed_ = 0;
    pairForce_.setSize(pairs_.size());
    pairForce_ = Zero;
    return stepTotals
    {
        List<symmTensor>(n, Zero),
        List<symmTensor>(model_.twoSphereHydrodynamics() ? n : 0, Zero),
        labelList(n, Zero),
        scalarList(n, Zero),
        scalarList(n, Zero)
    };
}


void Foam::fdm::lubricatedDEM::addPairLoads
(
    const label k,
    const scalar dt,
    const scalar logCrushed,
    stepTotals& totals
)
{
    const label i = pairs_.pair(k).first();
    const label j = pairs_.pair(k).second();
    if (!mobile_[i] && !mobile_[j])
    {
        // Two floor spheres: their loads move nothing (and rows of a
        // sheared floor slide past each other)
        return;
    }
    const vector l = box_.minimumImage(position_[j] - position_[i]);
    const scalar dist = mag(l);
    const scalar a = 0.5*(radius_[i] + radius_[j]);
    const scalar un = dist - radius_[i] - radius_[j];

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
    const scalar armI = radius_[i] + 0.5*un;
    const scalar armJ = radius_[j] + 0.5*un;

    // Relative velocity of the surfaces, the affine shear across the branch
    // vector included (frame-invariant: zero for a pair in rigid-body
    // motion)
    vector dv = velocity_[j] - velocity_[i];
    dv.x() += shearRate_*l.y();
    const vector contactVelocity = model_.surfaceVelocity
    (
        dv, nij, un, radius_[i], radius_[j], spin_[i], spin_[j]
    );
    const vector w = spin_[j] - spin_[i];

    const lubricatedPairLoads loads = model_.step
    (
        {nij, un, a, contactVelocity, w, 0.5*(spin_[i] + spin_[j])},
        dt,
        pairs_[k].state
    );

    const vector F = loads.force(nij);
    const vector Fs = loads.shearContact + loads.shearLubrication;
    const vector wn = (w & nij)*nij;
    const vector Tv = loads.rollingDamping*(w - wn) + loads.twistingDamping*wn;

    force_[i] += F;
    force_[j] -= F;
    pairForce_[k] = F;
    torque_[i] += armI*(nij ^ Fs) + Tv;
    torque_[j] += armJ*(nij ^ Fs) - Tv;
    const vector Fc = loads.normalContact*nij + loads.shearContact;
    contactForce_[i] += Fc;
    contactForce_[j] -= Fc;
    contactTorque_[i] += armI*(nij ^ loads.shearContact);
    contactTorque_[j] += armJ*(nij ^ loads.shearContact);

    addStresslets(loads, nij, armI, armJ, i, j);
    addToTotals(loads, nij, armI, armJ, i, j, totals);
    if (model_.twoSphereHydrodynamics())
    {
        pairForce_[k] += addTwoBodyLoads(i, j, nij, un, armI, armJ, totals);
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


Foam::vector Foam::fdm::lubricatedDEM::addTwoBodyLoads
(
    const label i,
    const label j,
    const vector& nij,
    const scalar un,
    const scalar armI,
    const scalar armJ,
    stepTotals& totals
)
{
    // Velocities relative to the ambient shear: the stored velocities
    // already are (whatever the periodic image), the spins less the
    // flow's; the squeeze is the implicit normal model's
    const vector flowSpin(0, 0, -0.5*shearRate_);
    const symmTensor E(0, 0.5*shearRate_, 0, 0, 0, 0);
    const twoSphereLoads h = model_.twoBody().loads
    (
        nij, un, radius_[i], radius_[j],
        velocity_[i], spin_[i] - flowSpin,
        velocity_[j], spin_[j] - flowSpin,
        E, false
    );
    force_[i] += h.force[0];
    force_[j] += h.force[1];
    torque_[i] += h.torque[0];
    torque_[j] += h.torque[1];
    totals.translationDamping[i] += h.translationDamping[0];
    totals.translationDamping[j] += h.translationDamping[1];
    totals.damping[i] += h.rotationDamping[0];
    totals.damping[j] += h.rotationDamping[1];

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


void Foam::fdm::lubricatedDEM::addToTotals
(
    const lubricatedPairLoads& loads,
    const vector& nij,
    const scalar armI,
    const scalar armJ,
    const label i,
    const label j,
    stepTotals& totals
) const
{
    const symmTensor nn = sqr(nij);
    const symmTensor D =
        loads.rollingDamping*(symmTensor::I - nn) + loads.twistingDamping*nn;
    totals.damping[i] += D;
    totals.damping[j] += D;

    const scalar kSum = loads.normalStiffness + loads.shearStiffness;
    totals.stiffness[i] += kSum;
    totals.stiffness[j] += kSum;
    totals.spinStiffness[i] += loads.shearStiffness*sqr(armI);
    totals.spinStiffness[j] += loads.shearStiffness*sqr(armJ);

    ++totals.nNeighbours[i];
    ++totals.nNeighbours[j];
}


void Foam::fdm::lubricatedDEM::addStresslets
(
    const lubricatedPairLoads& loads,
    const vector& nij,
    const scalar armI,
    const scalar armJ,
    const label i,
    const label j
)
{
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
}


void Foam::fdm::lubricatedDEM::movePressureWall(const scalar dt)
{
    // Overdamped motion along its normal under the load of the spheres and
    // the imposed pressure, c v_w = F_n - P A (the servo of article 2,
    // without its unpublished gains)
    wallLoad_ = 0;
    for (const label i : wall_)
    {
        wallLoad_ += force_[i][wallNormal_];
    }
    const vector& L = box_.span();
    const scalar area = L.x()*L.y()*L.z()/L[wallNormal_];
    wallVelocity_ = (wallLoad_ - wallPressure_*area)/wallDamping_;
    for (const label i : wall_)
    {
        velocity_[i][wallNormal_] = wallVelocity_;
        position_[i][wallNormal_] += dt*wallVelocity_;
        displacementSinceSearch_[i][wallNormal_] += dt*wallVelocity_;
    }
}


void Foam::fdm::lubricatedDEM::checkDisplacement
(
    const label i,
    const vector& dx
) const
{
    // No sound step moves a sphere by a quarter of the cell: the step has
    // diverged (before the position overflows or turns NaN)
    if (!isFinite(dx) || mag(dx) > 0.25*cmptMin(box_.span()))
    {
        FatalErrorInFunction
            << "Time " << time_ << ": particle " << i << " would move by "
            << dx << " in one step (cell " << box_.span() << "): the step"
            << " diverged.  Lower deltaT in system/controlDict (stability"
            << " number of the last step " << stabilityNumber_ << ")." << nl
            << "    Last good state: the latest time directory"
            << exit(FatalError);
    }
}


void Foam::fdm::lubricatedDEM::advanceParticles
(
    const scalar dt,
    const stepTotals& totals
)
{
    stabilityNumber_ = 0;
    const vector flowSpin(0, 0, -0.5*shearRate_);
    for (label i = 0; i < size(); ++i)
    {
        if (!mobile_[i])
        {
            // Fixed (wall) spheres are carried by the affine flow
            position_[i].x() += dt*shearRate_*position_[i].y();
            continue;
        }
        const scalar m = mass_[i];
        const scalar J = inertia_[i];
        const scalar a = radius_[i];
        const scalar drag =
            dragViscosity_
          + (
                totals.nNeighbours[i] < isolatedBelow_
              ? isolatedDragViscosity_
              : 0
            );
        const scalar cDrag = 6*pi*drag*a;
        const scalar cSpin = 8*pi*drag*pow3(a);

        vector& v = velocity_[i];
        const vector F =
            force_[i] - cDrag*v - m*shearRate_*v.y()*vector(1, 0, 0);
        if (model_.twoSphereHydrodynamics())
        {
            // The two-body damping point-implicit too
            const tensor M =
                (m + dt*cDrag)*tensor::I + dt*totals.translationDamping[i];
            v += inv(M) & (dt*F);
        }
        else
        {
            v += dt/(m + dt*cDrag)*F;
        }

        const vector T = torque_[i] - cSpin*(spin_[i] - flowSpin);
        const tensor M =
            J*tensor::I + dt*(totals.damping[i] + cSpin*symmTensor::I);
        spin_[i] += inv(M) & (dt*T);

        vector dx = dt*v;
        dx.x() += dt*shearRate_*(position_[i].y() + 0.5*dt*v.y());
        checkDisplacement(i, dx);
        position_[i] += dx;
        displacementSinceSearch_[i] += dt*v;

        stabilityNumber_ = max
        (
            stabilityNumber_,
            0.5*dt*std::sqrt
            (
                2*max(totals.stiffness[i]/m, totals.spinStiffness[i]/J)
            )
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::lubricatedDEM::step(const scalar dt)
{
    if (skin_ < 0)
    {
        skin_ = 0.3*max(radius_);
    }
    if (searchDue())
    {
        searchPairs();
    }

    stepTotals totals = resetLoads();
    // Smooth spheres (roughness 0) never touch: no crushed threshold
    const scalar logCrushed =
        model_.roughness() > 0 ? std::log(0.01*model_.roughness()) : -GREAT;
    forAll(pairs_, k)
    {
        addPairLoads(k, dt, logCrushed, totals);
    }

    if (wall_.size())
    {
        movePressureWall(dt);
    }

    // Leapfrog with point-implicit drag and viscous torques
    advanceParticles(dt, totals);

    timeSinceSearch_ += dt;
    ++stepsSinceSearch_;
    setTime(time_ + dt);
    forAll(position_, i)
    {
        position_[i] = box_.wrap(position_[i]);
    }
}


// ************************************************************************* //
