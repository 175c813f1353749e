// Unit tests for Foam::fdm::resistanceTable (tabulated SG functions,
// thesis 1 eq 3.6, cut-offs of section 3.2, floor of B.1/B.2)

#include "resistanceTable.H"
#include "IStringStream.H"
#include "OFstream.H"
#include "unitTestHelpers.H"
#include "OSspecific.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <vector>
#include <sstream>
#include <string>

using namespace Foam;

namespace
{

typedef fdm::resistanceTable table;

const char* pairNames[] =
    {"XA21", "YA21", "YB21", "XC21", "YC11",
     "XG11", "YG11", "YH21", "XP12", "XP21"};

//- A pair table: gap (0 0.01 0.1 0.5); function k has singular
//  (k+1, 0.5 k, -0.1 k) and remainder (k, k+1, k+3, k+2).  Overrides:
//  XA21 cutoff 0.05, YB21 cutoff 1.
std::string pairTable
(
    const std::string& gap = "(0 0.01 0.1 0.5)",
    const std::string& skip = "",
    const std::string& xaRemainder = "(0 1 3 2)",
    const std::string& gapVariable = "xi"
)
{
    std::ostringstream os;
    os  << "kind pair;\nlambda 1.4;\ngapVariable " << gapVariable << ";\n"
        << "gap " << gap << ";\nfunctions\n{\n";
    label k = 0;
    for (const char* n : pairNames)
    {
        if (skip != n)
        {
            os  << "    " << n << " { singular (" << k + 1 << ' ' << 0.5*k
                << ' ' << -0.1*k << "); remainder ";
            if (k == 0)
            {
                os  << xaRemainder;
            }
            else
            {
                os  << '(' << k << ' ' << k + 1 << ' ' << k + 3 << ' '
                    << k + 2 << ')';
            }
            os  << ';';
            if (k == 0) os << " cutoff 0.05;";
            if (k == 2) os << " cutoff 1;";
            os  << " }\n";
        }
        ++k;
    }
    os  << "    comment { singular (0 0 0); remainder (0); }\n}\n";
    return os.str();
}

table parse(const std::string& text, const scalar xMin = table::defaultXMin)
{
    IStringStream is(text);
    const dictionary dict(is);
    return table(dict, xMin);
}

//- Reference evaluation of function k of pairTable at x (a1 = 1)
scalar reference(const label k, const scalar x)
{
    const scalar L = std::log(1/x);
    const scalar g1 = k + 1, g2 = 0.5*k, g3 = -0.1*k;
    const scalar gap[4] = {0, 0.01, 0.1, 0.5};
    const scalar rem[4] = {scalar(k), scalar(k + 1), scalar(k + 3),
                           scalar(k + 2)};
    label i = 1;
    while (gap[i] < x) ++i;
    const scalar w = (x - gap[i-1])/(gap[i] - gap[i-1]);
    return g1/x + g2*L + g3*x*L + (1 - w)*rem[i-1] + w*rem[i];
}

//- Message of the error thrown by parsing text
std::string parseError(const std::string& text)
{
    try
    {
        parse(text);
    }
    catch (const Foam::error& e)
    {
        return e.message();
    }
    return "no error";
}

} // namespace


TEST(resistanceTable, readsPairTableAndInterpolates)
{
    const table t = parse(pairTable());
    EXPECT_TRUE(t.isPair());
    EXPECT_EQ(t.lambda(), 1.4);
    EXPECT_EQ(t.gap().size(), 4);
    EXPECT_EQ(t.xMin(), 1e-5);

    // Singular terms plus linear interpolation of the remainder, a1 = 1
    for (const scalar x : {2e-5, 1e-3, 0.01, 0.037, 0.1, 0.14})
    {
        EXPECT_NEAR(t.value("YA21", x, 1), reference(1, x),
                    1e-13*mag(reference(1, x)));
        EXPECT_NEAR(t.value("XC21", x, 1), reference(3, x),
                    1e-13*mag(reference(3, x)));
    }
    // Interpolation alone: singular part subtracted at a mid point
    {
        const scalar x = 0.055, L = std::log(1/x);
        const scalar sing = 4/x + 1.5*L - 0.3*x*L;
        EXPECT_NEAR(t.value("XC21", x, 1) - sing, 3 + 1 + 2*0.5, 1e-12);
    }

    // Scaling with a1: A ~ a1, B G P ~ a1^2, C H ~ a1^3
    const scalar x = 0.02;
    EXPECT_NEAR(t.value("YA21", x, 2), 2*t.value("YA21", x, 1), 1e-12);
    EXPECT_NEAR(t.value("YB21", x, 2), 4*t.value("YB21", x, 1), 1e-12);
    EXPECT_NEAR(t.value("XG11", x, 2), 4*t.value("XG11", x, 1), 1e-12);
    EXPECT_NEAR(t.value("XP21", x, 2), 4*t.value("XP21", x, 1), 1e-12);
    EXPECT_NEAR(t.value("YC11", x, 2), 8*t.value("YC11", x, 1), 1e-11);
    EXPECT_NEAR(t.value("YH21", x, 2), 8*t.value("YH21", x, 1), 1e-11);

    // All base functions at once
    const fdm::pairBaseFunctions f = t.pairFunctions(0.02, 1.5);
    EXPECT_EQ(f.XA21, t.value("XA21", 0.02, 1.5));
    EXPECT_EQ(f.YA21, t.value("YA21", 0.02, 1.5));
    EXPECT_EQ(f.YB21, t.value("YB21", 0.02, 1.5));
    EXPECT_EQ(f.XC21, t.value("XC21", 0.02, 1.5));
    EXPECT_EQ(f.YC11, t.value("YC11", 0.02, 1.5));
    EXPECT_EQ(f.XG11, t.value("XG11", 0.02, 1.5));
    EXPECT_EQ(f.YG11, t.value("YG11", 0.02, 1.5));
    EXPECT_EQ(f.YH21, t.value("YH21", 0.02, 1.5));
    EXPECT_EQ(f.XP12, t.value("XP12", 0.02, 1.5));
    EXPECT_EQ(f.XP21, t.value("XP21", 0.02, 1.5));
    EXPECT_NEAR(f.XP12, 2.25*reference(8, 0.02), 1e-12*mag(f.XP12));

    // A pair table gives no wall functions
    FatalError.throwExceptions();
    EXPECT_THROW(t.wallFunctions(0.01, 1), Foam::error);
    FatalError.dontThrowExceptions();
}


TEST(resistanceTable, cutoffsAndClamping)
{
    const table t = parse(pairTable());

    // Defaults: X 0.3, Y 0.15; explicit XA21 0.05, YB21 1
    EXPECT_EQ(t.cutoff("XA21"), 0.05);
    EXPECT_EQ(t.cutoff("YB21"), 1);
    EXPECT_EQ(t.cutoff("XC21"), 0.3);
    EXPECT_EQ(t.cutoff("YA21"), 0.15);
    EXPECT_EQ(t.value("XA21", 0.06, 1), 0);
    EXPECT_NE(t.value("XA21", 0.04, 1), 0);
    EXPECT_EQ(t.value("YA21", 0.16, 1), 0);
    EXPECT_NE(t.value("YA21", 0.14, 1), 0);
    EXPECT_EQ(t.value("XC21", 0.31, 1), 0);
    EXPECT_NE(t.value("XC21", 0.29, 1), 0);

    // Above gap.last() (inside a cut-off beyond it) the value is frozen
    EXPECT_EQ(t.value("YB21", 0.8, 1), t.value("YB21", 0.5, 1));
    EXPECT_NEAR(t.value("YB21", 0.5, 1), reference(2, 0.5), 1e-13);

    // Below the floor the value is frozen at xMin (default 1e-5)
    EXPECT_EQ(t.value("YA21", 1e-9, 1), t.value("YA21", 1e-5, 1));
    EXPECT_NE(t.value("YA21", 2e-5, 1), t.value("YA21", 1e-5, 1));

    // A settable floor (e.g. the roughness gap of the contact model)
    const table tr = parse(pairTable(), 1e-3);
    EXPECT_EQ(tr.xMin(), 1e-3);
    EXPECT_EQ(tr.value("XP12", 1e-4, 1), tr.value("XP12", 1e-3, 1));
    EXPECT_NEAR(tr.value("XP12", 1e-3, 1), reference(8, 1e-3), 1e-9);
}


TEST(resistanceTable, readsWallTableFromFile)
{
    const fileName dir("resistanceTableTest.tmp");
    mkDir(dir);
    const fileName file(dir/"wall_a1");
    {
        OFstream os(file);
        os  << "kind wall;\ngapVariable epsilon;\ngap (0 0.1 0.3);\n"
            << "functions\n{\n";
        for (const char* n : {"XA", "YA", "YB", "XC", "YC", "XG", "XP"})
        {
            os  << "    " << n << " { singular (1 2 3); remainder (1 2 4); }\n";
        }
        os  << "}\n";
    }

    const table t = table::read(file);
    EXPECT_FALSE(t.isPair());
    const scalar eps = 0.05, L = std::log(1/eps);
    const scalar f1 = 1/eps + 2*L + 3*eps*L + 1.5;
    const fdm::wallBaseFunctions f = t.wallFunctions(eps, 2);
    EXPECT_NEAR(f.XA, 2*f1, 1e-12);
    EXPECT_NEAR(f.YA, 2*f1, 1e-12);
    EXPECT_NEAR(f.YB, 4*f1, 1e-12);
    EXPECT_NEAR(f.XC, 8*f1, 1e-11);
    EXPECT_NEAR(f.YC, 8*f1, 1e-11);
    EXPECT_NEAR(f.XG, 4*f1, 1e-12);
    EXPECT_NEAR(f.XP, 4*f1, 1e-12);
    // Wall cut-offs: X 0.3, Y 0.15
    EXPECT_EQ(t.wallFunctions(0.2, 1).YA, 0);
    EXPECT_NE(t.wallFunctions(0.2, 1).XA, 0);

    // A wall table gives no pair functions
    FatalError.throwExceptions();
    EXPECT_THROW(t.pairFunctions(0.01, 1), Foam::error);
    EXPECT_THROW(t.value("XA21", 0.01, 1), Foam::error);
    FatalError.dontThrowExceptions();

    rmDir(dir);
}


TEST(resistanceTable, rejectsMalformedTables)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // Missing function: the message names it
    EXPECT_NE
    (
        parseError(pairTable("(0 0.01 0.1 0.5)", "YH21")).find("YH21"),
        std::string::npos
    );
    // Remainder length differs from gap
    {
        const std::string msg =
            parseError(pairTable("(0 0.01 0.1 0.5)", "", "(0 1 3)"));
        EXPECT_NE(msg.find("XA21"), std::string::npos) << msg;
        EXPECT_NE(msg.find("remainder"), std::string::npos) << msg;
    }
    // Non-increasing gap
    EXPECT_NE
    (
        parseError(pairTable("(0 0.1 0.1 0.5)")).find("gap"),
        std::string::npos
    );
    EXPECT_NE(parseError(pairTable("(0 0.2 0.1 0.5)")), "no error");
    // Wrong gap variable for the kind
    EXPECT_NE
    (
        parseError(pairTable("(0 0.01 0.1 0.5)", "", "(0 1 3 2)", "epsilon"))
            .find("gapVariable"),
        std::string::npos
    );
    // Missing keyword, wrong singular size, unknown kind
    EXPECT_NE(parseError("kind pair; gapVariable xi; lambda 1;"), "no error");
    {
        std::string text = pairTable();
        const std::string::size_type at = text.find("singular (1 0 -0)");
        ASSERT_NE(at, std::string::npos);
        text.replace(at, 17, "singular (1 0)");
        EXPECT_NE(parseError(text).find("singular"), std::string::npos);
    }
    {
        std::string text = pairTable();
        text.replace(text.find("kind pair"), 9, "kind duo");
        EXPECT_NE(parseError(text).find("kind"), std::string::npos);
    }
    // Nonpositive gap floor
    EXPECT_THROW(parse(pairTable(), 0), Foam::error);

    FatalIOError.dontThrowExceptions();
    FatalError.dontThrowExceptions();
}


namespace
{

// Golden table of the shipped a/5 sub-grid tables as resistanceTable
// evaluates them, rows (table, function, gap, value at a1 = 1); the Python
// twin (fdmResistance.tables.evaluate) is tested on it too
struct goldenRow
{
    std::string table;
    std::string function;
    double gap;
    double value;
};

std::vector<goldenRow> shippedTableRows()
{
    std::vector<goldenRow> rows;
    for (const char* name : {"subGridPair_lambda1", "subGridPair_lambda1.4",
        "subGridWall"})
    {
        const table t = table::read
        (
            unitTest::projectFile(std::string("data/resistance/") + name)
        );
        const wordList& functions =
            t.isPair() ? table::pairFunctionNames : table::wallFunctionNames;
        // On and between grid points, near contact, past cut-offs and the
        // end of the grid
        for (const word& f : functions)
        for (const double x : {1e-6, 3.3e-5, 1e-3, 0.0123, 0.05, 0.149, 0.2,
            0.31, 0.45, 0.7})
        {
            rows.push_back({name, f, x, t.value(f, x, 1)});
        }
    }
    return rows;
}

} // namespace


TEST(resistanceTable, shippedTablesMatchTheGoldenTable)
{
    // FDM_WRITE_GOLDEN=1 fdmUnitTests rewrites the golden table after a
    // deliberate change of the tables or of their evaluation (the Python
    // reader must follow)
    const std::string golden = unitTest::projectFile("tests/golden/resistanceTables.dat");
    const std::vector<goldenRow> rows(shippedTableRows());
    if (unitTest::writingGolden())
    {
        std::ofstream os(golden);
        os.precision(17);
        os  << "# The shipped sub-grid tables (data/resistance) as"
            << " resistanceTable evaluates them,\n# f = g1/x + g2 ln(1/x) +"
            << " g3 x ln(1/x) + remainder(x), zero past the cut-off (a1 = 1)"
            << "\n# written by tests/unit/subGrid/resistanceTableTest.C"
            << " (FDM_WRITE_GOLDEN=1)\n# table function gap value\n";
        for (const goldenRow& r : rows)
        {
            os  << r.table << ' ' << r.function << ' ' << r.gap << ' '
                << r.value << '\n';
        }
    }
    std::ifstream is(golden);
    ASSERT_TRUE(is.good()) << golden;
    std::string line;
    std::size_t i = 0;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#')
        {
            continue;
        }
        std::istringstream ls(line);
        goldenRow g;
        ls >> g.table >> g.function >> g.gap >> g.value;
        ASSERT_LT(i, rows.size());
        EXPECT_EQ(g.table + g.function, rows[i].table + rows[i].function);
        EXPECT_EQ(g.gap, rows[i].gap) << "row " << i;
        EXPECT_NEAR(rows[i].value, g.value, 1e-13*std::abs(g.value))
            << "row " << i << ": " << g.table << ' ' << g.function;
        ++i;
    }
    EXPECT_EQ(i, rows.size());
}
