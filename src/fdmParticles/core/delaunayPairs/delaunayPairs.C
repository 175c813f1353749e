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
// Hidden points (none without large overlaps) need not be remembered
typedef CGAL::Regular_triangulation_cell_base_3
<
    Kernel,
    CGAL::Triangulation_cell_base_3<Kernel>,
    CGAL::Discard_hidden_points
> Cell;
typedef CGAL::Triangulation_data_structure_3<Vertex, Cell> DataStructure;
typedef CGAL::Regular_triangulation_3<Kernel, DataStructure> Triangulation;
typedef Kernel::Weighted_point_3 WeightedPoint;
typedef std::vector<std::pair<WeightedPoint, label>> pointList;


//- Whether x lies within margin of the box along every direction
bool inWindow(const fdm::periodicBox& box, const point& x, const scalar margin)
{
    for (direction d = 0; d < 3; ++d)
    {
        if
        (
            x[d] < box.min()[d] - margin
         || x[d] >= box.min()[d] + box.span()[d] + margin
        )
        {
            return false;
        }
    }
    return true;
}


//- Append the periodic images of the centres that lie within outer but
//  not within inner of the box faces to points, their particles to
//  source.  The image ny periods up in y sits +ny s along x (Lees-Edwards);
//  nx reaches -2..2 so that the shifted images still cover x.
void addImages
(
    const fdm::periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii,
    const scalar inner,
    const scalar outer,
    pointList& points,
    std::vector<label>& source
)
{
    const vector& L = box.span();
    forAll(positions, i)
    {
        for (label nz = -1; nz <= 1; ++nz)
        for (label ny = -1; ny <= 1; ++ny)
        for (label nx = -2; nx <= 2; ++nx)
        {
            const point x
            (
                positions[i].x() + nx*L.x() + ny*box.shearOffset(),
                positions[i].y() + ny*L.y(),
                positions[i].z() + nz*L.z()
            );
            if ((nx || ny || nz) && inWindow(box, x, outer)
             && !inWindow(box, x, inner))
            {
                points.emplace_back
                (
                    WeightedPoint
                    (
                        Kernel::Point_3(x.x(), x.y(), x.z()),
                        sqr(radii[i])
                    ),
                    label(source.size())
                );
                source.push_back(i);
            }
        }
    }
}


//- Distance from x to the outer boundary of the box widened by margin
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


//- The edges (particle pairs) of the tetrahedra with a vertex among the
//  first n points, when each of these tetrahedra is regular with respect
//  to all images, also those beyond the margin: a point q outside the
//  widened box has power |c - q|^2 - w_q >= clearance^2 - wMax at the
//  orthogonal centre c, so clearance^2 > R^2 + wMax suffices.  False
//  (edges incomplete) when a tetrahedron fails.
bool collectEdges
(
    const fdm::periodicBox& box,
    const Triangulation& rt,
    const label n,
    const std::vector<label>& source,
    const scalar margin,
    const scalar wMax,
    std::vector<std::pair<label, label>>& edges
)
{
    edges.clear();
    for (auto c = rt.all_cells_begin(); c != rt.all_cells_end(); ++c)
    {
        FixedList<label, 4> v(-1);
        bool hasCentre = false;
        for (int k = 0; k < 4; ++k)
        {
            if (!rt.is_infinite(c->vertex(k)))
            {
                v[k] = c->vertex(k)->info();
                hasCentre = hasCentre || v[k] < n;
            }
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
        for (int a = 0; a < 4; ++a)
        {
            for (int b = a + 1; b < 4; ++b)
            {
                if (v[a] < n || v[b] < n)
                {
                    const label i = source[v[a]];
                    const label j = source[v[b]];
                    edges.emplace_back(min(i, j), max(i, j));
                }
            }
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

    // The centres, then images in widening shells until the check passes;
    // a wider margin adds its shell to the triangulation
    pointList points;
    std::vector<label> source;
    forAll(positions, i)
    {
        const point& x = positions[i];
        points.emplace_back
        (
            WeightedPoint(Kernel::Point_3(x.x(), x.y(), x.z()), sqr(radii[i])),
            i
        );
        source.push_back(i);
    }
    // The orthogonal spheres of a dense packing's tetrahedra are about a
    // radius wide: start from a_max plus the mean spacing, grow by a
    // quarter while the check fails
    scalar margin = min(rMax + spacing, halfPeriod);
    addImages(box, positions, radii, 0, margin, points, source);
    Triangulation rt(points.begin(), points.end());

    std::vector<std::pair<label, label>> edges;
    while (!collectEdges(box, rt, n, source, margin, sqr(rMax), edges))
    {
        if (margin >= halfPeriod)
        {
            FatalErrorInFunction
                << "The periodic images within half a period (" << halfPeriod
                << ") of the faces do not define the Delaunay"
                << " triangulation of " << n << " spheres in the cell " << L
                << ": too few or too sparse particles" << abort(FatalError);
        }
        const scalar inner = margin;
        margin = min(1.25*margin, halfPeriod);
        points.clear();
        addImages(box, positions, radii, inner, margin, points, source);
        rt.insert(points.begin(), points.end());
    }

    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    pairs.setCapacity(edges.size());
    for (const auto& e : edges)
    {
        if (e.first == e.second)
        {
            FatalErrorInFunction
                << "Particle " << e.first << " neighbours its own periodic"
                << " image: the cell " << L << " is too small for"
                << " Delaunay neighbours" << abort(FatalError);
        }
        pairs.append(labelPair(e.first, e.second));
    }

    label nVisible = 0;
    for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v)
    {
        nVisible += (v->info() < n);
    }
    return {label(source.size()), margin, n - nVisible};
}


// ************************************************************************* //
