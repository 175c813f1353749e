/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleContacts.H"
#include "pairSearch.H"
#include "contactLoads.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Action>
void Foam::particleContacts::forEachContact
(
    const fdm::pairStepInput& in,
    const Action& action
) const
{
    const pointField& positions = in.positions;
    const scalarField& radii = in.radii;
    const fdm::periodicBox& box = in.box;
    // action(key, geometry, arm of i, arm of j, wall or -1, velocity of
    // the image of j relative to j): the arm is the distance from the
    // centre to the contact point along n, the weight a_i r/(a_i + a_j) of
    // eqs 2.64 and 2.69
    DynamicList<labelPair> touching;
    fdm::selectNearPairs
    (
        box, positions, radii, pairReach(), in.near, touching
    );
    for (const labelPair& pq : touching)
    {
        const label i = pq.first(), j = pq.second();
        const vector between = positions[j] - positions[i];
        const vector r = box.minimumImage(between);
        const scalar d = mag(r);
        const scalar sum = radii[i] + radii[j];
        const fdm::contactGeometry g{r/d, d - sum, 0.5*gapFloor_*sum};
        if (law_->touching(g.gap))
        {
            action
            (
                key(i, j), g, radii[i]*d/sum, radii[j]*d/sum, -1,
                box.imageVelocity(between)
            );
        }
    }
    forAll(walls_.walls(), w)
    {
        const planeWalls::wall& wall = walls_.walls()[w];
        forAll(positions, i)
        {
            if (!in.holds(i))
            {
                continue;
            }
            const fdm::contactGeometry g
            {
                wall.normal,
                wall.distance(positions[i]) - radii[i],
                gapFloor_*radii[i]
            };
            if (law_->touching(g.gap))
            {
                action(key(i, -1 - w), g, radii[i], 0, w, vector::zero);
            }
        }
    }
}


void Foam::particleContacts::linearise(const UList<scalar>& gaps)
{
    loads_.force = Zero;
    loads_.torque = Zero;
    loads_.stresslet = Zero;
    nSliding_ = 0;

    fdm::pairHistory<vector> current;
    forAll(gaps, c)
    {
        contactEntry& e = contacts_[c];
        const fdm::contactGeometry& g0 = e.geometry;
        const label i = e.k.first();
        const label j = e.spring.j();

        // The law at the linearisation gap g*, and the elastic force at
        // the end gap g_e = g0 - dt (current w + previous w_old) as
        // F(g*) + k'(g*) (g* - g_e), k' = -dF/d(gap): the part in the
        // unknown approach rate w goes into the matrix, the rest here
        fdm::contactGeometry g = g0;
        g.gap = gaps[c];
        vector slip = e.slip0;
        fdm::contactForce f = law_->evaluate(g, slip);
        const scalar k = law_->normalStiffness(g.gap, g.floorGap);
        f.force -= k*(g.gap - g0.gap + e.oldApproach)*g0.normal;

        e.linearisationGap = g.gap;
        e.force = f.force;
        e.spring = fdm::implicitContactSpring
        (
            i, j, g0.normal, e.armI, e.armJ, k*step_.dt*step_.current,
            f.tangentialStiffness*step_.dt, e.spring.knownVelocity()
        );
        fdm::addContactLoads(f, g0.normal, e.armI, e.armJ, i, j, loads_);
        current.append(e.k, slip);
        nSliding_ += f.sliding && e.counted;
    }
    current.sort();
    slip_ = std::move(current);
}


Foam::List<Foam::scalar> Foam::particleContacts::startGaps() const
{
    // Linearised at the start gap; a gap at the barrier's floor (within
    // 1e-4 h_r of it, or below it: crossed in the last step) is taken a
    // hundredth of h_r above the floor, where the barrier's stiffness is
    // finite.  At the floor (x = 1e-6 in eq 2.57) k' dt is about 1e8 times
    // a resistance of the lubrication's size, and the particle velocity
    // solve of a dense suspension stopped converging (phi0 = 0.52, strain
    // 0.754: 3 gaps below the floor, CG residual 1.7e4 after 1000
    // iterations).  Gaps above that keep their own linearisation, so that
    // a contact resting on the barrier rests at its balance.
    const scalar hr = law_->roughness();
    List<scalar> gaps(contacts_.size());
    forAll(gaps, c)
    {
        const fdm::contactGeometry& g = contacts_[c].geometry;
        gaps[c] = g.gap < g.floorGap + 1e-4*hr
          ? g.floorGap + 1e-2*hr
          : g.gap;
    }
    return gaps;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleContacts::particleContacts
(
    const dictionary& dict,
    const fvMesh& mesh,
    const fdm::contactLaw::scales& s,
    const scalar gapFloor,
    const label nParticles
)
:
    mesh_(mesh),
    law_(fdm::contactLaw::New(dict, s)),
    walls_(mesh, "particle-wall contact"),
    gapFloor_(gapFloor),
    step_(fdm::positionStep::euler(0)),
    relinearisations_(0),
    loads_(nParticles),
    nPairs_(0),
    nWalls_(0),
    nSliding_(0),
    nBelowFloor_(0),
    minGap_(GREAT),
    sharedCounts_(false)
{
    law_->writeInfo(Info);
    Info<< "    contacts with " << walls_.size() << " plane wall(s)" << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleContacts::update(const fdm::pairStepInput& in)
{
    const scalarField& radii = in.radii;
    const fdm::positionStep& step = in.step;
    step_ = step;
    // The slip of the contacts of a particle that changed rank goes with it
    fdm::shareWithOwners(slip_, in.owner);
    sharedCounts_ = !in.owner.empty();
    relinearisations_ = 0;
    contacts_.clear();
    List<vector> wallVelocity(walls_.size());
    forAll(walls_.walls(), w)
    {
        wallVelocity[w] = walls_.velocity(walls_.walls()[w]);
    }
    nPairs_ = nWalls_ = nBelowFloor_ = 0;
    minGap_ = GREAT;
    // The contact of the smallest gap, for the messages
    key closest(-1, -1);
    bool closestAcrossShear = false;

    forEachContact
    (
        in,
        [&](const key& k, const fdm::contactGeometry& g, const scalar armI,
            const scalar armJ, const label wall, const vector& imageU)
        {
            const label i = k.first();
            const label j = wall < 0 ? k.second() : -1;
            // The partner's known velocity: the wall's, or its image's
            const fdm::implicitContactSpring spring
            (
                i, j, g.normal, armI, armJ, 0, 0,
                wall < 0 ? imageU : wallVelocity[wall]
            );
            contacts_.push_back
            (
                contactEntry
                {
                    k, g, armI, armJ, slip_.get(k, Zero),
                    // The gap closed by the previous velocities' share of
                    // the step (none for a first, forward-Euler step)
                    step.previous == 0
                  ? 0
                  : step.dt*step.previous*spring.approach(in.Uold),
                    g.gap,
                    spring,
                    Zero,
                    (g.gap + radii[i] + (wall < 0 ? radii[j] : 0))*g.normal,
                    in.holds(i)
                }
            );
            if (in.holds(i))
            {
                ++(wall < 0 ? nPairs_ : nWalls_);
            }
            nBelowFloor_ += g.gap < g.floorGap;
            if (g.gap < minGap_)
            {
                minGap_ = g.gap;
                closest = k;
                closestAcrossShear = wall < 0 && magSqr(imageU) > 0;
            }
        }
    );
    linearise(startGaps());

    checkGaps(closest, closestAcrossShear);
    nPairs_ = in.total(nPairs_);
    nWalls_ = in.total(nWalls_);
    if (sharedCounts_)
    {
        reduce(minGap_, minOp<scalar>());
    }
}


void Foam::particleContacts::relinearise(const List<vector>& U)
{
    // A Newton step on the end-of-step balance of each contact: the gap
    // that the velocities U predict, kept off the barrier's floor (at most
    // nine tenths of the way to it from the last linearisation), where the
    // force of eq 2.57 diverges.  Two per step, then the linearisation is
    // held: the outer iterations converge to a fixed point of a fixed
    // particle system, and with a new one every iteration they diverged
    // now and then (phi0 = 0.47, strains 8.104 and 10.744)
    if (relinearisations_ >= 2)
    {
        return;
    }
    ++relinearisations_;
    List<scalar> gaps(contacts_.size());
    forAll(gaps, c)
    {
        const contactEntry& e = contacts_[c];
        const scalar predicted =
            e.geometry.gap - e.oldApproach
          - step_.dt*step_.current*e.spring.approach(U);
        const scalar last = e.linearisationGap;
        const scalar floorGap = e.geometry.floorGap;
        gaps[c] = max(predicted, floorGap + 0.1*(last - floorGap));
    }
    linearise(gaps);
}


void Foam::particleContacts::advance
(
    const List<vector>& U,
    const List<vector>& Omega,
    const scalar dt
)
{
    // The contacts of the last update, at the positions the particles are
    // about to leave, with the slip operator of their implicit stiffness
    for (const contactEntry& e : contacts_)
    {
        slip_[slip_.find(e.k)] += dt*e.spring.slip(U, Omega);
    }
}


void Foam::particleContacts::addTo
(
    fdm::particleSystemSink& system,
    const fdm::fluidProperties& fluid
) const
{
    for (const contactEntry& e : contacts_)
    {
        e.spring.addTo(system, 1/fluid.rho);
    }
}


void Foam::particleContacts::addSolvedLoads
(
    const List<vector>& U,
    const List<vector>& Omega,
    const fdm::fluidProperties&,
    fdm::particleLoads& loads,
    List<scalar>&
) const
{
    for (const contactEntry& e : contacts_)
    {
        const fdm::implicitContactSpring& s = e.spring;
        fdm::addContactLoads
        (
            s.force(U, Omega), s.normal(), s.armI(), s.armJ(), s.i(), s.j(),
            loads
        );
    }
}


Foam::fdm::contactNetwork Foam::particleContacts::network
(
    const List<vector>& U,
    const List<vector>& Omega
) const
{
    DynamicList<labelPair> pairs;
    DynamicList<vector> branches;
    DynamicList<vector> forces;
    for (const contactEntry& e : contacts_)
    {
        if (e.counted)
        {
            pairs.append(e.k);
            branches.append(e.branch);
            forces.append(e.force + e.spring.force(U, Omega).force);
        }
    }
    const List<labelPair> allPairs(onMaster(pairs));
    const List<vector> allBranches(onMaster(branches));
    const List<vector> allForces(onMaster(forces));
    fdm::contactNetwork links;
    forAll(allPairs, c)
    {
        links.append
        (
            fdm::contactLink::split
            (
                allPairs[c].first(), allPairs[c].second(), allBranches[c],
                allForces[c]
            )
        );
    }
    return links;
}


// ************************************************************************* //
