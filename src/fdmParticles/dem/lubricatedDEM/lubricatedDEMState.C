/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)

Description
    The restart state of the lubricated DEM (particleState entries): the
    particles, the stresslets (output only) and the pair history.

\*---------------------------------------------------------------------------*/

#include "lubricatedDEM.H"
#include "Ostream.H"
#include "dictionary.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fdm::lubricatedDEM::writeState(Ostream& os) const
{
    os.writeEntry("time", time_);
    os.writeEntry("nParticles", size());
    os.writeEntry("position", position_);
    os.writeEntry("velocity", velocity_);
    os.writeEntry("angularVelocity", spin_);
    os.writeEntry("radius", radius_);
    os.writeEntry("mobile", mobile_);
    for (label p = 0; p < lubricatedInteraction::nStressParts; ++p)
    {
        // Output only (local stress profiles); not read back
        os.writeEntry
        (
            word
            (
                "stresslet_"
              + std::string(lubricatedInteraction::stressPartName(p))
            ),
            stresslets(p)
        );
    }

    pairs_.writePairs(os);
    os.writeEntry("pairSelection", pairSelectionName());
    os.writeEntry("timeSinceSearch", timeSinceSearch_);
    os.writeEntry("stepsSinceSearch", stepsSinceSearch_);
    os.writeEntry("displacementSinceSearch", displacementSinceSearch_);
}


void Foam::fdm::lubricatedDEM::readState(const dictionary& dict)
{
    const label n = dict.get<label>("nParticles");
    if (n != size())
    {
        FatalIOErrorInFunction(dict)
            << dict.name() << " holds " << n << " particles but the case"
            << " lists " << size() << exit(FatalIOError);
    }
    const scalarList radius(dict.get<scalarList>("radius"));
    forAll(radius, i)
    {
        if (mag(radius[i] - radius_[i]) > 1e-12*radius_[i])
        {
            FatalIOErrorInFunction(dict)
                << dict.name() << ": particle " << i << " has radius "
                << radius[i] << " but the particle list gives " << radius_[i]
                << "; a restart continues the spheres that started the run"
                << " (restore the list, or start again at time 0)"
                << exit(FatalIOError);
        }
    }
    position_ = dict.get<List<point>>("position");
    velocity_ = dict.get<List<vector>>("velocity");
    spin_ = dict.get<List<vector>>("angularVelocity");

    pairs_.readPairs(dict, mobile_);
    near_ = pairs_.pairs();
    timeSinceSearch_ = dict.get<scalar>("timeSinceSearch");
    stepsSinceSearch_ = dict.getOrDefault<label>("stepsSinceSearch", 0);
    displacementSinceSearch_ =
        dict.get<List<vector>>("displacementSinceSearch");

    // Pairs listed by another selection (the case's neighbours changed
    // since the state was written; states before the choice existed hold
    // cut-off pairs): search again at the first step
    const word selection
    (
        dict.getOrDefault<word>("pairSelection", "cutoff")
    );
    if (selection != pairSelectionName())
    {
        Info<< "    " << dict.name() << " lists " << selection
            << " pairs; the " << pairSelectionName()
            << " pairs are searched at the first step" << nl;
        timeSinceSearch_ = GREAT;
    }
    setTime(dict.get<scalar>("time"));
}


// ************************************************************************* //
