/*---------------------------------------------------------------------------*\
  fdmSuspension: particle-resolved simulation of dense suspensions
  License: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include "delaunayPairs.H"
#include "error.H"
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Regular_triangulation_vertex_base_3<Kernel> VertexBase;
typedef CGAL::Triangulation_vertex_base_with_info_3<label, Kernel, VertexBase>
    Vertex;
typedef CGAL::Regular_triangulation_cell_base_3<Kernel> Cell;
typedef CGAL::Triangulation_data_structure_3<Vertex, Cell> DataStructure;
typedef CGAL::Regular_triangulation_3<Kernel, DataStructure> Triangulation;
typedef Kernel::Weighted_point_3 WeightedPoint;


//- Centres and their periodic images within margin of the box faces:
//  source[k] is the particle of point k; the first size() are the centres
class periodicPoints
{
public:

    std::vector<std::pair<WeightedPoint, label>> points;
    std::vector<label> source;

    periodicPoints
    (
        const fdm::periodicBox& box,
        const UList<point>& positions,
        const UList<scalar>& radii,
        const scalar margin
    )
    {
        const vector& L = box.span();
        forAll(positions, i)
        {
            add(positions[i], radii[i], i);
        }
        // The image ny periods up in y sits +ny s along x (Lees-Edwards);
        // nx reaches -2..2 so that the shifted images still cover x
        forAll(positions, i)
        {
            for (label nz = -1; nz <= 1; ++nz)
            for (label ny = -1; ny <= 1; ++ny)
            for (label nx = -2; nx <= 2; ++nx)
            {
                if (nx == 0 && ny == 0 && nz == 0)
                {
                    continue;
                }
                const point x
                (
                    positions[i].x() + nx*L.x() + ny*box.shearOffset(),
                    positions[i].y() + ny*L.y(),
                    positions[i].z() + nz*L.z()
                );
                if (inWindow(box, x, margin))
                {
                    add(x, radii[i], i);
                }
            }
        }
    }

    static bool inWindow
    (
        const fdm::periodicBox& box,
        const point& x,
        const scalar margin
    )
    {
        for (direction d = 0; d < 3; ++d)
        {
            const scalar lo = box.min()[d] - margin;
            const scalar hi = box.min()[d] + box.span()[d] + margin;
            if (x[d] < lo || x[d] >= hi)
            {
                return false;
            }
        }
        return true;
    }

private:

    void add(const point& x, const scalar r, const label i)
    {
        points.emplace_back
        (
            WeightedPoint(Kernel::Point_3(x.x(), x.y(), x.z()), r*r),
            label(source.size())
        );
        source.push_back(i);
    }
};


//- Distance from x to the outer boundary of the window box + margin
scalar clearance
(
    const fdm::periodicBox& box,
    const Kernel::Point_3& x,
    const scalar margin
)
{
    scalar c = GREAT;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar lo = box.min()[d] - margin;
        const scalar hi = box.min()[d] + box.span()[d] + margin;
        c = min(c, min(x[d] - lo, hi - x[d]));
    }
    return c;
}


//- Whether every tetrahedron with a vertex among the first n points is
//  regular with respect to all images, also those beyond the margin: a
//  point q outside the window has power |c - q|^2 - w_q >= clearance^2 -
//  wMax at the orthogonal centre c, so clearance^2 > R^2 + wMax suffices
bool marginSuffices
(
    const fdm::periodicBox& box,
    const Triangulation& rt,
    const label n,
    const scalar margin,
    const scalar wMax
)
{
    for
    (
        auto c = rt.all_cells_begin();
        c != rt.all_cells_end();
        ++c
    )
    {
        bool hasCentre = false;
        for (int v = 0; v < 4; ++v)
        {
            hasCentre = hasCentre
             || (!rt.is_infinite(c->vertex(v)) && c->vertex(v)->info() < n);
        }
        if (!hasCentre)
        {
            continue;
        }
        if (rt.is_infinite(c))
        {
            return false;
        }
        const Kernel::Point_3 centre = rt.dual(c);
        const WeightedPoint& p = c->vertex(0)->point();
        const scalar R2 =
            CGAL::squared_distance(centre, p.point()) - p.weight();
        const scalar gap = clearance(box, centre, margin);
        if (gap <= 0 || sqr(gap) <= R2 + wMax)
        {
            return false;
        }
    }
    return true;
}

} // namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::fdm::delaunayStatistics Foam::fdm::findDelaunayPairs
(
    const periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii,
    DynamicList<labelPair>& pairs
)
{
    pairs.clear();
    const label n = positions.size();
    if (!(box.periodic(0) && box.periodic(1) && box.periodic(2)))
    {
        FatalErrorInFunction
            << "Delaunay neighbours are defined here for a cell periodic in"
            << " x, y and z (walls would need the hull's edges removed)"
            << abort(FatalError);
    }
    scalar rMax = 0;
    forAll(radii, i)
    {
        rMax = max(rMax, radii[i]);
    }
    const vector& L = box.span();
    const scalar halfPeriod = 0.5*min(L.x(), min(L.y(), L.z()));
    const scalar spacing = std::cbrt(L.x()*L.y()*L.z()/max(n, label(1)));
    // Enough for dense packings at the first try (a retry triangulates
    // again): the orthogonal spheres of the tetrahedra are about a wide
    scalar margin = min(1.5*(rMax + spacing), halfPeriod);

    while (true)
    {
        const periodicPoints set(box, positions, radii, margin);
        const Triangulation rt(set.points.begin(), set.points.end());

        if (marginSuffices(box, rt, n, margin, sqr(rMax)))
        {
            std::vector<std::pair<label, label>> edges;
            for (auto e = rt.finite_edges_begin(); e != rt.finite_edges_end(); ++e)
            {
                const label a = e->first->vertex(e->second)->info();
                const label b = e->first->vertex(e->third)->info();
                if (a >= n && b >= n)
                {
                    continue;
                }
                const label i = set.source[a];
                const label j = set.source[b];
                if (i == j)
                {
                    FatalErrorInFunction
                        << "Particle " << i << " neighbours its own periodic"
                        << " image: the cell " << L << " is too small for"
                        << " Delaunay neighbours" << abort(FatalError);
                }
                edges.emplace_back(min(i, j), max(i, j));
            }
            std::sort(edges.begin(), edges.end());
            edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
            pairs.setCapacity(edges.size());
            for (const auto& e : edges)
            {
                pairs.append(labelPair(e.first, e.second));
            }

            label nVisible = 0;
            for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v)
            {
                nVisible += (v->info() < n);
            }
            return {label(set.points.size()), margin, n - nVisible};
        }
        if (margin >= halfPeriod)
        {
            FatalErrorInFunction
                << "The periodic images within half a period (" << halfPeriod
                << ") of the faces do not define the Delaunay"
                << " triangulation of " << n << " spheres in the cell " << L
                << ": too few or too sparse particles" << abort(FatalError);
        }
        margin = min(1.5*margin, halfPeriod);
    }
}


// ************************************************************************* //
