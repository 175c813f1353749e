/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "frameInvariantSubGrid.H"
#include "checkKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include "pairSearch.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "IFstream.H"

namespace Foam
{
    defineTypeNameAndDebug(frameInvariantSubGrid, 0);
    addToRunTimeSelectionTable
    (
        subGridModel,
        frameInvariantSubGrid,
        dictionary
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::autoPtr<Foam::fdm::resistanceTable>
Foam::frameInvariantSubGrid::readTable
(
    const dictionary& dict,
    const fileName& file,
    const settings& s,
    const scalar aReference
) const
{
    const fileName path(fileName(file).expand());
    IFstream is(path);
    if (!is.good())
    {
        FatalIOErrorInFunction(dict)
            << "Cannot read the sub-grid table " << path << " named in "
            << dict.name() << nl
            << "    make it with applications/utilities/subGridCalibration"
            << exit(FatalIOError);
    }
    const dictionary table(is);

    // The solver-resolved part depends on Delta/a, b and c (appendix C:
    // measured at Delta = a/5, b = 5, c = 0.3)
    const scalar deltaTable = table.get<scalar>("delta");
    const scalar bTable = table.get<scalar>("b");
    const scalar cTable = table.get<scalar>("c");
    const scalar deltaCase = s.delta/aReference;
    if
    (
        mag(deltaTable - deltaCase) > 1e-6*deltaCase
     || mag(bTable - s.b) > 1e-9*s.b
     || mag(cTable - s.c) > 1e-9*max(s.c, 1)
    )
    {
        FatalIOErrorInFunction(dict)
            << "The sub-grid table " << path << " was measured with"
            << " Delta/a = " << deltaTable << ", b = " << bTable
            << ", c = " << cTable << nl
            << "    but this case has Delta/a = " << deltaCase
            << " (a = " << aReference << "), b = " << s.b << ", c = "
            << s.c << "." << nl
            << "    Measure a table for these settings with "
            << "applications/utilities/subGridCalibration, or use the "
            << "settings of the table." << exit(FatalIOError);
    }
    return autoPtr<fdm::resistanceTable>::New(table, s.gapFloor);
}


const Foam::fdm::resistanceTable&
Foam::frameInvariantSubGrid::pairTable(const scalar lambda) const
{
    forAll(pairTables_, i)
    {
        if (mag(pairTables_[i].lambda() - lambda) < 1e-6*lambda)
        {
            return pairTables_[i];
        }
    }
    FatalErrorInFunction
        << "No sub-grid pair table for the radius ratio " << lambda
        << " in subGrid.pairTables of particleProperties" << nl
        << "    available ratios:";
    forAll(pairTables_, i)
    {
        FatalError<< ' ' << pairTables_[i].lambda();
    }
    FatalError<< nl << "    measure one with applications/utilities/"
        << "subGridCalibration run --kind pair --ratio " << lambda
        << exit(FatalError);
    return pairTables_[0];
}


void Foam::frameInvariantSubGrid::readPairTables
(
    const dictionary& dict,
    const settings& s,
    const scalar aSmall
)
{
    const fileNameList pairFiles
    (
        dict.getOrDefault<fileNameList>
        (
            "pairTables",
            {"$FDM_PROJECT_DIR/data/resistance/subGridPair_lambda1"}
        )
    );
    pairTables_.setSize(pairFiles.size());
    forAll(pairFiles, i)
    {
        pairTables_.set(i, readTable(dict, pairFiles[i], s, aSmall));
        if (!pairTables_[i].isPair())
        {
            FatalIOErrorInFunction(dict)
                << pairFiles[i] << " in pairTables is not a pair table"
                << exit(FatalIOError);
        }
        for (const word& f : fdm::resistanceTable::pairFunctionNames)
        {
            pairCutoff_ = max(pairCutoff_, pairTables_[i].cutoff(f));
        }
    }
}


void Foam::frameInvariantSubGrid::readWallTable
(
    const dictionary& dict,
    const fvMesh& mesh,
    const settings& s,
    const scalar aSmall
)
{
    if (dict.getOrDefault<bool>("walls", true))
    {
        walls_.reset
        (
            new planeWalls(mesh, "sub-grid wall lubrication (frameInvariant)")
        );
    }
    if (walls_ && !walls_->empty())
    {
        wallTable_ = readTable
        (
            dict,
            dict.getOrDefault<fileName>
            (
                "wallTable",
                "$FDM_PROJECT_DIR/data/resistance/subGridWall"
            ),
            s,
            aSmall
        );
        if (wallTable_->isPair())
        {
            FatalIOErrorInFunction(dict)
                << "wallTable is not a wall table" << exit(FatalIOError);
        }
        for (const word& f : fdm::resistanceTable::wallFunctionNames)
        {
            wallCutoff_ = max(wallCutoff_, wallTable_->cutoff(f));
        }
    }
}


void Foam::frameInvariantSubGrid::checkRatiosCovered
(
    const scalarField& radii
) const
{
    // Every radius ratio present needs its table: fail now, not mid-run
    scalarList distinct;
    for (const scalar a : radii)
    {
        bool known = false;
        for (const scalar b : distinct)
        {
            known = known || mag(a - b) < 1e-9*a;
        }
        if (!known)
        {
            distinct.append(a);
        }
    }
    for (const scalar a : distinct)
    {
        for (const scalar b : distinct)
        {
            if (a <= b)
            {
                pairTable(b/a);
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frameInvariantSubGrid::frameInvariantSubGrid
(
    const dictionary& dict,
    const fvMesh& mesh,
    const settings& s,
    const scalarField& radii
)
:
    subGridModel(mesh),
    pairCutoff_(0),
    wallCutoff_(0),
    aLarge_(radii.empty() ? 0 : max(radii)),
    nPairs_(0),
    nWallGaps_(0)
{
    fdm::checkKeywords
    (
        dict, {"model", "pairTables", "walls", "wallTable"},
        "subGrid block, model frameInvariant"
    );

    // Tables are for a1 = 1 scaled by the particle radius; the smallest
    // radius sets Delta/a1 (thesis: a1 = 1, Delta = a1/5)
    const scalar aSmall = radii.empty() ? 1 : min(radii);

    readPairTables(dict, s, aSmall);
    readWallTable(dict, mesh, s, aSmall);
    checkRatiosCovered(radii);

    Info<< "Sub-grid lubrication: frameInvariant, " << pairTables_.size()
        << " pair table(s), " << (walls_ ? walls_->size() : 0)
        << " plane wall(s), gap floor " << s.gapFloor << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::frameInvariantSubGrid::pairReach() const
{
    return pairCutoff_*aLarge_;
}


void Foam::frameInvariantSubGrid::update(const fdm::pairStepInput& in)
{
    const pointField& positions = in.positions;
    const scalarField& radii = in.radii;
    const fdm::periodicBox& box = in.box;
    pairs_.clear();
    wallGaps_.clear();
    nPairs_ = 0;

    // Pairs: xi = 2r/(a_p + a_q) - 2 below the largest cut-off, i.e. a
    // surface gap below pairCutoff (a_p + a_q)/2 <= pairCutoff a_max
    DynamicList<labelPair> close;
    fdm::selectNearPairs(box, positions, radii, pairReach(), in.near, close);
    for (const labelPair& pq : close)
    {
        // "1" is the smaller particle, lambda = a_2/a_1 >= 1
        const bool swap = radii[pq.second()] < radii[pq.first()];
        const label p = swap ? pq.second() : pq.first();
        const label q = swap ? pq.first() : pq.second();
        const vector d = positions[q] - positions[p];
        const vector rv = box.minimumImage(d);
        const scalar r = mag(rv);
        const scalar xi = 2*r/(radii[p] + radii[q]) - 2;
        if (xi > pairCutoff_)
        {
            continue;
        }
        const fdm::resistanceTable& table = pairTable(radii[q]/radii[p]);
        pairs_.push_back
        (
            pairEntry{p, q, box.imageVelocity(d), fdm::pairSubGridMatrix
            (
                table.pairFunctions(xi, radii[p]), r, rv/r
            )}
        );
        nPairs_ += in.holds(pq.first());
    }

    if (walls_ && !walls_->empty())
    {
        updateWallGaps(in);
    }
    nPairs_ = in.total(nPairs_);
    nWallGaps_ = in.total(label(wallGaps_.size()));
}


void Foam::frameInvariantSubGrid::report() const
{
    Info<< "Sub-grid lubrication: " << nPairs() << " pairs, " << nWallGaps()
        << " particle-wall gaps" << endl;
}


void Foam::frameInvariantSubGrid::updateWallGaps
(
    const fdm::pairStepInput& in
)
{
    const scalarField& radii = in.radii;
    for (const planeWalls::wall& w : walls_->walls())
    {
        const vector Uw = walls_->velocity(w);
        forAll(in.positions, p)
        {
            const scalar h = w.distance(in.positions[p]);
            const scalar epsilon = h/radii[p] - 1;
            if (epsilon > wallCutoff_ || !in.holds(p))
            {
                continue;
            }
            wallGaps_.push_back
            (
                wallEntry{p, Uw, fdm::wallSubGridMatrix
                (
                    wallTable_->wallFunctions(epsilon, radii[p]),
                    radii[p],
                    epsilon,
                    w.normal
                )}
            );
        }
    }
}


void Foam::frameInvariantSubGrid::addTo
(
    fdm::particleSystemSink& system,
    const fdm::fluidProperties& fluid
) const
{
    const scalar nu = fluid.nu;
    for (const pairEntry& e : pairs_)
    {
        e.matrix.addTo(system, e.p, e.q, nu, e.qImageVelocity);
    }
    for (const wallEntry& e : wallGaps_)
    {
        e.matrix.addTo(system, e.p, e.wallVelocity, nu);
    }
}


void Foam::frameInvariantSubGrid::addSolvedLoads
(
    const List<vector>& U,
    const List<vector>& Omega,
    const fdm::fluidProperties& fluid,
    fdm::particleLoads& loads,
    List<scalar>& dipoleTrace
) const
{
    const scalar eta = fluid.rho*fluid.nu;
    // F^h = F^FDM + F^SG etc. (eqs 2.9, 2.68)
    for (const pairEntry& e : pairs_)
    {
        const vector& U1 = U[e.p];
        const vector& W1 = Omega[e.p];
        const vector U2 = U[e.q] + e.qImageVelocity;
        const vector& W2 = Omega[e.q];
        vector F1, T1, F2, T2;
        e.matrix.forceTorque(U1, W1, U2, W2, F1, T1, F2, T2);
        loads.force[e.p] += eta*F1;
        loads.torque[e.p] += eta*T1;
        loads.force[e.q] += eta*F2;
        loads.torque[e.q] += eta*T2;
        loads.stresslet[e.p] += eta*e.matrix.stresslet(0, U1, W1, U2, W2);
        loads.stresslet[e.q] += eta*e.matrix.stresslet(1, U1, W1, U2, W2);
        dipoleTrace[e.p] += eta*e.matrix.dipoleTrace(0, U1, U2);
        dipoleTrace[e.q] += eta*e.matrix.dipoleTrace(1, U1, U2);
    }
    for (const wallEntry& e : wallGaps_)
    {
        vector F, T;
        e.matrix.forceTorque(U[e.p], Omega[e.p], e.wallVelocity, F, T);
        loads.force[e.p] += eta*F;
        loads.torque[e.p] += eta*T;
        loads.stresslet[e.p] +=
            eta*e.matrix.stresslet(U[e.p], Omega[e.p], e.wallVelocity);
        dipoleTrace[e.p] +=
            eta*e.matrix.dipoleTrace(U[e.p], e.wallVelocity);
    }
}


// ************************************************************************* //
