/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    One step of the lubricated DEM: the pair loads of the implicit
    lubricated contact model (thesis 2, article 1 eqs 14-23) through its
    pair interaction, the pressure wall, and the leapfrog with
    point-implicit drag and viscous torques (thesis 2 eqs 2.3-2.5).

\*---------------------------------------------------------------------------*/

#include "lubricatedDEM.H"
#include "mathematicalConstants.H"
#include "tensor.H"
#include "scalarField.H"
#include "isFinite.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdm::lubricatedDEM::addPairLoads(const scalar dt)
{
    loads_.force = Zero;
    loads_.torque = Zero;
    loads_.stresslet = Zero;

    // The steps of a pair interaction, as the FDM cloud runs them; the
    // velocities relative to the affine flow.  The pair forces add to the
    // weights one by one
    pairs_.setExternalForce(bodyForce_);
    pairInteraction& pairs = pairs_;
    const positionStep step(positionStep::euler(dt));
    pairs.update
    ({
        position_, radius_, box_, near_, step, velocity_, shearRate_,
        labelList()
    });
    pairs.advance(velocity_, spin_, dt);
    List<scalar> noDipoleTrace;
    pairs.addSolvedLoads
    (
        velocity_, spin_, fluidProperties{1, model().viscosity()}, loads_,
        noDipoleTrace
    );
}


void Foam::fdm::lubricatedDEM::movePressureWall(const scalar dt)
{
    // Overdamped motion along its normal under the load of the spheres and
    // the imposed pressure, c v_w = F_n - P A (the servo of article 2,
    // without its unpublished gains)
    wallLoad_ = 0;
    for (const label i : wall_)
    {
        wallLoad_ += loads_.force[i][wallNormal_];
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


void Foam::fdm::lubricatedDEM::advanceParticles(const scalar dt)
{
    const lubricatedInteraction::particleTotals& totals = pairs_.totals();
    const bool twoBody = model().twoSphereHydrodynamics();
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
            loads_.force[i] - cDrag*v - m*shearRate_*v.y()*vector(1, 0, 0);
        if (twoBody)
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

        const vector T = loads_.torque[i] - cSpin*(spin_[i] - flowSpin);
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

    addPairLoads(dt);

    if (wall_.size())
    {
        movePressureWall(dt);
    }

    // Leapfrog with point-implicit drag and viscous torques
    advanceParticles(dt);

    timeSinceSearch_ += dt;
    ++stepsSinceSearch_;
    setTime(time_ + dt);
    forAll(position_, i)
    {
        position_[i] = box_.wrap(position_[i]);
    }
}


// ************************************************************************* //
