/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "fdmParticleCloud.H"
#include "cloudGravity.H"
#include "pairSearch.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "constants.H"
#include "checkKeywords.H"
#include "leesEdwardsShear.H"
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- A number with 6 significant digits for messages (the case's
//  writePrecision would otherwise print round-off digits)
Foam::word brief(const double x)
{
    std::ostringstream os;
    os.precision(6);
    os << x;
    return Foam::word(os.str(), false);
}

} // namespace

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fdmParticleCloud::meshSpacing() const
{
    // The method (alpha_lambda = Delta^2/nu, the indicator widths, the
    // calibrated sub-grid tables) assumes a uniform cubic mesh.
    const scalarField& V = mesh_.V();
    const scalar Vmin = gMin(V);
    const scalar Vmax = gMax(V);

    scalar worstAspect = 1;
    forAll(mesh_.cells(), celli)
    {
        const boundBox bb(mesh_.cells()[celli].points(mesh_.faces(),
            mesh_.points()), false);
        worstAspect = max(worstAspect, cmptMax(bb.span())/cmptMin(bb.span()));
    }
    reduce(worstAspect, maxOp<scalar>());

    if (Vmax - Vmin > 1e-6*Vmax || worstAspect - 1 > 1e-6)
    {
        FatalErrorInFunction
            << "The particle coupling needs a uniform mesh of cubic cells"
            << " (thesis 1, section 2.2.1): cell volumes range from "
            << Vmin << " to " << Vmax << ", largest edge ratio "
            << worstAspect << "." << nl
            << "    Make the blockMeshDict cell counts proportional to the"
            << " box edges, without grading." << exit(FatalError);
    }

    return Foam::cbrt(Vmax);
}


Foam::fdm::periodicBox Foam::fdmParticleCloud::meshBox() const
{
    const boundBox bounds(mesh_.points(), true);
    FixedList<bool, 3> periodic(false);

    // Face areas of each cyclic patch, including the parts that became
    // processorCyclic patches after decomposition (a rank may hold a
    // cyclic patch with no faces at all)
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    List<vector> area(patches.size(), Zero);
    for (const polyPatch& pp : patches)
    {
        label cyclicID = -1;
        if (isA<cyclicPolyPatch>(pp))
        {
            cyclicID = pp.index();
        }
        else if (isA<processorCyclicPolyPatch>(pp))
        {
            cyclicID =
                refCast<const processorCyclicPolyPatch>(pp).referPatchID();
        }
        if (cyclicID >= 0)
        {
            for (const vector& Sf : pp.faceAreas())
            {
                area[cyclicID] += cmptMag(Sf);
            }
        }
    }

    for (const polyPatch& pp : patches)
    {
        if (!isA<cyclicPolyPatch>(pp))
        {
            continue;
        }
        vector a = area[pp.index()];
        reduce(a, sumOp<vector>());

        const direction axis = findMax(a);
        if (cmptMax(a) > 0)
        {
            for (direction d = 0; d < 3; ++d)
            {
                if (d != axis && a[d] > 1e-9*a[axis])
                {
                    FatalErrorInFunction
                        << "Cyclic patch " << pp.name() << " is not normal to"
                        << " a coordinate axis; the particle coupling needs"
                        << " an axis-aligned box." << exit(FatalError);
                }
            }
            periodic[axis] = true;
        }
    }

    return fdm::periodicBox(bounds.min(), bounds.max(), periodic);
}


void Foam::fdmParticleCloud::checkParticles() const
{
    // What the mesh and the indicator need besides checkParticleList
    const fileName file = dict_.objectPath();
    const scalar minCellsPerRadius = 2;
    forAll(state_.position, p)
    {
        const scalar a = state_.radius[p];
        if (a < minCellsPerRadius*delta_)
        {
            FatalIOErrorInFunction(dict_)
                << "Particle " << p << " in " << file << " has radius " << a
                << " = " << brief(a/delta_) << " cells: the mesh (Delta = "
                << brief(delta_) << ") is too coarse to resolve it." << nl
                << "    At least " << minCellsPerRadius << " cells per radius"
                << " are required; the method is calibrated at 5 (thesis 1,"
                << " Delta = a1/5)." << exit(FatalIOError);
        }
        for (direction d = 0; d < 3; ++d)
        {
            if
            (
                box_.periodic(d)
             && box_.span()[d] < 2*indicator_.supportRadius(a)
            )
            {
                FatalIOErrorInFunction(dict_)
                    << "Particle " << p << " in " << file << ": its"
                    << " support diameter " << 2*indicator_.supportRadius(a)
                    << " exceeds the periodic length " << box_.span()[d]
                    << " in direction " << d << "." << exit(FatalIOError);
            }
        }
    }
}


Foam::vector Foam::fdmParticleCloud::bodyForce(const label p) const
{
    const particleGroup& g = groups_[state_.group[p]];
    const scalar V =
        4.0/3.0*constant::mathematical::pi*pow3(state_.radius[p]);

    // Buoyant weight (thesis eq 2.11d; gravity on the fluid is in p) and
    // the external force, per unit fluid density like lambda
    return (g.density()/rhoFluid_ - 1)*V*gravity_ + g.force()/rhoFluid_;
}


Foam::scalar Foam::fdmParticleCloud::readGapFloor() const
{
    // One floor on the reduced gaps xi and epsilon for the sub-grid
    // lubrication and the contact barrier (eq 2.57; the thesis floors both
    // at 1e-5)
    const scalar gapFloor = dict_.getOrDefault<scalar>("gapFloor", 1e-5);
    if (!(gapFloor > 0 && gapFloor < 0.1))
    {
        FatalIOErrorInFunction(dict_)
            << "gapFloor " << gapFloor << " in " << dict_.name()
            << ": allowed values are 0 < gapFloor < 0.1 (floor on the "
            << "reduced surface gaps; thesis 1e-5)" << exit(FatalIOError);
    }
    return gapFloor;
}


void Foam::fdmParticleCloud::reportSetup() const
{
    Info<< "    " << size() << " particles in " << groups_.size()
        << " group(s); Delta = " << delta_ << ", radius/Delta from "
        << gMin(state_.radius)/delta_ << " to "
        << gMax(state_.radius)/delta_ << nl
        << "    indicator b = " << indicator_.b() << ", c = "
        << indicator_.c() << "; alpha_lambda = " << alphaLambda_ << nl
        << "    periodic (x y z): (" << box_.periodic(0) << ' '
        << box_.periodic(1) << ' ' << box_.periodic(2) << "), box "
        << box_.min() << " + " << box_.span() << nl
        << "    particle system solved "
        << (
               distributedSolve_
             ? "by subdomain (parallelParticleSolve distributed)"
             : "whole on every rank"
           ) << nl << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdmParticleCloud::fdmParticleCloud
(
    const fvMesh& mesh,
    const dictionary& transport
)
:
    mesh_(mesh),
    readingTrapsOff_(),
    dict_
    (
        IOobject
        (
            "particleProperties",
            mesh.time().constant(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        )
    ),
    rhoFluid_(1),
    nu_(transport.get<scalar>("nu")),
    gravity_(Zero),
    delta_(0),
    indicator_(5, 0.3, 1),
    alphaLambda_(0),
    lambdaTolerances_{0, 0, 0},
    solveTolerance_(1e-6),
    maxCourant_(1),
    consistentOverlaps_(false),
    positionScheme_(fdm::positionScheme::adamsBashforth2),
    box_(point::zero, point::one, FixedList<bool, 3>(false)),
    domainVolume_(gSum(mesh.V())),
    solved_(false),
    historyDeltaT_(0),
    alternation_(),
    firstSolveDone_(false),
    verbose_(true),
    gatheredTimeIndex_(-1),
    system_(0),
    distributedSolve_(false),
    contacts_(new noContacts(0)),
    lambdaPartsSum_(Zero),
    timings_{0, 0, 0, 0, 0},
    lastSolve_{0, 0, true},
    lambdaResidual_(0)
{
    readingTrapsOff_.restore();
    if (!dict_.headerOk())
    {
        fdm::requireHeader(dict_.objectPath());
        Info<< "No constant/particleProperties: particle-free Stokes flow"
            << nl << endl;
        return;
    }

    Info<< "Reading particleProperties" << nl;
    fdm::checkKeywords
    (
        dict_,
        {
            "coupling", "gravity", "groups", "particles", "particlesFile",
            "indicator", "subGrid", "contact", "gapFloor", "output",
            "acceptChangedRadii"
        },
        "top level of the particle input"
    );

    rhoFluid_ = transport.get<scalar>("rho");
    if (!(rhoFluid_ > 0))
    {
        FatalIOErrorInFunction(transport)
            << "rho " << rhoFluid_ << " in " << transport.name()
            << ": allowed values are > 0 (fluid density, needed with"
            << " particles)" << exit(FatalIOError);
    }

    delta_ = meshSpacing();
    box_ = meshBox();
    fdm::setLeesEdwardsShear(mesh_, box_);
    cellBins_.reset(new fdm::pointBins(mesh.C().primitiveField(), delta_*4));

    readCoupling();
    readGroups();
    readParticles();
    checkParticles();
    gravity_ = fdm::readCloudGravity
    (
        dict_, mesh_, groups_, state_, rhoFluid_, rhoFluid_*nu_
    );

    system_ = fdm::particleVelocitySystem(distributedSolve_ ? 0 : size());
    state_.resizeVelocities();
    hydro_ = fdm::particleLoads(size());
    dipoleTrace_.setSize(size(), Zero);
    moments_.setSize(size());
    contact_ = fdm::particleLoads(size());

    const scalar gapFloor = readGapFloor();
    contacts_ = contactModel::New
    (
        dict_, mesh_, state_.radius, rhoFluid_*nu_, gapFloor
    );

    readState();

    subGrid_ = subGridModel::New
    (
        dict_,
        mesh_,
        {delta_, indicator_.b(), indicator_.c(), gapFloor},
        state_.radius
    );
    pairInteractions_.setSize(2);
    pairInteractions_.set(0, &subGrid_());
    pairInteractions_.set(1, &contacts_());
    setHalo();

    output_.reset
    (
        new particleCloudOutput(mesh_, dict_.subOrEmptyDict("output"), dict_)
    );
    reportSetup();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fdmParticleCloud::lambdaTolerance() const
{
    return lambdaTolerances_.of(firstSolveDone_, output_->recordDue());
}


bool Foam::fdmParticleCloud::looseSolve() const
{
    return
        !empty()
     && lambdaTolerances_.loose(firstSolveDone_, output_->recordDue());
}


bool Foam::fdmParticleCloud::requiresBalancingGradient(vector& gradient) const
{
    gradient = Zero;
    if (empty() || !(box_.periodic(0) && box_.periodic(1) && box_.periodic(2)))
    {
        return false;
    }

    forAll(state_.position, p)
    {
        if (groups_[state_.group[p]].translationPrescribed())
        {
            // A held particle absorbs any net force
            return false;
        }
        gradient += bodyForce(p);
    }

    // Integral of the momentum equation over the periodic box:
    // V0 grad(P0) = integral of lambda = sum of the particles' forces
    gradient /= domainVolume_;
    return true;
}


// ************************************************************************* //
