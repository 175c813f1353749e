/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "channelAverages.H"
#include "tensor.H"
#include "mathematicalConstants.H"
#include "error.H"

#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fdm::slabVolume(scalar c, scalar a, scalar lo, scalar hi)
{
    const scalar u0 = min(max(lo - c, -a), a);
    const scalar u1 = min(max(hi - c, -a), a);
    auto F = [a](scalar u) { return a*a*u - u*u*u/3; };
    return constant::mathematical::pi*(F(u1) - F(u0));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::channelAverages::channelAverages
(
    const point& lo,
    const vector& span,
    direction normal,
    direction flow,
    label nBins,
    scalar leesEdwardsRate
)
:
    normal_(normal),
    flow_(flow),
    lo_(lo[normal]),
    height_(span[normal]),
    area_(cmptProduct(span)/span[normal]),
    nBins_(nBins),
    leesEdwardsRate_(leesEdwardsRate)
{
    if (normal > 2 || flow > 2 || normal == flow || nBins < 1)
    {
        FatalErrorInFunction
            << "need distinct normal and flow directions (0, 1, 2) and at "
            << "least one bin; got normal " << label(normal) << ", flow "
            << label(flow) << ", " << nBins << " bins" << exit(FatalError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::Pair<Foam::scalar>>
Foam::fdm::channelAverages::images(const scalar c) const
{
    if (leesEdwardsRate_ == 0)
    {
        return {Pair<scalar>(c, 0)};
    }
    const scalar du = leesEdwardsRate_*height_;
    return
    {
        Pair<scalar>(c, 0),
        Pair<scalar>(c - height_, -du),
        Pair<scalar>(c + height_, du)
    };
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fdm::channelAverages::profiles
Foam::fdm::channelAverages::binned(const particleSample& s) const
{
    const scalar dy = height_/nBins_;
    profiles p;
    p.y.setSize(nBins_);
    p.volumeFraction = scalarField(nBins_, Zero);
    p.velocity = List<vector>(nBins_, Zero);
    p.hydrodynamic = List<symmTensor>(nBins_, Zero);
    p.contact = List<symmTensor>(nBins_, Zero);

    const bool hasContact = !s.contact.empty();
    forAll(s.position, i)
    {
        const scalar a = s.radius[i];
        const scalar Vp = 4.0/3.0*constant::mathematical::pi*a*a*a;
        for (const Pair<scalar>& image : images(s.position[i][normal_]))
        {
            const scalar c = image.first();
            vector u = s.velocity[i];
            u[flow_] += image.second();
            // Only the bins the sphere reaches
            const label b0 = max(label(std::floor((c - a - lo_)/dy)), 0);
            const label b1 =
                min(label(std::floor((c + a - lo_)/dy)), nBins_ - 1);
            for (label b = b0; b <= b1; ++b)
            {
                const scalar v =
                    slabVolume(c, a, lo_ + b*dy, lo_ + (b + 1)*dy);
                p.volumeFraction[b] += v;
                p.velocity[b] += v*u;
                // Stresslet spread uniformly over the sphere (eq 2.75)
                p.hydrodynamic[b] += (v/Vp)*s.hydrodynamic[i];
                if (hasContact)
                {
                    p.contact[b] += (v/Vp)*s.contact[i];
                }
            }
        }
    }

    const scalar binVolume = area_*dy;
    forAll(p.y, b)
    {
        p.y[b] = lo_ + (b + 0.5)*dy;
        // eq 6.4: phi u_p is the bin average of sum U_p chi_p
        if (p.volumeFraction[b] > 0)
        {
            p.velocity[b] /= p.volumeFraction[b];
        }
        p.volumeFraction[b] /= binVolume;
        p.hydrodynamic[b] /= binVolume;
        p.contact[b] /= binVolume;
    }
    return p;
}


Foam::fdm::channelAverages::region
Foam::fdm::channelAverages::averages
(
    const particleSample& s,
    scalar layer
) const
{
    const scalar lo = lo_ + layer;
    const scalar hi = lo_ + height_ - layer;
    if (hi <= lo)
    {
        FatalErrorInFunction
            << "wall layer " << layer << " leaves no core in a channel of "
            << "height " << height_ << exit(FatalError);
    }

    region r{0, 0, 0, Zero, Zero};
    scalar sy = 0, su = 0, syy = 0, syu = 0;
    const bool hasContact = !s.contact.empty();
    forAll(s.position, i)
    {
        const scalar y = s.position[i][normal_];
        for (const Pair<scalar>& image : images(y))
        {
            r.volumeFraction += slabVolume(image.first(), s.radius[i], lo, hi);
        }
        if (y > lo && y < hi)
        {
            ++r.nParticles;
            r.hydrodynamic += s.hydrodynamic[i];
            if (hasContact)
            {
                r.contact += s.contact[i];
            }
            const scalar u = s.velocity[i][flow_];
            sy += y;
            su += u;
            syy += y*y;
            syu += y*u;
        }
    }

    const scalar V = area_*(hi - lo);
    r.volumeFraction /= V;
    r.hydrodynamic /= V;
    r.contact /= V;

    if (leesEdwardsRate_ != 0)
    {
        // The mean velocity gradient of a Lees-Edwards cell is imposed
        r.shearRate = leesEdwardsRate_;
        return r;
    }
    // Least-squares slope of u(y); undefined below two particles
    const label n = r.nParticles;
    const scalar varY = syy - sy*sy/max(n, 1);
    r.shearRate = (n >= 2 && varY > 0) ? (syu - sy*su/n)/varY
        : std::numeric_limits<scalar>::quiet_NaN();
    return r;
}


Foam::scalar Foam::fdm::channelAverages::shear(const symmTensor& t) const
{
    return tensor(t)(flow_, normal_);
}


Foam::scalar
Foam::fdm::channelAverages::firstDifference(const symmTensor& t) const
{
    const tensor T(t);
    return T(flow_, flow_) - T(normal_, normal_);
}


Foam::scalar
Foam::fdm::channelAverages::secondDifference(const symmTensor& t) const
{
    const tensor T(t);
    const direction vorticity = 3 - normal_ - flow_;
    return T(normal_, normal_) - T(vorticity, vorticity);
}


// ************************************************************************* //
