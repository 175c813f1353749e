/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The lubricatedContact dictionary and the two-body hydrodynamics of
    lubrication twoSphere (lubricatedContact.H).

\*---------------------------------------------------------------------------*/

#include "lubricatedContact.H"
#include "readBounded.H"
#include "checkKeywords.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

namespace
{

//- The model of a lubricatedContact block, its keywords checked first
Foam::fdm::lubricatedContact fromDictionary(const Foam::dictionary& dict)
{
    using namespace Foam;
    using namespace Foam::fdm;
    checkKeywords
    (
        dict,
        {
            "viscosity", "stiffness", "stiffnessRatio",
            "tangentialStiffness", "roughness", "friction", "cutoff",
            "shearArms", "asperities", "torques", "lubrication", "table"
        },
        "lubricatedContact block"
    );
    lubricatedContact law
    (
        readBounded(dict, "viscosity", VSMALL, GREAT, "fluid viscosity eta_f"),
        readBounded
        (
            dict, "stiffness", VSMALL, GREAT,
            "bulk stiffness g [force/length]; rigid limit g/(eta gammaDot a)"
            " >~ 1e5"
        ),
        readBoundedOrDefault
        (
            dict, "stiffnessRatio", 1, VSMALL, GREAT,
            "asperity/bulk stiffness k_n/g; thesis 1"
        ),
        readBoundedOrDefault
        (
            dict, "tangentialStiffness", 0.5, VSMALL, GREAT,
            "k_t/g; not given by the thesis, default 0.5"
        ),
        readBounded
        (
            dict, "roughness", 0, 0.5,
            "asperity height eps = h/a; 0 for smooth spheres, thesis 1e-3"
        ),
        readBounded(dict, "friction", 0, GREAT, "Coulomb coefficient mu_m"),
        readBoundedOrDefault
        (
            dict, "cutoff", 2, VSMALL, GREAT,
            "interaction while the gap is below cutoff*a; thesis 2 (4 for"
            " the two-sphere test)"
        ),
        readChoice
        (
            dict, "shearArms", lubricatedContact::shearArmsNames,
            lubricatedContact::shearArms::contactPoint
        ),
        readChoice
        (
            dict, "asperities", lubricatedContact::asperitiesNames,
            lubricatedContact::asperities::outside
        )
    );

    law.setTorques
    (
        readChoice
        (
            dict, "torques", lubricatedContact::torqueFormsNames,
            lubricatedContact::torqueForms::thesis
        )
    );

    const word lubrication(dict.getOrDefault<word>("lubrication", "thesis"));
    checkChoice(dict, "lubrication", lubrication, {"thesis", "twoSphere"});
    if (lubrication == "twoSphere")
    {
        fileName table
        (
            dict.getOrDefault<fileName>
            (
                "table",
                twoSphereResistance::defaultTableName
            )
        );
        table.expand();
        law.useTwoSphereHydrodynamics(table);
    }
    else if (dict.found("table"))
    {
        FatalIOErrorInFunction(dict)
            << "table: the two-body resistance table applies to lubrication"
            << " twoSphere only (lubrication is " << lubrication << ")"
            << exit(FatalIOError);
    }
    return law;
}

} // namespace


Foam::fdm::lubricatedContact::lubricatedContact(const dictionary& dict)
:
    lubricatedContact(fromDictionary(dict))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::lubricatedContact::useTwoSphereHydrodynamics
(
    const fileName& table
)
{
    if (asperities_ == asperities::inside)
    {
        FatalErrorInFunction
            << "asperities inside is article 2's law with the thesis forms;"
            << " lubrication twoSphere needs asperities outside (its gap is"
            << " the surface gap)" << exit(FatalError);
    }
    // The functions freeze where the asperities touch (gap floored at the
    // roughness, and at the table's first point for smooth spheres)
    twoBody_ = std::make_shared<const twoSphereResistance>
    (
        table, viscosity_, max(roughness_, 1e-6)
    );
    if (cutoff_ > twoBody_->maxGap())
    {
        FatalErrorInFunction
            << "cutoff " << cutoff_ << " is beyond the last gap "
            << twoBody_->maxGap() << " of the two-body table " << table
            << "; allowed cutoff <= " << twoBody_->maxGap()
            << exit(FatalError);
    }
}


const Foam::fdm::twoSphereResistance&
Foam::fdm::lubricatedContact::twoBody() const
{
    if (!twoBody_)
    {
        FatalErrorInFunction
            << "lubrication thesis has no two-body hydrodynamics"
            << abort(FatalError);
    }
    return *twoBody_;
}


// ************************************************************************* //
