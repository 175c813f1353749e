/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "andersonAcceleration.H"

#include <Eigen/Dense>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Growth of |f| over one iteration that drops the history (restarts)
const Foam::scalar restartGrowth = 2;

//- This processor's parts of the new Gram row dF_last . dF_i (gramRow),
//  of dF_i . f and (withNorm) of f . f, in one pass over the history in
//  blocks that stay in cache: each stored difference is read from memory
//  once instead of twice (the update is bound by memory traffic)
void localDots
(
    const Foam::UList<Foam::List<float>>& dF,
    const Foam::scalarField& f,
    const bool gramRow,
    const bool withNorm,
    Foam::List<Foam::scalar>& dots
)
{
    const Foam::label m = dF.size();
    const Foam::label n = f.size();
    const Foam::label block = 1024;
    const Foam::scalar* __restrict__ pf = f.cdata();
    const float* __restrict__ pl = dF[m - 1].cdata();
    for (Foam::label k0 = 0; k0 < n; k0 += block)
    {
        const Foam::label k1 = Foam::min(k0 + block, n);
        for (Foam::label i = 0; i < m; ++i)
        {
            const float* __restrict__ pd = dF[i].cdata();
            Foam::scalar row = 0, rhs = 0;
            for (Foam::label k = k0; k < k1; ++k)
            {
                row += Foam::scalar(pl[k])*pd[k];
                rhs += pd[k]*pf[k];
            }
            if (gramRow)
            {
                dots[i] += row;
            }
            dots[m + i] += rhs;
        }
        if (withNorm)
        {
            Foam::scalar norm = 0;
            for (Foam::label k = k0; k < k1; ++k)
            {
                norm += pf[k]*pf[k];
            }
            dots[2*m] += norm;
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::andersonAcceleration::andersonAcceleration
(
    const label depth,
    const reduction& reduce,
    const bool restartOnGrowth
)
:
    depth_(depth),
    reduce_(reduce),
    restartOnGrowth_(restartOnGrowth),
    fNorm2Prev_(GREAT),
    gram_(depth*depth, Zero)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdm::andersonAcceleration::appendDifferences
(
    const scalarField& x,
    const scalarField& g
)
{
    const label n = g.size();
    List<float> dF, dG;
    if (dF_.size() == depth_)
    {
        // Drop the oldest difference, reusing its storage, and shift the
        // Gram matrix with it
        dF.transfer(dF_[0]);
        dG.transfer(dG_[0]);
        for (label i = 1; i < depth_; ++i)
        {
            dF_[i - 1].transfer(dF_[i]);
            dG_[i - 1].transfer(dG_[i]);
            for (label j = 1; j < depth_; ++j)
            {
                gram_[(i - 1)*depth_ + j - 1] = gram_[i*depth_ + j];
            }
        }
        dF_.setSize(depth_ - 1);
        dG_.setSize(depth_ - 1);
    }
    else
    {
        dF.setSize(n);
        dG.setSize(n);
    }

    // One pass: the differences and the new previous values
    for (label k = 0; k < n; ++k)
    {
        const scalar f = g[k] - x[k];
        dF[k] = static_cast<float>(f - fPrev_[k]);
        dG[k] = static_cast<float>(g[k] - gPrev_[k]);
        fPrev_[k] = f;
        gPrev_[k] = g[k];
    }

    const label m = dF_.size();
    dF_.setSize(m + 1);
    dG_.setSize(m + 1);
    dF_[m].transfer(dF);
    dG_[m].transfer(dG);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::andersonAcceleration::reset()
{
    gPrev_.clear();
    fPrev_.clear();
    dG_.clear();
    dF_.clear();
    fNorm2Prev_ = GREAT;
}


bool Foam::fdm::andersonAcceleration::restartIfGrown(const scalar fNorm2)
{
    const bool grown =
        restartOnGrowth_ && fNorm2 > sqr(restartGrowth)*fNorm2Prev_;
    fNorm2Prev_ = fNorm2;
    if (grown)
    {
        dF_.clear();
        dG_.clear();
    }
    return grown;
}


void Foam::fdm::andersonAcceleration::update
(
    const scalarField& x,
    scalarField& g
)
{
    const bool appended = (gPrev_.size() == g.size());
    if (appended)
    {
        appendDifferences(x, g);
    }
    else
    {
        gPrev_ = g;
        fPrev_ = g - x;
    }
    const scalarField& f = fPrev_;

    const label m = dF_.size();
    if (m == 0)
    {
        return;
    }

    // Partial sums of the new Gram row dF_{m-1} . dF_j, of the right-hand
    // side dF_i . f and (restarts only) of f . f, summed over processors
    // in one reduction
    List<scalar> dots(2*m + 1, Zero);
    localDots(dF_, f, appended, restartOnGrowth_, dots);
    reduce_(dots);
    if (restartIfGrown(dots[2*m]))
    {
        return;
    }
    if (appended)
    {
        for (label j = 0; j < m; ++j)
        {
            gram_[(m - 1)*depth_ + j] = dots[j];
        }
    }

    // Normal equations (dF^T dF) gamma = dF^T f
    Eigen::MatrixXd A(m, m);
    Eigen::VectorXd b(m);
    scalar trace = 0;
    for (label i = 0; i < m; ++i)
    {
        for (label j = 0; j <= i; ++j)
        {
            A(i, j) = A(j, i) = gram_[i*depth_ + j];
        }
        b(i) = dots[m + i];
        trace += A(i, i);
    }
    if (!(trace > 0))
    {
        return;
    }
    A += (1e-12*trace/m)*Eigen::MatrixXd::Identity(m, m);
    const Eigen::VectorXd gamma = A.ldlt().solve(b);

    // g -= dG gamma in one pass
    scalar* __restrict__ pg = g.data();
    for (label k = 0; k < g.size(); ++k)
    {
        scalar s = 0;
        for (label i = 0; i < m; ++i)
        {
            s += gamma(i)*dG_[i][k];
        }
        pg[k] -= s;
    }
}


// ************************************************************************* //
