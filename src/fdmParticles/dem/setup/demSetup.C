/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demSetup.H"
#include "demLoads.H"
#include "demState.H"
#include "particleList.H"
#include "checkKeywords.H"
#include "readBounded.H"
#include "fpTrapsOff.H"
#include "HashSet.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::autoPtr<Foam::IOdictionary> Foam::fdm::readDEMProperties
(
    const Time& runTime
)
{
    IOobject propertiesIO
    (
        "particleProperties",
        runTime.constant(),
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (!propertiesIO.typeHeaderOk<IOdictionary>(true))
    {
        fdm::requireHeader(propertiesIO.objectPath());
    }
    autoPtr<IOdictionary> propertiesPtr;
    {
        fdm::fpTrapsOff trapsOff;
        propertiesPtr.reset(new IOdictionary(propertiesIO));
    }
    return propertiesPtr;
}


void Foam::fdm::checkDEMKeywords(const dictionary& props)
{
    fdm::checkKeywords
    (
        props,
        {
            "particlesFile", "particles", "density", "cell", "drag",
            "fixedGroups", "gravity", "fluidDensity", "pressureWall",
            "lubricatedContact", "neighbours", "output"
        },
        "top level of the lubricatedDEM input"
    );
    const std::initializer_list<std::pair<const char*, wordList>> blocks
    {
        {"cell", {"min", "max", "shearRate", "open"}},
        {"drag", {"viscosity", "isolatedViscosity", "isolatedBelow"}},
        {"pressureWall", {"group", "pressure", "damping"}},
        {"neighbours", {"selection", "interval"}},
        {"output", {"interval", "track", "vtkInterval"}}
    };
    for (const auto& block : blocks)
    {
        if (props.isDict(block.first))
        {
            fdm::checkKeywords
            (
                props.subDict(block.first),
                block.second,
                word(block.first) + " block"
            );
        }
    }
}


Foam::FixedList<bool, 3> Foam::fdm::readPeriodicity(const dictionary& cell)
{
    FixedList<bool, 3> periodic({true, true, true});
    for (const word& w : cell.getOrDefault<wordList>("open", wordList()))
    {
        const label d = fdm::axisIndex(w);
        if (d < 0)
        {
            FatalIOErrorInFunction(cell)
                << "open: direction '" << w << "' is not one of x, y, z"
                << " (the directions without periodic images, e.g. (y) for"
                << " gravity along the velocity gradient)"
                << exit(FatalIOError);
        }
        periodic[d] = false;
    }
    return periodic;
}


void Foam::fdm::setNeighbours(lubricatedDEM& dem, const dictionary& props)
{
    const dictionary dict(props.subOrEmptyDict("neighbours"));
    const word selection(dict.getOrDefault<word>("selection", "cutoff"));
    fdm::checkChoice(dict, "selection", selection, {"cutoff", "delaunay"});
    if (selection == "delaunay")
    {
        dem.setDelaunayNeighbours
        (
            label
            (
                fdm::readBoundedOrDefault
                (
                    dict, "interval", 1, 1, labelMax,
                    "steps between Delaunay triangulations (1: the pairs"
                    " follow every change of the triangulation)"
                )
            )
        );
    }
    else if (dict.found("interval"))
    {
        FatalIOErrorInFunction(dict)
            << "interval: the steps between Delaunay triangulations apply"
            << " to selection delaunay only (cutoff pairs come from a"
            << " Verlet list)" << exit(FatalIOError);
    }
}


namespace
{

//- The set-up's summary: the model's settings and the two numbers that
//  decide the regime (rigidity, inertia)
void reportSetUp
(
    const Foam::fdm::lubricatedDEM& dem,
    const Foam::scalar shearRate,
    const Foam::scalar rho
)
{
    using namespace Foam;
    const fdm::lubricatedContact& m = dem.model();
    const scalar a = min(dem.radii());
    Info<< "lubricatedDEM: " << dem.size() << " spheres, phi "
        << dem.volumeFraction() << ", shear rate " << shearRate << nl
        << "    roughness " << m.roughness() << ", friction "
        << m.friction() << ", cutoff " << m.cutoff() << " a, shearArms "
        << fdm::lubricatedContact::shearArmsNames[m.arms()]
        << ", asperities "
        << fdm::lubricatedContact::asperitiesNames[m.asperitiesPlace()]
        << ", torques "
        << fdm::lubricatedContact::torqueFormsNames[m.torques()]
        << ", lubrication " << m.lubricationName() << nl
        << "    lubricated pairs: ";
    if (dem.delaunayInterval() > 0)
    {
        Info<< "Delaunay neighbours within the cutoff, triangulated every "
            << dem.delaunayInterval() << " steps" << nl;
    }
    else
    {
        Info<< "every pair within the cutoff" << nl;
    }
    Info<< "    stiffness number g/(eta gammaDot a) "
        << m.stiffness()/(m.viscosity()*max(mag(shearRate), SMALL)*a)
        << ", Stokes number rho a^2 gammaDot/eta "
        << rho*a*a*mag(shearRate)/m.viscosity() << nl;
}

} // namespace


Foam::fdm::lubricatedDEM Foam::fdm::createDEM
(
    const dictionary& props,
    const Time& runTime
)
{
    checkDEMKeywords(props);
    const dictionary& cell = props.subDict("cell");
    const fdm::periodicBox box
    (
        cell.get<point>("min"),
        cell.get<point>("max"),
        readPeriodicity(cell)
    );
    const scalar shearRate = cell.get<scalar>("shearRate");

    fdm::lubricatedDEM dem
    (
        box,
        shearRate,
        fdm::lubricatedContact(props.subDict("lubricatedContact"))
    );
    const scalar rho = fdm::readBounded
    (
        props, "density", VSMALL, GREAT,
        "particle density rho_p (Stokes number rho_p a^2 gammaDot/eta)"
    );
    setDrag(dem, props);
    setNeighbours(dem, props);

    const fdm::particleList list = fdm::readParticleList
    (
        props, runTime.globalPath()/runTime.constant()
    );
    const wordList fixedGroups
    (
        props.getOrDefault<wordList>("fixedGroups", wordList())
    );
    for (const word& g : fixedGroups)
    {
        if (!list.group.found(g))
        {
            FatalIOErrorInFunction(props)
                << "fixedGroups: no particle of group " << g << " in the"
                << " particle list; its groups are "
                << wordList(HashSet<word>(list.group).sortedToc())
                << exit(FatalIOError);
        }
    }
    fdm::checkParticleList(list.position, list.radius, box, list.source);
    boolList mobile(list.position.size());
    forAll(list.position, i)
    {
        mobile[i] = !fixedGroups.found(list.group[i]);
    }
    dem.addParticles(list.position, list.radius, rho, mobile);
    setGravity(dem, props, rho, mobile);
    setPressureWall(dem, props, list, mobile);

    readDEMState(dem, runTime);
    reportSetUp(dem, shearRate, rho);
    return dem;
}


void Foam::fdm::checkTimeStep
(
    const fdm::lubricatedDEM& dem,
    const scalar dt,
    const Time& runTime
)
{
    const scalar dtCr = dem.criticalTimeStep();
    Info<< "    deltaT " << dt << " = " << dt/dtCr
        << " of the critical step min sqrt(m/k) = " << dtCr;
    if (mag(dem.shearRate()) > 0)
    {
        Info<< ", " << 1/(dt*mag(dem.shearRate())) << " steps per strain";
    }
    Info<< nl;

    if (dt > dtCr)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "deltaT " << dt << " in system/controlDict is above the"
            << " critical step min sqrt(m/k) = " << dtCr
            << " of the particles' masses and the stiffnesses g, k_t"
            << " (thesis 2, eqs 2.6-2.7): allowed deltaT <= " << dtCr
            << "; dense packings need about " << 0.2*dtCr
            << " (several contacts per particle)" << exit(FatalIOError);
    }
}


// ************************************************************************* //
