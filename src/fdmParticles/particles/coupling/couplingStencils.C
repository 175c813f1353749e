/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "couplingStencils.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::fdm::couplingStencils::image>
Foam::fdm::couplingStencils::images(const periodicBox& box)
{
    // Across y: the offset within +-L_x/2, so that the x images -1, 0, 1
    // around it cover the box and the supports reaching into it
    const scalar Lx = box.span().x();
    const scalar offset =
        box.shearOffset() - Lx*std::round(box.shearOffset()/Lx);

    DynamicList<image> found(27);
    for (label k = -1; k <= 1; ++k)
    for (label j = -1; j <= 1; ++j)
    for (label i = -1; i <= 1; ++i)
    {
        const FixedList<label, 3> s({i, j, k});
        bool valid = true;
        vector shift(Zero);
        for (direction d = 0; d < 3; ++d)
        {
            if (s[d] != 0 && !box.periodic(d))
            {
                valid = false;
            }
            shift[d] = s[d]*box.span()[d];
        }
        if (valid)
        {
            shift.x() += j*offset;
            found.append(image{shift, box.imageVelocity(j).x()});
        }
    }
    return List<image>(std::move(found));
}


Foam::List<Foam::vector>
Foam::fdm::couplingStencils::imageShifts(const periodicBox& box)
{
    const List<image> all(images(box));
    List<vector> shifts(all.size());
    forAll(all, i)
    {
        shifts[i] = all[i].shift;
    }
    return shifts;
}


void Foam::fdm::couplingStencils::build
(
    const pointField& cellCentres,
    const pointBins& cellBins,
    const pointField& positions,
    const scalarField& radii,
    const indicatorFunctions& indicator,
    const periodicBox& box,
    const bool consistentOverlaps,
    const UList<bool>& held
)
{
    start_.setSize(positions.size() + 1);
    cell_.clear();
    offset_.clear();
    Ju_.clear();
    Jlambda_.clear();
    owner_.clear();
    imageUx_.clear();
    consistentOverlaps_ = consistentOverlaps;

    const List<image> shifts(images(box));
    DynamicList<label> found;
    forAll(positions, p)
    {
        start_[p] = cell_.size();
        if (held.size() && !held[p])
        {
            continue;
        }
        const scalar a = radii[p];
        const scalar R = indicator.supportRadius(a);

        for (const image& im : shifts)
        {
            const point centre = positions[p] + im.shift;
            found.clear();
            cellBins.findInSphere(centre, R, found);
            for (const label celli : found)
            {
                const vector r = cellCentres[celli] - centre;
                cell_.append(celli);
                owner_.append(p);
                offset_.append(r);
                Ju_.append(indicator.Ju(mag(r), a));
                Jlambda_.append(1);
                imageUx_.append(im.Ux);
            }
        }
    }
    start_[positions.size()] = cell_.size();

    // J_lambda shared where supports overlap (section 2.3.2: 1/2 for two)
    labelList count(cellCentres.size(), 0);
    DynamicList<label> support;
    for (const label celli : cell_)
    {
        if (count[celli]++ == 0)
        {
            support.append(celli);
        }
    }
    forAll(cell_, e)
    {
        Jlambda_[e] = 1.0/count[cell_[e]];
    }
    supportCells_.transfer(support);
    findOverlaps(count);
}


Foam::List<Foam::fdm::rigidBodyMoments>
Foam::fdm::couplingStencils::moments(const scalarField& V) const
{
    List<rigidBodyMoments> m(size());
    forAll(m, p)
    {
        for (label e = start_[p]; e < start_[p + 1]; ++e)
        {
            m[p].add(Jmass_[e], offset_[e], V[cell_[e]]);
        }
    }
    return m;
}


Foam::List<Foam::fdm::couplingStencils::supportIntegrals>
Foam::fdm::couplingStencils::integrals
(
    const scalarField& V,
    const UList<vector>& u,
    const UList<vector>& lambda
) const
{
    List<supportIntegrals> sums(size());
    forAll(sums, p)
    {
        vector fu(Zero), tu(Zero), fl(Zero), tl(Zero);
        for (label e = start_[p]; e < start_[p + 1]; ++e)
        {
            const label c = cell_[e];
            const vector& r = offset_[e];
            const vector wu =
                (Jintegral_[e]*V[c])*(u[c] - vector(integralUx_[e], 0, 0));
            const vector wl = (Jlambda_[e]*V[c])*lambda[c];
            fu += wu;
            tu += r ^ wu;
            fl += wl;
            tl += r ^ wl;
        }
        sums[p] = {fu, tu, fl, tl};
    }
    return sums;
}


void Foam::fdm::couplingStencils::correctLambda
(
    const UList<vector>& U,
    const UList<vector>& Omega,
    const scalar alphaLambda,
    const UList<vector>& u,
    UList<vector>& lambda
) const
{
    for (label p = 0; p < size(); ++p)
    {
        for (label e = start_[p]; e < start_[p + 1]; ++e)
        {
            const label c = cell_[e];
            lambda[c] +=
                (Jlambda_[e]/alphaLambda)*(rigid(p, e, U, Omega) - u[c]);
        }
    }
}


void Foam::fdm::couplingStencils::correctVelocity
(
    const UList<vector>& U,
    const UList<vector>& Omega,
    UList<vector>& u
) const
{
    // Consistent overlaps: the cells of several supports (J_lambda < 1)
    // first, from the uncorrected u; the loop below leaves them
    correctOverlapVelocity(U, Omega, u);
    for (label p = 0; p < size(); ++p)
    {
        for (label e = start_[p]; e < start_[p + 1]; ++e)
        {
            if (consistentOverlaps_ && Jlambda_[e] < 1)
            {
                continue;
            }
            const label c = cell_[e];
            u[c] += Ju_[e]*(rigid(p, e, U, Omega) - u[c]);
        }
    }
}


Foam::List<Foam::fdm::couplingStencils::dipoleIntegrals>
Foam::fdm::couplingStencils::dipoles
(
    const scalarField& V,
    const UList<vector>& lambda,
    const scalarField& p,
    const scalar pMean
) const
{
    List<dipoleIntegrals> sums(size());
    forAll(sums, n)
    {
        vector f(Zero);
        tensor moment(Zero);
        scalar pressure = 0;
        for (label e = start_[n]; e < start_[n + 1]; ++e)
        {
            const label c = cell_[e];
            const vector w = (Jlambda_[e]*V[c])*lambda[c];
            f += w;
            moment += w*offset_[e];
            pressure += Ju_[e]*V[c]*(p[c] - pMean);
        }
        sums[n] = {f, moment, pressure};
    }
    return sums;
}


// ************************************************************************* //
