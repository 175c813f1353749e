/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    Consistent overlaps of the coupling stencils (see couplingStencils.H):
    the cells of several supports, their weights, velocity correction and
    the particle-system blocks that couple neighbours through them.

\*---------------------------------------------------------------------------*/

#include "couplingStencils.H"
#include "particleSystemSink.H"
#include "labelPairHashes.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fdm::couplingStencils::findOverlaps(const labelUList& count)
{
    // The thesis form: J_u weighs the velocity integral and the pseudo-mass
    Jintegral_ = Ju_;
    Jmass_ = Ju_;
    integralUx_ = imageUx_;
    overlapStart_.setSize(1, 0);
    overlapEntries_.clear();
    overlapJ_.clear();
    if (!consistentOverlaps_)
    {
        return;
    }

    // Overlap cells in order of first appearance, each with its entries
    labelList slot(count.size(), -1);
    DynamicList<label> start(1, 0);
    forAll(cell_, e)
    {
        const label c = cell_[e];
        if (count[c] > 1 && slot[c] < 0)
        {
            slot[c] = start.size() - 1;
            start.append(start.last() + count[c]);
        }
    }
    overlapStart_.transfer(start);
    const label nOverlap = overlapStart_.size() - 1;
    overlapEntries_.setSize(overlapStart_.last());
    labelList filled(nOverlap, 0);
    forAll(cell_, e)
    {
        const label i = slot[cell_[e]];
        if (i >= 0)
        {
            overlapEntries_[overlapStart_[i] + filled[i]++] = e;
        }
    }

    // J = 1 - prod (1 - J_u): what the thesis' corrections, one particle
    // after the other, move u by in all
    overlapJ_.setSize(nOverlap);
    for (label i = 0; i < nOverlap; ++i)
    {
        scalar unmoved = 1;
        for (label k = overlapStart_[i]; k < overlapStart_[i + 1]; ++k)
        {
            unmoved *= 1 - Ju_[overlapEntries_[k]];
        }
        overlapJ_[i] = 1 - unmoved;
        scalar meanUx = 0;
        for (label k = overlapStart_[i]; k < overlapStart_[i + 1]; ++k)
        {
            const label e = overlapEntries_[k];
            Jintegral_[e] = overlapJ_[i]*Jlambda_[e];
            Jmass_[e] = overlapJ_[i]*sqr(Jlambda_[e]);
            meanUx += Jlambda_[e]*imageUx_[e];
        }
        for (label k = overlapStart_[i]; k < overlapStart_[i + 1]; ++k)
        {
            integralUx_[overlapEntries_[k]] = meanUx;
        }
    }
}


void Foam::fdm::couplingStencils::correctOverlapVelocity
(
    const UList<vector>& U,
    const UList<vector>& Omega,
    UList<vector>& u
) const
{
    forAll(overlapJ_, i)
    {
        vector ubar(Zero);
        for (label k = overlapStart_[i]; k < overlapStart_[i + 1]; ++k)
        {
            const label e = overlapEntries_[k];
            const label p = owner_[e];
            ubar += Jlambda_[e]*rigid(p, e, U, Omega);
        }
        const label c = cell_[overlapEntries_[overlapStart_[i]]];
        u[c] += overlapJ_[i]*(ubar - u[c]);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::fdm::couplingStencils::overlapBlock>
Foam::fdm::couplingStencils::overlapBlocks
(
    const scalarField& V,
    const scalar alphaLambda,
    const UList<labelPair>& pairs
) const
{
    List<overlapBlock> blocks(pairs.size());
    for (overlapBlock& b : blocks)
    {
        b = {Zero, Zero, Zero, Zero};
    }
    labelPairLookup index(2*pairs.size());
    forAll(pairs, k)
    {
        index.insert(pairs[k], k);
    }

    // Particle p's equation: (1/alpha) int J J_lambda,p ubar with ubar =
    // sum_q J_lambda,q (U_q - [r_q]_x Omega_q); torque with r_p x
    forAll(overlapJ_, i)
    {
        for (label k = overlapStart_[i]; k < overlapStart_[i + 1]; ++k)
        {
            const label e = overlapEntries_[k];
            // [r]_x, the matrix of v -> r x v: OpenFOAM's Hodge dual
            const tensor Re(*offset_[e]);
            for (label m = overlapStart_[i]; m < overlapStart_[i + 1]; ++m)
            {
                const label f = overlapEntries_[m];
                const auto found =
                    index.cfind(labelPair(owner_[e], owner_[f]));
                if (!found.found())
                {
                    continue;
                }
                const scalar w =
                    overlapJ_[i]*Jlambda_[e]*Jlambda_[f]*V[cell_[e]]
                   /alphaLambda;
                const tensor Rf(*offset_[f]);
                overlapBlock& b = blocks[*found];
                b.forceU += w*tensor::I;
                b.forceOmega -= w*Rf;
                b.torqueU += w*Re;
                b.torqueOmega -= w*(Re & Rf);
            }
        }
    }
    return blocks;
}


void Foam::fdm::couplingStencils::addOverlapBlocks
(
    const UList<labelPair>& pairs,
    const UList<overlapBlock>& blocks,
    particleSystemSink& system
)
{
    forAll(pairs, k)
    {
        const label p = pairs[k].first();
        const label q = pairs[k].second();
        const overlapBlock& b = blocks[k];
        for (direction r = 0; r < 3; ++r)
        {
            for (direction c = 0; c < 3; ++c)
            {
                const scalar entries[4] =
                {
                    b.forceU(r, c), b.forceOmega(r, c),
                    b.torqueU(r, c), b.torqueOmega(r, c)
                };
                const label rows[4] = {r, r, 3 + r, 3 + r};
                const label cols[4] = {c, 3 + c, c, 3 + c};
                for (label j = 0; j < 4; ++j)
                {
                    // Block (p, q) and its transpose (q, p)
                    system.addEntry(6*p + rows[j], 6*q + cols[j], entries[j]);
                    system.addEntry(6*q + cols[j], 6*p + rows[j], entries[j]);
                }
            }
        }
    }
}


// ************************************************************************* //
