/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

\*---------------------------------------------------------------------------*/

#include "twoSphereResistance.H"
#include "resistanceTensorForms.H"
#include "tensor.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const char* const Foam::fdm::twoSphereResistance::defaultTableName =
    "$FDM_PROJECT_DIR/data/resistance/twoBody_lambda1";


Foam::fileName Foam::fdm::twoSphereResistance::defaultTable()
{
    fileName table(defaultTableName);
    table.expand();
    return table;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fdm::twoSphereResistance::twoSphereResistance
(
    const resistanceTable& table,
    const scalar viscosity
)
:
    table_(table),
    viscosity_(viscosity),
    squeeze_(0)
{
    if (table_.kind() != resistanceTable::tableKind::twoBody)
    {
        FatalErrorInFunction
            << "Resistance table " << table_.name() << " is not a twoBody"
            << " table (kind twoBody: the exact functions of two spheres"
            << " minus the isolated sphere's)" << exit(FatalError);
    }
    if (mag(table_.lambda() - 1) > SMALL)
    {
        FatalErrorInFunction
            << "Resistance table " << table_.name() << ": lambda = "
            << table_.lambda() << "; the two-body hydrodynamics reads the"
            << " table of equal spheres (lambda 1)" << exit(FatalError);
    }
    squeeze_ = table_.singular("XA11")[0];
}


Foam::fdm::twoSphereResistance::twoSphereResistance
(
    const fileName& table,
    const scalar viscosity,
    const scalar xMin
)
:
    twoSphereResistance(resistanceTable::read(table, xMin), viscosity)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fdm::twoSphereLoads Foam::fdm::twoSphereResistance::loads
(
    const vector& d,
    const scalar centreGap,
    const scalar radius1,
    const scalar radius2,
    const vector& U1,
    const vector& W1,
    const vector& U2,
    const vector& W2,
    const symmTensor& E,
    const bool withSqueeze
) const
{
    // Equal-sphere functions at the harmonic-mean radius (see Description),
    // on the stack (one pair of a DEM step)
    const scalar a = 2*radius1*radius2/(radius1 + radius2);
    FixedList<scalar, resistanceTable::nTwoBodyFunctions> values;
    UList<scalar> f(values.data(), values.size());
    table_.values(centreGap/a, a, f);

    // Function f11 of block (i, j) from its 11 and 12 values and parity p
    typedef resistanceTable rt;
    auto block = [&f](const label f11, const scalar p, const label i,
                      const label j)
    {
        const scalar s11 = f[f11], s12 = f[f11 + 1];
        return i == j ? (i == 0 ? s11 : p*s11) : (i == 0 ? s12 : p*s12);
    };

    // The pair's common translation projected out, of the velocities here
    // and of the forces below (see Description)
    const vector common = 0.5*(U1 + U2);
    const vector U[2] = {U1 - common, U2 - common};
    const vector W[2] = {W1, W2};
    const scalar eta = viscosity_;
    twoSphereLoads out;
    for (label i = 0; i < 2; ++i)
    {
        vector F(Zero), T(Zero);
        for (label j = 0; j < 2; ++j)
        {
            F -= axialForm
            (
                block(rt::XA11, 1, i, j), block(rt::YA11, 1, i, j), d
            ) & U[j];
            F -= epsilonForm(-block(rt::YB11, -1, j, i), d) & W[j];
            F += strainContractG
            (
                block(rt::XG11, -1, j, i), block(rt::YG11, -1, j, i), d, E
            );
            T -= epsilonForm(block(rt::YB11, -1, i, j), d) & U[j];
            T -= axialForm
            (
                block(rt::XC11, 1, i, j), block(rt::YC11, 1, i, j), d
            ) & W[j];
            T += strainContractH(block(rt::YH11, 1, j, i), d, E);
        }
        out.force[i] = eta*F;
        out.torque[i] = eta*T;
        // Own block of the projected A: (A_ii - A_ij - A_ji + A_jj)/4,
        // the 22 and 21 blocks being the 11 and 12 ones (X^A, Y^A even)
        out.translationDamping[i] = 0.5*eta*symm
        (
            axialForm
            (
                block(rt::XA11, 1, 0, 0) - block(rt::XA11, 1, 0, 1),
                block(rt::YA11, 1, 0, 0) - block(rt::YA11, 1, 0, 1),
                d
            )
        );
        out.rotationDamping[i] = eta*symm
        (
            axialForm(block(rt::XC11, 1, i, i), block(rt::YC11, 1, i, i), d)
        );
    }
    const vector commonForce = 0.5*(out.force[0] + out.force[1]);
    out.force[0] -= commonForce;
    out.force[1] -= commonForce;
    if (!withSqueeze)
    {
        removeSqueeze(d, centreGap, a, radius1 + radius2, U1, U2, E, out);
    }
    return out;
}


void Foam::fdm::twoSphereResistance::removeSqueeze
(
    const vector& d,
    const scalar centreGap,
    const scalar a,
    const scalar radiusSum,
    const vector& U1,
    const vector& U2,
    const symmTensor& E,
    twoSphereLoads& loads
) const
{
    // The leading term of X^A, eta c a*^2/u_n with c the table's 1/xi
    // coefficient of XA11 (3/2 pi: thesis 2, article 1, eq 4), on the
    // whole relative normal velocity, ambient strain included: what the
    // implicit normal model applies.  Removed with its own-velocity
    // blocks.  Its ambient part cancels the 1/xi terms of X^G, so that
    // what stays is logarithmic at contact
    const scalar c =
        viscosity_*squeeze_*sqr(a)/max(centreGap, table_.xMin()*a);
    const vector r = (centreGap + radiusSum)*d;
    const scalar approach = ((U2 - U1) + (E & r)) & d;
    const vector F = c*approach*d;
    loads.force[0] -= F;
    loads.force[1] += F;
    for (label i = 0; i < 2; ++i)
    {
        loads.translationDamping[i] -= c*sqr(d);
    }
}


// ************************************************************************* //
