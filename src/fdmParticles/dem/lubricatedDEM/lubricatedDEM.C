/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "lubricatedDEM.H"
#include "pairSearch.H"
#include "delaunayPairs.H"
#include "mathematicalConstants.H"
#include "tensor.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::fdm::lubricatedDEM::searchDue() const
{
    if (timeSinceSearch_ >= GREAT)
    {
        return true;
    }
    if (delaunayInterval_ > 0)
    {
        return stepsSinceSearch_ >= delaunayInterval_;
    }

    // A pair not listed can close in by the fluctuation displacements of
    // both particles plus the affine shear across at most the reach
    scalar maxDisp = 0;
    forAll(displacementSinceSearch_, i)
    {
        maxDisp = max(maxDisp, magSqr(displacementSinceSearch_[i]));
    }
    const scalar lMax = 2*max(radius_) + pairs_.pairReach() + skin_;
    return
        2*std::sqrt(maxDisp) + mag(shearRate_)*lMax*timeSinceSearch_
     >= skin_;
}


void Foam::fdm::lubricatedDEM::searchPairs()
{
    const scalar listReach = 2*max(radius_) + pairs_.pairReach() + skin_;
    for (direction d = 0; d < 3; ++d)
    {
        if (box_.periodic(d) && 2*listReach >= box_.span()[d])
        {
            FatalErrorInFunction
                << "The cell is too small for the interaction range: edge "
                << box_.span()[d] << " along direction " << label(d)
                << " must exceed twice 2 a_max + cutoff a_max + skin = "
                << 2*listReach << " (the minimum image would miss pairs)."
                << nl << "    Enlarge the box or lower the cutoff"
                << abort(FatalError);
        }
    }

    if (delaunayInterval_ > 0)
    {
        findDelaunayPairs(box_, position_, radius_, near_);
    }
    else
    {
        findNearPairs
        (
            box_, position_, radius_, pairs_.pairReach() + skin_, near_
        );
    }

    // Two fixed spheres: their loads move nothing (and rows of a sheared
    // floor slide past each other)
    label kept = 0;
    for (const labelPair& p : near_)
    {
        if (mobile_[p.first()] || mobile_[p.second()])
        {
            near_[kept++] = p;
        }
    }
    near_.setSize(kept);
    displacementSinceSearch_ = Zero;
    timeSinceSearch_ = 0;
    stepsSinceSearch_ = 0;
    ++nSearches_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::lubricatedDEM::lubricatedDEM
(
    const periodicBox& box,
    const scalar shearRate,
    const lubricatedContact& model
)
:
    box_(box),
    shearRate_(shearRate),
    pairs_(model),
    dragViscosity_(0),
    isolatedDragViscosity_(0),
    isolatedBelow_(0),
    wallNormal_(vector::Y),
    wallPressure_(0),
    wallDamping_(1),
    wallLoad_(0),
    wallVelocity_(0),
    skin_(-1),
    delaunayInterval_(0),
    stepsSinceSearch_(0),
    timeSinceSearch_(GREAT),
    nSearches_(0),
    stabilityNumber_(0),
    time_(0)
{
    if (box_.periodic(vector::Y) && !box_.periodic(vector::X))
    {
        FatalErrorInFunction
            << "A cell periodic in y (Lees-Edwards images) must be periodic"
            << " in x as well" << abort(FatalError);
    }

    // The images' offset follows the time from here on (setTime)
    setTime(time_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::lubricatedDEM::setDelaunayNeighbours(const label interval)
{
    if (interval < 1)
    {
        FatalErrorInFunction
            << "Steps between Delaunay triangulations " << interval
            << " must be at least 1" << abort(FatalError);
    }
    delaunayInterval_ = interval;
    timeSinceSearch_ = GREAT;
}


Foam::label Foam::fdm::lubricatedDEM::addParticles
(
    const UList<point>& x,
    const UList<scalar>& radius,
    const scalar density,
    const UList<bool>& mobile
)
{
    // Every list grown once: appending sphere by sphere would copy each
    // list for every sphere (minutes at 10^5 spheres)
    const label start = size();
    const label n = start + x.size();
    position_.setSize(n);
    velocity_.setSize(n, Zero);
    spin_.setSize(n, Zero);
    radius_.setSize(n);
    mass_.setSize(n);
    inertia_.setSize(n);
    bodyForce_.setSize(n, Zero);
    mobile_.setSize(n);
    displacementSinceSearch_.setSize(n, Zero);
    loads_.force.setSize(n, Zero);
    loads_.torque.setSize(n, Zero);
    loads_.stresslet.setSize(n, Zero);
    forAll(x, k)
    {
        const label i = start + k;
        const scalar m = density*4.0/3.0*pi*pow3(radius[k]);
        position_[i] = box_.wrap(x[k]);
        radius_[i] = radius[k];
        mass_[i] = m;
        inertia_[i] = 0.4*m*sqr(radius[k]);
        mobile_[i] = mobile[k];
    }
    pairs_.addParticles(radius);
    timeSinceSearch_ = GREAT;
    return start;
}


Foam::label Foam::fdm::lubricatedDEM::addParticle
(
    const point& x,
    const scalar radius,
    const scalar density,
    const bool mobile
)
{
    return addParticles
    (
        List<point>(1, x), scalarList(1, radius), density, boolList(1, mobile)
    );
}


void Foam::fdm::lubricatedDEM::setIsolatedDrag
(
    const scalar viscosity,
    const label minInteractions
)
{
    isolatedDragViscosity_ = viscosity;
    isolatedBelow_ = minInteractions;
}


void Foam::fdm::lubricatedDEM::setPressureWall
(
    const labelList& spheres,
    const direction normal,
    const scalar pressure,
    const scalar damping
)
{
    for (const label i : spheres)
    {
        if (i < 0 || i >= size() || mobile_[i])
        {
            FatalErrorInFunction
                << "Pressure wall sphere " << i << " is not a fixed sphere"
                << abort(FatalError);
        }
    }
    if (box_.periodic(normal) || damping <= 0)
    {
        FatalErrorInFunction
            << "A pressure wall needs an open normal direction and a"
            << " positive damping" << abort(FatalError);
    }
    wall_ = spheres;
    wallNormal_ = normal;
    wallPressure_ = pressure;
    wallDamping_ = damping;
}


void Foam::fdm::lubricatedDEM::setTime(const scalar t)
{
    time_ = t;
    // Sheared images only across periodic y (Lees-Edwards); an open y
    // (gravity along the gradient) has none
    if (box_.periodic(vector::Y))
    {
        box_.setShearOffset(shearRate_*box_.span()[1]*time_);
    }
}


Foam::vector Foam::fdm::lubricatedDEM::labVelocity(const label i) const
{
    return velocity_[i] + vector(shearRate_*position_[i].y(), 0, 0);
}


Foam::symmTensor Foam::fdm::lubricatedDEM::stress(const label part) const
{
    const vector& L = box_.span();
    return sum(stresslets(part))/(L.x()*L.y()*L.z());
}


Foam::scalar Foam::fdm::lubricatedDEM::volumeFraction() const
{
    scalar V = 0;
    forAll(radius_, i)
    {
        if (mobile_[i])
        {
            V += 4.0/3.0*pi*pow3(radius_[i]);
        }
    }
    const vector& L = box_.span();
    return V/(L.x()*L.y()*L.z());
}


Foam::scalar Foam::fdm::lubricatedDEM::criticalTimeStep() const
{
    const lubricatedContact& law = model();
    const scalar k = max(law.stiffness(), law.tangentialStiffness());
    scalar dt = GREAT;
    forAll(mass_, i)
    {
        if (mobile_[i])
        {
            dt = min(dt, std::sqrt(mass_[i]/k));
            const scalar kSpin =
                law.tangentialStiffness()*sqr(radius_[i]);
            dt = min(dt, std::sqrt(inertia_[i]/kSpin));
        }
    }
    return dt;
}


// ************************************************************************* //
