// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_PLACE_INITIAL_BUBBLES_H
#define CGAL_BUBBLE_MESH_3_PLACE_INITIAL_BUBBLES_H

#include <CGAL/Bubble_mesh_3/Bubble.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/K_means_clustering.h>
#include <CGAL/Bubble_mesh_3/Surface_bubble_sizing_field.h>
#include <CGAL/Bubble_mesh_3/cluster_validity.h>
#include <CGAL/Bubble_mesh_3/internal/placement_parameters.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <CGAL/use.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

What `place_initial_bubbles()` did in one region (see the named parameter
`placement_statistics`).
*/
struct Region_placement_statistics
{
  /// the region
  std::size_t region = 0;
  std::size_t number_of_surface_points = 0;   ///< points clustered
  std::size_t number_of_clusters = 0;         ///< k used
  std::vector<Cluster_validity> cluster_validity; ///< per-k table (empty when k was fixed)
  std::size_t calinski_harabasz_choice = 0;   ///< see `Number_of_clusters_selection`
  /// k the silhouette index prefers
  std::size_t silhouette_choice = 0;
  /// k the elbow of the error curve gives
  std::size_t elbow_choice = 0;
  double cell_edge = 0.;                      ///< edge of the cubic cells (with graded cells: of the smallest)
  std::size_t number_of_cells = 0;            ///< distinct cells tested
  std::size_t rejected_outside = 0;           ///< cell centres outside the region
  std::size_t rejected_near_surface = 0;      ///< centres closer than their radius to a surface
  std::size_t number_of_bubbles = 0;          ///< bubbles placed
  /// time spent clustering
  double clustering_seconds = 0.;
  /// time spent placing bubbles in the cells
  double placement_seconds = 0.;
};

namespace internal {

// The surfaces of one region: its closed boundary (for inside tests) and all
// its triangles, boundary plus surfaces inside it (for clearance).
template <class GeomTraits>
struct Region_surfaces
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Triangle_3 Triangle_3;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef CGAL::Side_of_triangle_mesh<Mesh, GeomTraits> Side_of;
  typedef typename std::vector<Triangle_3>::const_iterator Triangle_iterator;
  typedef CGAL::AABB_triangle_primitive<GeomTraits, Triangle_iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<GeomTraits, Primitive> > Tree;

  typedef typename Side_of::AABB_tree Boundary_tree;

  Mesh boundary;
  std::vector<Triangle_3> triangles;
  std::unique_ptr<Boundary_tree> boundary_tree;
  std::unique_ptr<Side_of> side_of;
  std::unique_ptr<Tree> tree;

  Region_surfaces(const Geological_model_3<GeomTraits>& model, std::size_t r)
  {
    for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    {
      const auto& patch = model.patch(model.patch_of_triangle(t));
      if(patch.positive_region != r && patch.negative_region != r) continue;
      const auto& tri = model.triangle(t);
      triangles.emplace_back(model.point(tri[0]), model.point(tri[1]), model.point(tri[2]));
      if(patch.is_inside_region()) continue;
      // A soup of separate triangles: non-manifold contacts between parts of
      // a region cannot make add_face fail. Orientation does not matter to
      // the parity test; keep it outward anyway.
      const bool flip = (patch.positive_region == r);
      const auto a = boundary.add_vertex(model.point(tri[0]));
      const auto b = boundary.add_vertex(model.point(tri[flip ? 2 : 1]));
      const auto c = boundary.add_vertex(model.point(tri[flip ? 1 : 2]));
      boundary.add_face(a, b, c);
    }
    if(boundary.number_of_faces() > 0)
    {
      // Side_of_triangle_mesh's ray parity is geometric: fed with the tree of
      // the soup it needs no connectivity (its mesh constructor would assert
      // that the soup is closed as a mesh, which it is not).
      boundary_tree.reset(new Boundary_tree(faces(boundary).first, faces(boundary).second, boundary));
      boundary_tree->build(); // built now: the later const queries may run concurrently
      side_of.reset(new Side_of(*boundary_tree));
    }
    if(!triangles.empty())
    {
      tree.reset(new Tree(triangles.begin(), triangles.end()));
      // built now: the later const queries may run concurrently
      tree->build();
      tree->accelerate_distance_queries();
    }
  }

  bool is_inside(const Point_3& p) const
  {
    return side_of && (*side_of)(p) == CGAL::ON_BOUNDED_SIDE;
  }

  double squared_distance(const Point_3& p) const
  {
    return CGAL::to_double(tree->squared_distance(p));
  }

  // a bubble of `radius` at `p` keeps `factor` times its radius from every triangle
  bool has_room(const Point_3& p, double radius, double factor) const
  {
    const double clearance = factor * radius;
    return radius > 0. && squared_distance(p) > clearance * clearance;
  }
};

template <class Function>
void for_each_index(std::size_t begin, std::size_t end, bool parallel, const Function& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for(std::size_t i = range.begin(); i != range.end(); ++i) f(i);
                      });
    return;
  }
#else
  CGAL_USE(parallel);
#endif
  for(std::size_t i = begin; i < end; ++i) f(i);
}

struct Placement_settings
{
  std::size_t fixed_k = 0, k_min = 2, k_max = 10;
  double cell_edge_factor = 1.;
  double clearance_factor = 1.;
  double graded_cell_factor = 0.; // (the paper's lattice unless set)
  bool parallel = true;
};

typedef std::array<long, 3> Cell;

// The bounding boxes of the clusters of a region's surface points; the
// corner of all of them anchors the region's lattice.
struct Cluster_boxes
{
  std::vector<std::array<double, 3> > lo, hi; // per cluster; lo > hi for an empty one
  std::array<double, 3> origin, top;          // the corners of all points

  Cluster_boxes(const std::vector<std::array<double, 3> >& pts, const std::vector<std::size_t>& labels, std::size_t k)
    : lo(k, {{DBL_MAX, DBL_MAX, DBL_MAX}}), hi(k, {{-DBL_MAX, -DBL_MAX, -DBL_MAX}}), origin(pts.front()), top(pts.front())
  {
    for(std::size_t i = 0; i < pts.size(); ++i)
      for(int d = 0; d < 3; ++d)
      {
        lo[labels[i]][d] = (std::min)(lo[labels[i]][d], pts[i][d]);
        hi[labels[i]][d] = (std::max)(hi[labels[i]][d], pts[i][d]);
        origin[d] = (std::min)(origin[d], pts[i][d]);
        top[d] = (std::max)(top[d], pts[i][d]);
      }
  }
  std::size_t size() const { return lo.size(); }
  bool is_empty(std::size_t c) const { return lo[c][0] > hi[c][0]; }
  // does the box [a, b] meet a cluster's box (touching counts)?
  bool meets(const std::array<double, 3>& a, const std::array<double, 3>& b) const
  {
    for(std::size_t c = 0; c < size(); ++c)
      if(lo[c][0] <= b[0] && a[0] <= hi[c][0] && lo[c][1] <= b[1] && a[1] <= hi[c][1] && lo[c][2] <= b[2] &&
         a[2] <= hi[c][2])
        return true;
    return false;
  }
};

// The cells tested by one task (a slab of the lattice, a coarsest graded
// cell) and the bubbles placed in them; merged in task order.
template <class GeomTraits>
struct Placed_cells
{
  std::vector<Bubble<GeomTraits> > bubbles;
  std::size_t cells = 0, outside = 0, near_surface = 0;

  void append_to(std::vector<Bubble<GeomTraits> >& out, Region_placement_statistics& stats) const
  {
    stats.number_of_cells += cells;
    stats.rejected_outside += outside;
    stats.rejected_near_surface += near_surface;
    out.insert(out.end(), bubbles.begin(), bubbles.end());
  }
};

// Steps 3-4 with the paper's lattice of edge h: a cell belongs to the first
// cluster whose box holds it; each cluster's cells go by slabs of constant x.
template <class GeomTraits, class SizingField>
void place_lattice_cells(const Cluster_boxes& boxes, double h, const Region_surfaces<GeomTraits>& surfaces,
                         const SizingField& sizing, std::size_t r, const Placement_settings& set,
                         std::vector<Bubble<GeomTraits> >& out, Region_placement_statistics& stats)
{
  typedef typename GeomTraits::Point_3 Point_3;
  const std::array<double, 3>& origin = boxes.origin;
  // the cells of each box (the same as the cells of its points' extremes: the floor is monotone)
  const std::size_t k = boxes.size();
  std::vector<Cell> lo(k), hi(k);
  for(std::size_t c = 0; c < k; ++c)
    if(!boxes.is_empty(c))
      for(int d = 0; d < 3; ++d)
      {
        lo[c][d] = long(std::floor((boxes.lo[c][d] - origin[d]) / h));
        hi[c][d] = long(std::floor((boxes.hi[c][d] - origin[d]) / h));
      }
  const auto in_box = [&](std::size_t c, long i, long j, long l) {
    return !boxes.is_empty(c) && lo[c][0] <= i && i <= hi[c][0] && lo[c][1] <= j && j <= hi[c][1] && lo[c][2] <= l &&
           l <= hi[c][2];
  };
  for(std::size_t c = 0; c < k; ++c)
  {
    if(boxes.is_empty(c)) continue;
    const std::size_t nx = std::size_t(hi[c][0] - lo[c][0] + 1);
    std::vector<Placed_cells<GeomTraits> > slabs(nx);
    for_each_index(0, nx, set.parallel, [&](std::size_t s) {
      const long i = lo[c][0] + long(s);
      Placed_cells<GeomTraits>& slab = slabs[s];
      for(long j = lo[c][1]; j <= hi[c][1]; ++j)
        for(long l = lo[c][2]; l <= hi[c][2]; ++l)
        {
          bool earlier = false;
          for(std::size_t e = 0; e < c && !earlier; ++e) earlier = in_box(e, i, j, l);
          if(earlier) continue;
          ++slab.cells;
          const Point_3 p(origin[0] + (double(i) + 0.5) * h, origin[1] + (double(j) + 0.5) * h,
                          origin[2] + (double(l) + 0.5) * h);
          if(!surfaces.is_inside(p)) { ++slab.outside; continue; }
          const double radius = sizing(p, r);
          if(!surfaces.has_room(p, radius, set.clearance_factor)) { ++slab.near_surface; continue; }
          slab.bubbles.emplace_back(p, radius, r, no_index, false);
        }
    });
    for(const Placed_cells<GeomTraits>& slab : slabs) slab.append_to(out, stats);
  }
}

/*
The graded variant of steps 3-4 (`graded_cell_factor` g > 0): cubic cells of
edges e_0 2^k on one lattice anchored at `origin`, split into eight while an
edge exceeds sqrt(2) g R(c), R the sizing field at the cell centre c, so
that a leaf's edge lies within a factor sqrt(2) of g R: about one bubble per
final one, denser where the sizes are small (next to fine surfaces, in thin
layers) instead of one cell edge for the whole region. A leaf whose centre
is outside the region or too close to a surface is split too (its children
may be inside). Only cells meeting a cluster's box are visited and a leaf
counts only if its centre lies in one (the clustering's part, as in the
uniform lattice).
*/
template <class GeomTraits, class SizingField>
void place_graded_cells(const Cluster_boxes& boxes, double s_min, double s_max,
                        const Region_surfaces<GeomTraits>& surfaces, const SizingField& sizing, std::size_t r,
                        const Placement_settings& set, std::vector<Bubble<GeomTraits> >& out,
                        Region_placement_statistics& stats)
{
  typedef typename GeomTraits::Point_3 Point_3;
  const double g = set.graded_cell_factor, root2 = std::sqrt(2.);
  const double e0 = g * s_min / root2;
  if(!(e0 > 0.) || !std::isfinite(e0)) return;
  // the coarsest level holds cells of the largest size found on the surfaces, with room
  int levels = 0;
  while(levels < 16 && e0 * std::ldexp(1., levels) < root2 * g * s_max * 2.) ++levels;
  const double top = e0 * std::ldexp(1., levels);
  stats.cell_edge = e0;

  const std::array<double, 3>& origin = boxes.origin;
  std::vector<Cell> tops;
  const long nx = long(std::floor((boxes.top[0] - origin[0]) / top)),
             ny = long(std::floor((boxes.top[1] - origin[1]) / top)),
             nz = long(std::floor((boxes.top[2] - origin[2]) / top));
  for(long i = 0; i <= nx; ++i)
    for(long j = 0; j <= ny; ++j)
      for(long l = 0; l <= nz; ++l)
      {
        const std::array<double, 3> a{{origin[0] + double(i) * top, origin[1] + double(j) * top, origin[2] + double(l) * top}};
        if(boxes.meets(a, {{a[0] + top, a[1] + top, a[2] + top}})) tops.push_back(Cell{{i, j, l}});
      }

  std::vector<Placed_cells<GeomTraits> > parts(tops.size());
  for_each_index(0, tops.size(), set.parallel, [&](std::size_t t) {
    Placed_cells<GeomTraits>& part = parts[t];
    // depth first, children in lexicographic order: the same bubbles in the same order whatever the threads
    // (cell, level, whether it is the child of a rejected leaf: tested as it is, never split)
    std::vector<std::tuple<Cell, int, bool> > stack(1, std::make_tuple(tops[t], levels, false));
    while(!stack.empty())
    {
      const Cell c = std::get<0>(stack.back());
      const int level = std::get<1>(stack.back());
      const bool last = std::get<2>(stack.back());
      stack.pop_back();
      const double e = e0 * std::ldexp(1., level);
      const std::array<double, 3> a{{origin[0] + double(c[0]) * e, origin[1] + double(c[1]) * e, origin[2] + double(c[2]) * e}};
      if(!boxes.meets(a, {{a[0] + e, a[1] + e, a[2] + e}})) continue;
      const std::array<double, 3> q{{a[0] + 0.5 * e, a[1] + 0.5 * e, a[2] + 0.5 * e}};
      const Point_3 p(q[0], q[1], q[2]);
      const double radius = sizing(p, r);
      const bool split_by_size = !last && level > 0 && !(e <= root2 * g * radius);
      if(!split_by_size)
      {
        if(!boxes.meets(q, q)) continue;
        const bool inside = surfaces.is_inside(p);
        if(inside && surfaces.has_room(p, radius, set.clearance_factor))
        {
          ++part.cells;
          part.bubbles.emplace_back(p, radius, r, no_index, false);
          continue;
        }
        if(level == 0 || last)
        {
          ++part.cells;
          ++(inside ? part.near_surface : part.outside);
          continue;
        }
      }
      // split, by size or to try again nearer the surfaces (pushed in reverse: popped in lexicographic order)
      for(int ch = 7; ch >= 0; --ch)
        stack.emplace_back(Cell{{2 * c[0] + ((ch >> 2) & 1), 2 * c[1] + ((ch >> 1) & 1), 2 * c[2] + (ch & 1)}}, level - 1,
                           !split_by_size);
    }
  });
  for(const Placed_cells<GeomTraits>& part : parts) part.append_to(out, stats);
}

// Places the bubbles of region r; all its output goes to `out` and `stats`.
template <class GeomTraits, class SizingField, class KMeansClustering, class NamedParameters>
void place_region_bubbles(const Geological_model_3<GeomTraits>& model,
                          const std::vector<Bubble<GeomTraits> >& surface_bubbles,
                          const std::vector<std::size_t>& bubble_of_point,
                          std::size_t r,
                          const SizingField& sizing,
                          const KMeansClustering& clustering,
                          const Placement_settings& set,
                          const NamedParameters& np,
                          std::vector<Bubble<GeomTraits> >& out,
                          Region_placement_statistics& stats)
{
  typedef typename GeomTraits::Point_3 Point_3;
  stats.region = r;
  CGAL::Real_timer timer;
  timer.start();

  // 1. the region's surface points (centres of its surface bubbles), clustered
  std::vector<std::array<double, 3> > pts;
  std::vector<std::size_t> bubble_ids;
  for(std::size_t v : region_surface_points(model, r))
  {
    const std::size_t b = bubble_of_point[v];
    if(b == no_index) continue;
    const Point_3& c = surface_bubbles[b].center;
    pts.push_back({{CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z())}});
    bubble_ids.push_back(b);
  }
  stats.number_of_surface_points = pts.size();
  if(pts.empty()) return;

  std::vector<std::size_t> labels;
  std::vector<std::array<double, 3> > centres;
  if(set.fixed_k > 0)
  {
    clustering(pts, set.fixed_k, labels, centres);
    stats.number_of_clusters = centres.size();
  }
  else
  {
    Number_of_clusters_selection sel =
      select_number_of_clusters(pts, set.k_min, (std::max)(set.k_min, set.k_max), clustering, np);
    stats.number_of_clusters = sel.number_of_clusters;
    stats.cluster_validity = sel.table;
    stats.calinski_harabasz_choice = sel.calinski_harabasz_choice;
    stats.silhouette_choice = sel.silhouette_choice;
    stats.elbow_choice = sel.elbow_choice;
    labels.swap(sel.labels);
  }
  stats.clustering_seconds = timer.time();

  // 2. cell edge (r_max + r_min) / 2, radii taken from the sizing field at the
  // surface bubbles (for the default field: their radii times the region's
  // scale); the 5 % and 95 % quantiles stand for the extremes, since a few
  // vertices of huge triangles (a box's top given as two triangles) would
  // make the lattice as coarse as them, and the whole region nearly empty
  std::vector<double> sizes;
  sizes.reserve(bubble_ids.size());
  for(std::size_t b : bubble_ids) sizes.push_back(sizing(surface_bubbles[b].center, r));
  double s_min = 0., s_max = 0.;
  if(!sizes.empty()) std::tie(s_min, s_max) = internal::quantiles_5_95(sizes);
  const double h = set.cell_edge_factor * 0.5 * (s_min + s_max);
  stats.cell_edge = h;
  if(!(h > 0.) || !std::isfinite(h)) return;

  // 3. one lattice per region, anchored at the corner of its points' box, so
  // that overlapping cluster boxes name the same cells
  const std::size_t k = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
  const Cluster_boxes boxes(pts, labels, k);

  const Region_surfaces<GeomTraits> surfaces(model, r);
  if(!surfaces.side_of) return;

  if(set.graded_cell_factor > 0.)
    place_graded_cells(boxes, s_min, s_max, surfaces, sizing, r, set, out, stats);
  else
    place_lattice_cells(boxes, h, surfaces, sizing, r, set, out, stats);
  stats.number_of_bubbles = out.size();
  stats.placement_seconds = timer.time() - stats.clustering_seconds;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Stage 2 of the method: the initial interior bubbles of every region.

For each region `r` (independently, in parallel when TBB is linked):
1. the centres of the surface bubbles on `r`'s boundary or on surfaces
   inside `r` are clustered with `clustering_model`, with a fixed
   `number_of_clusters` or with k chosen in
   [`min_number_of_clusters`, `max_number_of_clusters`] by
   `select_number_of_clusters()`;
2. the cell edge is `h = cell_edge_factor * (s_max + s_min) / 2`, where
   `s_min` and `s_max` are the 5 % and 95 % quantiles of the sizing field at
   the region's surface bubbles: for the default field these are the
   surface-bubble radii times the region's scale, so `h` is the paper's
   `(r_max + r_min) / 2` with the extremes taken robustly (a box's top face
   given as two triangles has corners whose radius is thousands of times the
   others', and with the true maximum the region would get a handful of
   bubbles);
3. the bounding box of every cluster is covered by the cubic cells of one
   lattice of edge `h` anchored at the corner of the region's points; a cell
   that several boxes hold is taken once (by the first cluster);
4. a cell centre `p` becomes a bubble of radius `R = sizing(p, r)` when it is
   strictly inside `r`'s boundary (`CGAL::Side_of_triangle_mesh`) and
   farther than `surface_clearance_factor * R` from every triangle of `r`,
   boundary and surfaces inside `r` alike (AABB tree): so it overlaps no
   surface and lies on neither side of a surface inside `r` closer than `R`.

<b>Graded cells</b> (`graded_cell_factor` g > 0, the default; a deviation
from the paper). Steps 2-3 above give one cell edge for the whole region:
about eight bubbles per final one where the sizes are small, and far fewer
than needed where a region's interior wants smaller bubbles than its
coarsest surfaces (a re-meshed model whose box walls are coarse and whose
layers are thin), which population control then fills one bubble per gap
and round. With g > 0 the cells follow the sizing field instead: cubes of
edges \f$ e_0 2^k \f$ on one lattice (\f$ e_0 = g\,s_{min}/\sqrt 2 \f$),
each split into eight while its edge exceeds \f$ \sqrt 2\, g R \f$ at its
centre, so that a cell's edge ends within a factor \f$ \sqrt 2 \f$ of
\f$ g R \f$ (g = 2.5: about the spacing of the relaxed bubbles, whose
neighbours sit near \f$ 2R \f$). A cell that meets no cluster box is skipped;
the centre of a final cell is tested as in step 4, and a cell whose centre
fails is split once more (its children are tested as they are). Measured
(bench/README.md, session 31): the relaxation 25-38 % shorter with the
surfaces kept (modelA1, modelA2, modelA5; CloudSpin the same) with the same
or higher shares of overlap ratios inside the bounds; modelA5 re-meshed at
`--size 3%` 273 -> 175 s, its aspect-ratio median 1.70 -> 1.66.

Bubbles come by region, then by cluster (by coarsest cell with graded
cells), then by lattice cell (lexicographic; depth first with graded
cells). The result depends on the input and the parameters only,
not on the number of threads. `region` is set, `surface_point` is
`no_index`, `is_fixed` is false.

\tparam SizingField a model of `BubbleSizingField`; it must be safe to call
concurrently when `parallel_regions` is true.

\cgalNamedParamsBegin
  \cgalParamNBegin{clustering_model}
    \cgalParamDescription{a model of `KMeansClustering`}
    \cgalParamDefault{`K_means_clustering(np)`: the seed, iteration count, tolerance and restarts given in `np`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_clusters}
    \cgalParamDescription{fixed k per region; 0 chooses it}
    \cgalParamType{std::size_t} \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{min_number_of_clusters}
    \cgalParamType{std::size_t} \cgalParamDefault{2}
  \cgalParamNEnd
  \cgalParamNBegin{max_number_of_clusters}
    \cgalParamType{std::size_t} \cgalParamDefault{10}
  \cgalParamNEnd
  \cgalParamNBegin{silhouette_sample_size}
    \cgalParamDescription{see `silhouette_coefficient()`}
    \cgalParamType{std::size_t} \cgalParamDefault{2000}
  \cgalParamNEnd
  \cgalParamNBegin{graded_cell_factor}
    \cgalParamDescription{g: cells that follow the sizing field (see above); 0: the paper's lattice of one cell edge per region}
    \cgalParamType{double} \cgalParamDefault{2.5}
  \cgalParamNEnd
  \cgalParamNBegin{cell_edge_factor}
    \cgalParamDescription{the paper's lattice (`graded_cell_factor` 0): its cell edge is this times \f$ (s_{max} + s_{min}) / 2 \f$}
    \cgalParamType{double} \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{surface_clearance_factor}
    \cgalParamType{double} \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{parallel_regions}
    \cgalParamDescription{use TBB (regions and lattice slabs) when linked}
    \cgalParamType{bool} \cgalParamDefault{true}
  \cgalParamNEnd
  \cgalParamNBegin{placement_statistics}
    \cgalParamDescription{receives one entry per region, index = region (entry 0 unused)}
    \cgalParamType{std::vector<Region_placement_statistics>*} \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class GeomTraits, class SizingField, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Bubble<GeomTraits> >
place_initial_bubbles(const Geological_model_3<GeomTraits>& model,
                      const std::vector<Bubble<GeomTraits> >& surface_bubbles,
                      const SizingField& sizing,
                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  internal::Placement_settings set;
  set.fixed_k = choose_parameter(get_parameter(np, internal_np::number_of_clusters), std::size_t(0));
  set.k_min = (std::max)(std::size_t(1),
                         choose_parameter(get_parameter(np, internal_np::min_number_of_clusters), std::size_t(2)));
  set.k_max = choose_parameter(get_parameter(np, internal_np::max_number_of_clusters), std::size_t(10));
  set.cell_edge_factor = choose_parameter(get_parameter(np, internal_np::cell_edge_factor), 1.);
  set.clearance_factor = choose_parameter(get_parameter(np, internal_np::surface_clearance_factor), 1.);
  set.parallel = choose_parameter(get_parameter(np, internal_np::parallel_regions), true);
  set.graded_cell_factor = choose_parameter(get_parameter(np, internal_np::graded_cell_factor),
                                            default_graded_cell_factor);
  std::vector<Region_placement_statistics>* stats_out =
    choose_parameter(get_parameter(np, internal_np::placement_statistics),
                     static_cast<std::vector<Region_placement_statistics>*>(nullptr));
  const auto clustering = choose_parameter(get_parameter(np, internal_np::clustering_model), K_means_clustering(np));

  std::vector<std::size_t> bubble_of_point(model.number_of_points(), no_index);
  for(std::size_t b = 0; b < surface_bubbles.size(); ++b)
    if(surface_bubbles[b].surface_point < model.number_of_points())
      bubble_of_point[surface_bubbles[b].surface_point] = b;

  const std::size_t nr = model.number_of_regions();
  std::vector<std::vector<Bubble<GeomTraits> > > per_region(nr + 1);
  std::vector<Region_placement_statistics> stats(nr + 1);
  internal::for_each_index(1, nr + 1, set.parallel, [&](std::size_t r) {
    internal::place_region_bubbles(model, surface_bubbles, bubble_of_point, r, sizing, clustering, set, np,
                                   per_region[r], stats[r]);
  });

  std::vector<Bubble<GeomTraits> > result;
  for(const auto& v : per_region) result.insert(result.end(), v.begin(), v.end());
  if(stats_out) stats_out->swap(stats);
  return result;
}

/*!
\ingroup PkgBubbleMesh3Ref

Same as above with the default sizing field,
`Surface_bubble_sizing_field<GeomTraits>(model, surface_bubbles, np)`: the
radius of a candidate follows the weight-point rule (`radius_weighting`,
`interaction_range_factor`) times `region_scale_factors`.
*/
template <class GeomTraits, class T, class Tag, class Base>
std::vector<Bubble<GeomTraits> >
place_initial_bubbles(const Geological_model_3<GeomTraits>& model,
                      const std::vector<Bubble<GeomTraits> >& surface_bubbles,
                      const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  const Surface_bubble_sizing_field<GeomTraits> sizing(model, surface_bubbles, np);
  return place_initial_bubbles(model, surface_bubbles, sizing, np);
}

/// \ingroup PkgBubbleMesh3Ref
/// Same as above with all parameters at their defaults.
template <class GeomTraits>
std::vector<Bubble<GeomTraits> >
place_initial_bubbles(const Geological_model_3<GeomTraits>& model,
                      const std::vector<Bubble<GeomTraits> >& surface_bubbles)
{
  return place_initial_bubbles(model, surface_bubbles, CGAL::parameters::default_values());
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_PLACE_INITIAL_BUBBLES_H
