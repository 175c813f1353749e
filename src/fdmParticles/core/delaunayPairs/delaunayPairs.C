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


//- The domain the triangulation describes, per direction: the box along
//  its periodic directions; along a walled one the slab between the
//  planes tangent to the outermost spheres, whose mirror images stand in
//  for the wall
struct domainBounds
{
    FixedList<bool, 3> periodic;
    point lo;
    point hi;
};


//- The domain of the spheres in box
domainBounds boundsOf
(
    const fdm::periodicBox& box,
    const UList<point>& positions,
    const UList<scalar>& radii
)
{
    domainBounds b{box.periodic(), box.min(), box.min() + box.span()};
    for (direction d = 0; d < 3; ++d)
    {
        if (!b.periodic[d])
        {
            b.lo[d] = GREAT;
            b.hi[d] = -GREAT;
            forAll(positions, i)
            {
                b.lo[d] = min(b.lo[d], positions[i][d] - radii[i]);
                b.hi[d] = max(b.hi[d], positions[i][d] + radii[i]);
            }
        }
    }
    return b;
}


//- Whether x lies within margin of the domain along every direction
bool inWindow(const domainBounds& b, const point& x, const scalar margin)
{
    for (direction d = 0; d < 3; ++d)
    {
        if (x[d] < b.lo[d] - margin || x[d] >= b.hi[d] + margin)
        {
            return false;
        }
    }
    return true;
}


//- Coordinate d of the image n of x: n periods along a periodic direction,
//  along a walled one the mirror image in the lower (n = -1) or upper
//  (n = 1) plane
scalar imageCoordinate
(
    const domainBounds& b,
    const direction d,
    const scalar x,
    const label n
)
{
    if (b.periodic[d])
    {
        return x + n*(b.hi[d] - b.lo[d]);
    }
    return n < 0 ? 2*b.lo[d] - x : n > 0 ? 2*b.hi[d] - x : x;
}


//- Append the images of the centres that lie within outer but not within
//  inner of the domain to points, their particles to source and whether
//  they are mirror images to mirrored.  The periodic image ny periods up
//  in y sits +ny s along x (Lees-Edwards); nx reaches -2..2 so that the
//  shifted images still cover x.
void addImages
(
    const fdm::periodicBox& box,
    const domainBounds& b,
    const UList<point>& positions,
    const UList<scalar>& radii,
    const scalar inner,
    const scalar outer,
    pointList& points,
    std::vector<label>& source,
    std::vector<bool>& mirrored
)
{
    const bool leesEdwards = b.periodic[0] && b.periodic[1];
    const label nxMax = leesEdwards ? 2 : 1;
    forAll(positions, i)
    {
        for (label nz = -1; nz <= 1; ++nz)
        for (label ny = -1; ny <= 1; ++ny)
        for (label nx = -nxMax; nx <= nxMax; ++nx)
        {
            const point& p = positions[i];
            const point x
            (
                imageCoordinate(b, 0, p.x(), nx)
              + (leesEdwards ? ny*box.shearOffset() : 0),
                imageCoordinate(b, 1, p.y(), ny),
                imageCoordinate(b, 2, p.z(), nz)
            );
            if ((nx || ny || nz) && inWindow(b, x, outer)
             && !inWindow(b, x, inner))
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
                mirrored.push_back
                (
                    (nx && !b.periodic[0]) || (ny && !b.periodic[1])
                 || (nz && !b.periodic[2])
                );
            }
        }
    }
}


//- Distance from x to the outer boundary of the domain widened by margin
scalar clearance
(
    const domainBounds& b,
    const Kernel::Point_3& x,
    const scalar margin
)
{
    scalar c = GREAT;
    for (direction d = 0; d < 3; ++d)
    {
        c = min(c, min(x[d] - (b.lo[d] - margin), b.hi[d] + margin - x[d]));
    }
    return c;
}


//- The edges (particle pairs) of the tetrahedra with a vertex among the
//  first n points, mirror images excepted (their faces lie beyond the
//  walls), when each of these tetrahedra is regular with respect to all
//  images, also those beyond the margin: a point q outside the widened
//  domain has power |c - q|^2 - w_q >= clearance^2 - wMax at the
//  orthogonal centre c, so clearance^2 > R^2 + wMax suffices.  False
//  (edges incomplete) when a tetrahedron fails.
bool collectEdges
(
    const domainBounds& b,
    const Triangulation& rt,
    const label n,
    const std::vector<label>& source,
    const std::vector<bool>& mirrored,
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
        const scalar gap = clearance(b, centre, margin);
        if (gap <= 0 || sqr(gap) <= R2 + wMax)
        {
            return false;
        }
        for (int k = 0; k < 4; ++k)
        {
            for (int l = k + 1; l < 4; ++l)
            {
                if
                (
                    (v[k] < n || v[l] < n)
                 && !mirrored[v[k]] && !mirrored[v[l]]
                )
                {
                    const label i = source[v[k]];
                    const label j = source[v[l]];
                    edges.emplace_back(min(i, j), max(i, j));
                }
            }
        }
    }
    return true;
}


//- The distinct edges as pairs; FatalError on a sphere neighbouring its
//  own periodic image
void toPairs
(
    std::vector<std::pair<label, label>>& edges,
    const vector& L,
    DynamicList<labelPair>& pairs
)
{
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
    scalar rMax = 0;
    forAll(radii, i)
    {
        rMax = max(rMax, radii[i]);
    }
    const domainBounds b(boundsOf(box, positions, radii));
    const vector L(b.hi - b.lo);
    // Images beyond half a period would meet their own centre's; a mirror
    // image of a mirror image lies at least the slab's width outside
    scalar reach = GREAT;
    for (direction d = 0; d < 3; ++d)
    {
        reach = min(reach, b.periodic[d] ? 0.5*L[d] : L[d]);
    }
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
    std::vector<bool> mirrored(n, false);
    // The orthogonal spheres of a dense packing's tetrahedra are about a
    // radius wide: start from a_max plus the mean spacing, grow by a
    // quarter while the check fails
    scalar margin = min(rMax + spacing, reach);
    addImages(box, b, positions, radii, 0, margin, points, source, mirrored);
    Triangulation rt(points.begin(), points.end());

    std::vector<std::pair<label, label>> edges;
    while
    (
        !collectEdges(b, rt, n, source, mirrored, margin, sqr(rMax), edges)
    )
    {
        if (margin >= reach)
        {
            FatalErrorInFunction
                << "The images within " << reach << " of the faces (half a"
                << " period, or a wall's mirror) do not define the Delaunay"
                << " triangulation of " << n << " spheres in the cell " << L
                << ": too few or too sparse particles" << abort(FatalError);
        }
        const scalar inner = margin;
        margin = min(1.25*margin, reach);
        points.clear();
        addImages
        (
            box, b, positions, radii, inner, margin, points, source, mirrored
        );
        rt.insert(points.begin(), points.end());
    }

    toPairs(edges, L, pairs);

    label nVisible = 0;
    for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v)
    {
        nVisible += (v->info() < n);
    }
    return {label(source.size()), margin, n - nVisible};
}


// ************************************************************************* //
