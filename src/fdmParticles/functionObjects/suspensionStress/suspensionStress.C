/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "suspensionStress.H"
#include "addToRunTimeSelectionTable.H"
#include "particleStateFile.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "freshOutputFile.H"
#include "checkKeywords.H"
#include "IOdictionary.H"
#include "Time.H"
#include "fvMesh.H"
#include "readBounded.H"
#include "leesEdwardsShear.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(suspensionStress, 0);
    addToRunTimeSelectionTable(functionObject, suspensionStress, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

Foam::direction readAxis
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::word& deflt
)
{
    const Foam::word name = dict.getOrDefault<Foam::word>(key, deflt);
    const Foam::label d = Foam::fdm::axisIndex(name);
    if (d >= 0)
    {
        return d;
    }
    FatalIOErrorInFunction(dict)
        << "keyword " << key << " is " << name << "; allowed: x, y, z"
        << Foam::exit(Foam::FatalIOError);
    return 0;
}


void writeRow(Foam::Ostream& os, const Foam::symmTensor& t)
{
    for (Foam::direction c = 0; c < Foam::symmTensor::nComponents; ++c)
    {
        os  << Foam::token::TAB << t[c];
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::functionObjects::suspensionStress::readSample
(
    fdm::particleSample& s
) const
{
    const fileName file = time_.globalPath()/time_.timeName()/"particleState";
    if (!isFile(file))
    {
        return false;
    }
    const dictionary state(fdm::readParticleStateFile(file));
    if (!state.found("radius"))
    {
        FatalIOErrorInFunction(state)
            << file << " has no keyword radius: it was written before "
            << "fdmSuspensionFoam recorded the radii; continue the run for "
            << "one step to write a complete particle state"
            << exit(FatalIOError);
    }
    s.position = state.get<List<point>>("position");
    s.velocity = state.get<List<vector>>("velocity");
    s.radius = state.get<scalarField>("radius");

    // S^H = S^h + (s^h/3) I, solver and sub-grid parts (eq 2.73)
    s.hydrodynamic = state.get<List<symmTensor>>("stresslet");
    const List<scalar> trace = state.get<List<scalar>>("dipoleTrace");
    forAll(s.hydrodynamic, i)
    {
        s.hydrodynamic[i] += (trace[i]/3)*symmTensor::I;
    }
    s.contact.clear();
    state.readIfPresent("contactStresslet", s.contact);
    return true;
}


void Foam::functionObjects::suspensionStress::writeProfiles
(
    const fdm::channelAverages::profiles& p
) const
{
    const fileName dir = baseTimeDir();
    mkDir(dir);
    OFstream os(fdm::freshOutputFile(dir, "profiles"));
    os.precision(writePrecision_);
    const word n(vector::componentNames[normal_]);
    os  << "# Suspension profiles (thesis 1 eqs 2.70, 2.75, 6.4, 6.5) at "
        << "time " << time_.timeName() << nl
        << "# " << n << " phi Up_x Up_y Up_z"
        << " SigmaHp_xx xy xz yy yz zz SigmaC_xx xy xz yy yz zz" << nl;
    forAll(p.y, b)
    {
        os  << p.y[b] << token::TAB << p.volumeFraction[b];
        for (direction c = 0; c < 3; ++c)
        {
            os  << token::TAB << p.velocity[b][c];
        }
        writeRow(os, p.hydrodynamic[b]);
        writeRow(os, p.contact[b]);
        os  << nl;
    }
}


Foam::autoPtr<Foam::OFstream>
Foam::functionObjects::suspensionStress::createFile
(
    const word& name,
    scalar timeValue
) const
{
    autoPtr<OFstream> os;
    if (Pstream::master() && writeToFile_)
    {
        if (useUserTime_)
        {
            timeValue = time_.timeToUserTime(timeValue);
        }
        const fileName dir = baseFileDir()/prefix_/Time::timeName(timeValue);
        mkDir(dir);
        os.reset(new OFstream(fdm::freshOutputFile(dir, name)));
        initStream(os());
    }
    return os;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::suspensionStress::suspensionStress
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName),
    normal_(1),
    flow_(0),
    bins_(20),
    wallLayer_(0),
    eta_(0)
{
    read(dict);
    resetFile(typeName);

    OFstream& os = file();
    writeHeader(os, "Suspension stress (thesis 1 eqs 2.70-2.76, 4.13)");
    writeHeader
    (
        os,
        "etaRel = 1 + Sigma^p_xy/(eta shearRate), shearRate by regression "
        "of the particle centres; Sigma_xy = eta shearRate + Sigma^p_xy; "
        "core tensors xx xy xz yy yz zz"
    );
    writeCommented(os, "Time");
    for
    (
        const char* col :
        {
            "phi", "phiCore", "nCore", "shearRate", "shearRateCore",
            "etaRel", "etaRelCore", "contactShareCore", "N1Core/Sigma_xy",
            "N2Core/Sigma_xy", "SigmaHpCore(6)", "SigmaCCore(6)"
        }
    )
    {
        writeTabbed(os, col);
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::suspensionStress::read(const dictionary& dict)
{
    // This object's keywords and those OpenFOAM's function-object
    // machinery reads (type, libs, time controls, writeFile settings)
    fdm::checkKeywords
    (
        dict,
        {
            "normal", "flow", "bins", "wallLayer",
            "type", "libs", "enabled", "log", "region", "timeStart",
            "timeEnd", "executeControl", "executeInterval", "writeControl",
            "writeInterval", "outputControl", "outputInterval",
            "writePrecision", "writeToFile", "useUserTime"
        },
        "function object " + name()
    );
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    normal_ = readAxis(dict, "normal", "y");
    flow_ = readAxis(dict, "flow", "x");
    bins_ = dict.getOrDefault<label>("bins", 20);
    wallLayer_ = dict.getOrDefault<scalar>("wallLayer", 0);

    const boundBox& bb = mesh_.bounds();
    if (wallLayer_ < 0 || 2*wallLayer_ >= bb.span()[normal_])
    {
        FatalIOErrorInFunction(dict)
            << "keyword wallLayer is " << wallLayer_ << "; allowed: "
            << "0 <= wallLayer < half the channel height "
            << bb.span()[normal_]/2 << exit(FatalIOError);
    }
    // A Lees-Edwards box: the images across its sheared faces (gradient
    // y, flow x) and its imposed shear rate
    const scalar leesEdwardsRate = fdm::leesEdwardsShearRate(mesh_);
    if (leesEdwardsRate != 0 && (normal_ != vector::Y || flow_ != vector::X))
    {
        FatalIOErrorInFunction(dict)
            << "keywords normal and flow are " << "xyz"[normal_] << " and "
            << "xyz"[flow_] << "; a Lees-Edwards box (0/U) is sheared along"
            << " x with its gradient along y: allowed normal y, flow x"
            << exit(FatalIOError);
    }
    averages_.reset
    (
        new fdm::channelAverages
        (
            bb.min(), bb.span(), normal_, flow_, bins_, leesEdwardsRate
        )
    );

    const IOdictionary transport
    (
        IOobject
        (
            "transportProperties",
            time_.constant(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    eta_ = transport.get<scalar>("rho")*transport.get<scalar>("nu");
    return true;
}


bool Foam::functionObjects::suspensionStress::execute()
{
    fdm::particleSample s;
    if (!Pstream::master() || !readSample(s))
    {
        return true;
    }
    const fdm::channelAverages& avg = averages_();
    const auto all = avg.averages(s, 0);
    const auto core = avg.averages(s, wallLayer_);

    auto relativeViscosity = [&](const fdm::channelAverages::region& r)
    {
        return 1 + avg.shear(r.hydrodynamic + r.contact)/(eta_*r.shearRate);
    };
    const symmTensor particle = core.hydrodynamic + core.contact;
    const scalar Sxy = eta_*core.shearRate + avg.shear(particle);

    OFstream& os = file();
    writeCurrentTime(os);
    os  << token::TAB << all.volumeFraction
        << token::TAB << core.volumeFraction
        << token::TAB << core.nParticles
        << token::TAB << all.shearRate
        << token::TAB << core.shearRate
        << token::TAB << relativeViscosity(all)
        << token::TAB << relativeViscosity(core)
        << token::TAB << avg.shear(core.contact)/Sxy
        << token::TAB << avg.firstDifference(particle)/Sxy
        << token::TAB << avg.secondDifference(particle)/Sxy;
    writeRow(os, core.hydrodynamic);
    writeRow(os, core.contact);
    os  << endl;

    writeProfiles(avg.binned(s));

    Log << type() << " " << name() << ": phi_core " << core.volumeFraction
        << ", shear rate " << core.shearRate << ", eta_core "
        << relativeViscosity(core) << nl << endl;
    return true;
}


bool Foam::functionObjects::suspensionStress::write()
{
    return true;
}


// ************************************************************************* //
