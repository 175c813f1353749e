/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The matrix, its block-Jacobi preconditioner and the conjugate-gradient
    solve of distributedParticleSystem (Eigen kept in this file).

\*---------------------------------------------------------------------------*/

#include "distributedParticleSystemOperators.H"
#include "particleUnknowns.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "error.H"

namespace
{

typedef Eigen::SparseMatrix<double> columnMatrix;
typedef Eigen::Triplet<double> triplet;

//- Sum over ranks of the dot product of the first n entries
double globalDot
(
    const Eigen::VectorXd& a,
    const Eigen::VectorXd& b,
    const long n
)
{
    double s = a.head(n).dot(b.head(n));
    Foam::reduce(s, Foam::sumOp<double>());
    return s;
}


//- Preconditioned conjugate gradients over the ranks' owned rows of A
//  from x (owned then ghost unknowns, the ghosts current) until the
//  residual is at most bound; exchange(p) brings the ghost values of a
//  search direction.  Returns the iterations and in rr the squared
//  residual norm.  The owned rows of rhs and A are zero where an unknown
//  is prescribed, so residual and search directions stay zero there.
template<class Exchange>
Foam::label conjugateGradients
(
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& A,
    const Eigen::IncompleteCholesky<double>& M,
    const Eigen::VectorXd& rhs,
    Eigen::VectorXd& x,
    const double bound,
    const Foam::label maxIterations,
    const Exchange& exchange,
    double& rr
)
{
    const long n = A.rows();
    Eigen::VectorXd r = rhs - A*x;
    rr = globalDot(r, r, n);
    Eigen::VectorXd p = Eigen::VectorXd::Zero(x.size());
    double rz = 0;
    Foam::label iterations = 0;
    for (; rr > bound*bound && iterations < maxIterations; ++iterations)
    {
        // A rank that owns no particle still takes part in the reductions
        const Eigen::VectorXd z = n ? M.solve(r) : r;
        const double rzNew = globalDot(r, z, n);
        p.head(n) = z + (iterations ? rzNew/rz : 0)*p.head(n);
        rz = rzNew;
        exchange(p.data());
        const Eigen::VectorXd q = A*p;
        const double pq = globalDot(p, q, n);
        if (!(pq > 0))
        {
            FatalErrorInFunction
                << "The particle system (thesis eq 2.43) is not positive"
                << " definite: p.Ap = " << pq << " at iteration "
                << iterations << Foam::abort(Foam::FatalError);
        }
        x.head(n) += rz/pq*p.head(n);
        r -= rz/pq*q;
        rr = globalDot(r, r, n);
    }
    return iterations;
}

} // namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::fdm::distributedParticleSystem::operators&
Foam::fdm::distributedParticleSystem::built() const
{
    if (operators_ && operators_->from.sameMatrix(entries_))
    {
        return *operators_;
    }
    operators_.reset(new operators());
    operators& o = *operators_;
    o.from = entries_;
    const particleSystemEntries& e = entries_;

    const label n = nDof*nOwned_;
    std::vector<triplet> all, owned;
    all.reserve(e.values.size());
    owned.reserve(e.values.size() + n);
    forAll(e.values, k)
    {
        const label r = e.rows[k], c = e.cols[k];
        if (e.prescribed[r])
        {
            continue;
        }
        all.push_back(triplet(r, c, e.values[k]));
        if (c < n && !e.prescribed[c])
        {
            owned.push_back(triplet(r, c, e.values[k]));
        }
    }
    for (label k = 0; k < n; ++k)
    {
        if (e.prescribed[k])
        {
            owned.push_back(triplet(k, k, 1));
        }
    }
    o.A.resize(n, nDof*(nOwned_ + nGhosts_));
    o.A.setFromTriplets(all.begin(), all.end());

    if (n == 0)
    {
        return o;   // this rank owns no particle: nothing to factorise
    }
    columnMatrix block(n, n);
    block.setFromTriplets(owned.begin(), owned.end());
    // As particleVelocitySystem: a larger diagonal shift when the
    // incomplete factorisation breaks down on a near-singular block
    o.preconditioner.compute(block);
    for
    (
        scalar shift = 0.1;
        o.preconditioner.info() != Eigen::Success && shift < 1e3;
        shift *= 10
    )
    {
        o.preconditioner.setInitialShift(shift);
        o.preconditioner.compute(block);
    }
    if (o.preconditioner.info() != Eigen::Success)
    {
        FatalErrorInFunction
            << "Incomplete-Cholesky factorisation of rank "
            << Pstream::myProcNo() << "'s block of the particle system"
            << " (thesis eq 2.43) failed: the block is not positive definite"
            << abort(FatalError);
    }
    return o;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fdm::distributedParticleSystem::solveInfo
Foam::fdm::distributedParticleSystem::solve
(
    const scalar tolerance,
    const label maxIterations,
    List<vector>& U,
    List<vector>& Omega,
    const scalar residualScale
) const
{
    const operators& o = built();
    const long n = nDof*nOwned_;
    const label nLocal = nOwned_ + nGhosts_;

    // The right-hand side (zero on prescribed rows) and, for the norm that
    // sets the tolerance as in particleVelocitySystem, the same with the
    // prescribed unknowns eliminated
    Eigen::VectorXd rhs(n);
    Eigen::VectorXd xp = Eigen::VectorXd::Zero(nDof*nLocal);
    for (long k = 0; k < n; ++k)
    {
        rhs[k] = entries_.prescribed[k] ? 0 : entries_.rhs[k];
        xp[k] = entries_.prescribed[k] ? entries_.prescribedValue[k] : 0;
    }
    exchange(xp.data());
    const Eigen::VectorXd b = rhs - o.A*xp;
    const scalar bNorm =
        std::sqrt(globalDot(b, b, n) + globalDot(xp, xp, n));
    const scalar relativeTolerance =
        relativeSolveTolerance(tolerance, residualScale, bNorm);
    const scalar bound = relativeTolerance*bNorm;

    Eigen::VectorXd x;
    packUnknowns(U, Omega, nLocal, x);
    for (long k = 0; k < n; ++k)
    {
        x[k] = entries_.prescribed[k] ? entries_.prescribedValue[k] : x[k];
    }
    exchange(x.data());

    solveInfo info{0, 0, true};
    scalar rr = 0;
    info.iterations = conjugateGradients
    (
        o.A, o.preconditioner, rhs, x, bound, maxIterations,
        [this](scalar* v) { exchange(v); }, rr
    );
    exchange(x.data());
    unpackUnknowns(x, U, Omega);
    info.converged = rr <= sqr(bound);
    // Relative to the scale of the tolerance, as particleVelocitySystem
    info.relativeResidual =
        bNorm > 0 ? std::sqrt(rr)/bNorm*tolerance/relativeTolerance : 0;
    return info;
}


// ************************************************************************* //
