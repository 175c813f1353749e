// Unit test of particleVTKWriter: the PolyData files (ASCII, read back as
// text) hold the points, cells and fields given, the series lists every
// written time, and a run starting at t0 drops the entries at or after t0.

#include "particleVTKWriter.H"
#include "OSspecific.H"
#include "IFstream.H"
#include <gtest/gtest.h>
#include <fstream>
#include <sstream>
#include <algorithm>

using namespace Foam;

namespace
{

std::string readText(const fileName& f)
{
    std::ifstream is(f);
    std::stringstream ss;
    ss << is.rdbuf();
    // Attributes in double quotes, whichever the formatter uses
    std::string text = ss.str();
    std::replace(text.begin(), text.end(), '\'', '"');
    return text;
}

//- The text between the DataArray named name and its end tag
std::string dataArray(const std::string& text, const std::string& name)
{
    const auto tag = text.find("Name=\"" + name + "\"");
    if (tag == std::string::npos)
    {
        return "";
    }
    const auto start = text.find('>', tag) + 1;
    return text.substr(start, text.find("</DataArray>", start) - start);
}

std::vector<double> numbers(const std::string& text)
{
    std::istringstream is(text);
    std::vector<double> v;
    double x;
    while (is >> x)
    {
        v.push_back(x);
    }
    return v;
}

void writeStep
(
    fdm::particleVTKWriter& w,
    const scalar t,
    const List<point>& x,
    const UList<fdm::contactLink>& network
)
{
    auto f = w.particles(name(t), t, x);
    f.write("id", labelList(identity(x.size())));
    f.write("radius", scalarList(x.size(), 1.5));
    f.write("velocity", List<vector>(x.size(), vector(1, 2, 3)));
    f.close();
    w.contacts(name(t), t, x, network);
}

} // namespace


TEST(particleVTKWriter, writesParticlesContactsAndSeries)
{
    const fileName dir = fileName("particleVTKWriterTest")/name(pid());
    rmDir(dir);

    const List<point> x({point(0, 0, 0), point(2.5, 0, 0), point(0, 3, 0)});
    fdm::contactNetwork network;
    network.append
    (
        fdm::contactLink::split(0, 1, vector(2.5, 0, 0), vector(-4, 1, 0))
    );
    network.append
    (
        fdm::contactLink::split(2, -1, vector(0, 1, 0), vector(0, -2, 0))
    );

    {
        fdm::particleVTKWriter w(dir, 0, true);
        writeStep(w, 0, x, network);
        writeStep(w, 0.5, x, network);
    }

    const std::string p = readText(dir/"particles_0.5.vtp");
    EXPECT_NE(p.find("NumberOfPoints=\"3\""), std::string::npos);
    EXPECT_NE(p.find("NumberOfVerts=\"3\""), std::string::npos);
    EXPECT_EQ(numbers(dataArray(p, "TimeValue")), std::vector<double>({0.5}));
    EXPECT_EQ(numbers(dataArray(p, "id")), std::vector<double>({0, 1, 2}));
    EXPECT_EQ(numbers(dataArray(p, "offsets")), std::vector<double>({1, 2, 3}));
    EXPECT_EQ(numbers(dataArray(p, "velocity")).size(), 9u);

    const std::string c = readText(dir/"contacts_0.5.vtp");
    EXPECT_NE(c.find("NumberOfLines=\"2\""), std::string::npos);
    EXPECT_EQ(numbers(dataArray(c, "offsets")), std::vector<double>({2, 4}));
    EXPECT_EQ(numbers(dataArray(c, "j")), std::vector<double>({1, -1}));
    EXPECT_EQ
    (
        numbers(dataArray(c, "normalForce")), std::vector<double>({-4, -2})
    );
    // Line 0 from the centre of 0 to that of 1, line 1 from 2 to the wall
    EXPECT_EQ
    (
        numbers(dataArray(c, "Points")),
        std::vector<double>({0, 0, 0, 2.5, 0, 0, 0, 3, 0, 0, 4, 0})
    );

    vtk::seriesWriter series;
    EXPECT_EQ(series.load(dir/"particles.vtp", true), 2);
    EXPECT_EQ(series.load(dir/"contacts.vtp", true), 2);

    // A run restarted at 0.5 lists 0 and its own 0.5 and 1 again
    {
        fdm::particleVTKWriter w(dir, 0.5, true);
        writeStep(w, 0.5, x, network);
        writeStep(w, 1, x, network);
    }
    EXPECT_EQ(series.load(dir/"particles.vtp", true), 3);
    // ... and one restarted at 0.25 only 0 until it writes
    {
        fdm::particleVTKWriter w(dir, 0.25, true);
        writeStep(w, 0.25, x, network);
    }
    EXPECT_EQ(series.load(dir/"particles.vtp", true), 2);
    EXPECT_FALSE(isFile(dir/"particles_0.25.vtp.tmp"));

    rmDir(fileName("particleVTKWriterTest"));
}
