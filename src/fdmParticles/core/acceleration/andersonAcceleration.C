/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "andersonAcceleration.H"

#include <Eigen/Dense>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::andersonAcceleration::andersonAcceleration
(
    const label depth,
    const reduction& reduce
)
:
    depth_(depth),
    reduce_(reduce)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::andersonAcceleration::reset()
{
    gPrev_.clear();
    fPrev_.clear();
    dG_.clear();
    dF_.clear();
}


void Foam::fdm::andersonAcceleration::update
(
    const scalarField& x,
    scalarField& g
)
{
    const scalarField f(g - x);

    if (gPrev_.size() == g.size())
    {
        if (dF_.size() == depth_)
        {
            // Drop the oldest difference
            for (label i = 1; i < depth_; ++i)
            {
                dF_[i - 1].transfer(dF_[i]);
                dG_[i - 1].transfer(dG_[i]);
            }
            dF_.setSize(depth_ - 1);
            dG_.setSize(depth_ - 1);
        }
        dF_.append(scalarField(f - fPrev_));
        dG_.append(scalarField(g - gPrev_));
    }
    gPrev_ = g;
    fPrev_ = f;

    const label m = dF_.size();
    if (m == 0)
    {
        return;
    }

    // Normal equations (dF^T dF) gamma = dF^T f, summed over processors
    List<scalar> dots(m*m + m, Zero);
    for (label i = 0; i < m; ++i)
    {
        for (label j = 0; j <= i; ++j)
        {
            dots[i*m + j] = sum(dF_[i]*dF_[j]);
        }
        dots[m*m + i] = sum(dF_[i]*f);
    }
    reduce_(dots);

    Eigen::MatrixXd A(m, m);
    Eigen::VectorXd b(m);
    scalar trace = 0;
    for (label i = 0; i < m; ++i)
    {
        for (label j = 0; j <= i; ++j)
        {
            A(i, j) = A(j, i) = dots[i*m + j];
        }
        b(i) = dots[m*m + i];
        trace += A(i, i);
    }
    if (!(trace > 0))
    {
        return;
    }
    A += (1e-12*trace/m)*Eigen::MatrixXd::Identity(m, m);
    const Eigen::VectorXd gamma = A.ldlt().solve(b);

    for (label i = 0; i < m; ++i)
    {
        g -= gamma(i)*dG_[i];
    }
}


// ************************************************************************* //
