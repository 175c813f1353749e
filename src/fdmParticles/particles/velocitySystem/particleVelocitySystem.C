/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "particleVelocitySystem.H"
#include "particleUnknowns.H"
#include "error.H"
#include "OFstream.H"
#include "Pstream.H"

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>

namespace
{

typedef Eigen::SparseMatrix<double> sparseMatrix;
typedef Eigen::Triplet<double> triplet;

typedef Eigen::ConjugateGradient
<
    sparseMatrix,
    Eigen::Lower|Eigen::Upper,
    Eigen::IncompleteCholesky<double>
> preconditionedCG;


//- The right-hand side with the prescribed unknowns eliminated: known
//  columns move to it, the rows of known unknowns hold their values
Eigen::VectorXd reducedRhs
(
    const Foam::UList<Foam::label>& rows,
    const Foam::UList<Foam::label>& cols,
    const Foam::UList<Foam::scalar>& values,
    const Foam::UList<Foam::scalar>& rhs,
    const Foam::UList<bool>& prescribed,
    const Foam::UList<Foam::scalar>& prescribedValue
)
{
    using namespace Foam;
    const label n = rhs.size();
    Eigen::VectorXd b(n);
    for (label k = 0; k < n; ++k)
    {
        b[k] = prescribed[k] ? prescribedValue[k] : rhs[k];
    }
    forAll(values, e)
    {
        if (!prescribed[rows[e]] && prescribed[cols[e]])
        {
            b[rows[e]] -= values[e]*prescribedValue[cols[e]];
        }
    }
    return b;
}


//- The matrix of the entries (rows, cols, values) with the prescribed
//  unknowns eliminated: their rows and columns become identity rows
//  (keeps the matrix SPD)
sparseMatrix reducedMatrix
(
    const Foam::UList<Foam::label>& rows,
    const Foam::UList<Foam::label>& cols,
    const Foam::UList<Foam::scalar>& values,
    const Foam::UList<bool>& prescribed
)
{
    using namespace Foam;
    const label n = prescribed.size();
    std::vector<triplet> entries;
    entries.reserve(values.size() + n);
    forAll(values, e)
    {
        if (!prescribed[rows[e]] && !prescribed[cols[e]])
        {
            entries.push_back(triplet(rows[e], cols[e], values[e]));
        }
    }
    for (label k = 0; k < n; ++k)
    {
        if (prescribed[k])
        {
            entries.push_back(triplet(k, k, 1));
        }
    }

    sparseMatrix A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    return A;
}


//- Factorise A for cg; FatalError (and A written out) when it is not
//  positive definite
void factorise(const sparseMatrix& A, preconditionedCG& cg)
{
    using namespace Foam;
    cg.compute(A);
    // The incomplete factorisation can break down on an SPD matrix whose
    // near-contact couplings almost cancel its diagonal (Eigen doubles its
    // diagonal shift ten times from 1e-3 of the scaled diagonal, then gives
    // up).  A larger shift changes the preconditioner only, not the
    // solution; a matrix that still fails at a shift of 100 times its
    // scaled diagonal is not positive definite.
    for
    (
        scalar shift = 0.1;
        cg.info() != Eigen::Success && shift < 1e3;
        shift *= 10
    )
    {
        cg.preconditioner().setInitialShift(shift);
        cg.compute(A);
    }
    if (cg.info() != Eigen::Success)
    {
        // Keep the matrix for inspection (row col value, 0-based)
        const fileName dump("particleSystem.failed");
        if (Pstream::master())
        {
            OFstream os(dump);
            os.precision(17);
            for (int k = 0; k < A.outerSize(); ++k)
            {
                for (sparseMatrix::InnerIterator it(A, k); it; ++it)
                {
                    os << it.row() << ' ' << it.col() << ' ' << it.value()
                        << nl;
                }
            }
        }
        FatalErrorInFunction
            << "Incomplete-Cholesky factorisation of the particle system"
            << " (thesis eq 2.43) failed: the matrix is not positive definite."
            << " Written to " << dump << " (row col value): its"
            << " eigenvector of negative eigenvalue names the particles; a"
            << " negative implicit contact stiffness or a sub-grid table"
            << " correcting beyond the exact resistance is the likely source."
            << abort(FatalError);
    }
}

} // namespace


struct Foam::fdm::particleVelocitySystem::factorisation
{
    //- What the matrix was made from
    particleSystemEntries from;

    sparseMatrix A;
    preconditionedCG cg;
};


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::particleVelocitySystem::particleVelocitySystem
(
    const label nParticles
)
:
    nParticles_(nParticles),
    entries_(nParticles)
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::fdm::particleVelocitySystem::~particleVelocitySystem()
{}


// * * * * * * * * * * * * * * * Member Operators  * * * * * * * * * * * * * //

Foam::fdm::particleVelocitySystem&
Foam::fdm::particleVelocitySystem::operator=(particleVelocitySystem&&) =
    default;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fdm::particleVelocitySystem::factorisation&
Foam::fdm::particleVelocitySystem::factorised() const
{
    if (!factorised_ || !factorised_->from.sameMatrix(entries_))
    {
        factorised_.reset(new factorisation());
        factorisation& f = *factorised_;
        f.from = entries_;
        const particleSystemEntries& e = entries_;
        f.A = reducedMatrix(e.rows, e.cols, e.values, e.prescribed);
        factorise(f.A, f.cg);
    }
    return *factorised_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::particleVelocitySystem::clear()
{
    entries_.clear();
}


void Foam::fdm::particleVelocitySystem::addEntry
(
    const label row,
    const label col,
    const scalar value
)
{
    entries_.add(row, col, value);
}


void Foam::fdm::particleVelocitySystem::addRhs
(
    const label i,
    const vector& force,
    const vector& torque
)
{
    entries_.addRhs(i, force, torque);
}


void Foam::fdm::particleVelocitySystem::prescribe
(
    const label i,
    const direction dof,
    const scalar value
)
{
    entries_.prescribe(i, dof, value);
}


Foam::fdm::particleVelocitySystem::solveInfo
Foam::fdm::particleVelocitySystem::solve
(
    const scalar tolerance,
    const label maxIterations,
    List<vector>& U,
    List<vector>& Omega,
    const scalar residualScale
) const
{
    const Eigen::VectorXd b
    (
        reducedRhs
        (
            entries_.rows, entries_.cols, entries_.values, entries_.rhs,
            entries_.prescribed, entries_.prescribedValue
        )
    );
    factorisation& f = factorised();
    const sparseMatrix& A = f.A;
    preconditionedCG& cg = f.cg;

    Eigen::VectorXd x;
    packUnknowns(U, Omega, nParticles_, x);

    // Eigen's tolerance is relative to the norm of b
    const scalar bNorm = b.norm();
    const scalar relativeTolerance =
        relativeSolveTolerance(tolerance, residualScale, bNorm);
    cg.setTolerance(relativeTolerance);
    cg.setMaxIterations(maxIterations);

    // Eigen counts the iterations completed before its convergence test,
    // so a solve converging in its first iteration reports 0; count the
    // iterations actually done (0 only if the guess already satisfies the
    // tolerance)
    const bool guessConverged =
        (b - A*x).squaredNorm() <= sqr(relativeTolerance*bNorm);

    x = cg.solveWithGuess(b, x);
    unpackUnknowns(x, U, Omega);

    solveInfo info;
    info.iterations =
        guessConverged ? 0 : min(label(cg.iterations()) + 1, maxIterations);
    // Relative to the scale of the tolerance, so that it compares with it
    info.relativeResidual = cg.error()*tolerance/relativeTolerance;
    info.converged = (cg.info() == Eigen::Success);
    return info;
}


void Foam::fdm::particleVelocitySystem::multiply
(
    const List<vector>& U,
    const List<vector>& Omega,
    List<vector>& force,
    List<vector>& torque
) const
{
    force.setSize(nParticles_);
    torque.setSize(nParticles_);
    force = Zero;
    torque = Zero;

    forAll(entries_.values, e)
    {
        const label r = entries_.rows[e];
        const label c = entries_.cols[e];
        const label pc = c/nDof;
        const direction dc = c % nDof;
        const scalar x = dc < 3 ? U[pc][dc] : Omega[pc][dc - 3];

        const label pr = r/nDof;
        const direction dr = r % nDof;
        if (dr < 3)
        {
            force[pr][dr] += entries_.values[e]*x;
        }
        else
        {
            torque[pr][dr - 3] += entries_.values[e]*x;
        }
    }
}


// ************************************************************************* //
