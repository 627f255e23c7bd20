// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_TETRAHEDRALIZE_BUBBLES_H
#define CGAL_BUBBLE_MESH_3_TETRAHEDRALIZE_BUBBLES_H

#include <CGAL/Bubble_mesh_3/Bubble.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Mesh_complex_3.h>
#include <CGAL/Bubble_mesh_3/Surface_vertex_supports.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/internal/Point_index_tree.h>
#include <CGAL/Bubble_mesh_3/internal/label_regions.h>
#include <CGAL/Bubble_mesh_3/internal/outer_wall_guards.h>
#include <CGAL/Bubble_mesh_3/internal/recover_surface.h>
#include <CGAL/Bubble_mesh_3/internal/stage_callback.h>
#include <CGAL/Bubble_mesh_3/internal/tetrahedralization_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <iterator>
#include <memory>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

What `tetrahedralize_bubbles()` did: sizes, Steiner points, how many input
triangles are single mesh facets, and the time of each step (seconds).
*/
struct Tetrahedralization_report
{
  std::size_t number_of_vertices = 0;                    ///< vertices of the output triangulation
  std::size_t number_of_cells = 0;                       ///< cells in the complex (inside the model)
  std::size_t number_of_facets = 0;                      ///< facets in the complex (on input triangles)
  std::size_t number_of_interior_points_inserted = 0;    ///< interior points that are mesh vertices
  std::size_t number_of_interior_points_duplicate = 0;   ///< dropped: on a model point or on an earlier interior point
  std::size_t number_of_interior_points_on_surfaces = 0; ///< dropped: on an input triangle (no facet could avoid them)
  std::size_t number_of_interior_points_encroaching = 0; ///< dropped: in the ball of an input edge or triangle
  std::size_t number_of_interior_points_outside = 0;     ///< dropped: outside every region
  std::size_t number_of_guard_points = 0;        ///< mirror images beyond tilted outer walls, inserted then removed (only when the recovery failed without them)
  std::size_t number_of_guard_points_inside = 0; ///< of those, any that fell inside a region (kept as vertices)
  /// Steiner points inserted on input edges
  std::size_t number_of_steiner_points_on_edges = 0;
  /// Steiner points inserted on input triangles
  std::size_t number_of_steiner_points_on_triangles = 0;
  std::size_t number_of_triangles_kept_whole = 0;        ///< input triangles that are a single mesh facet
  std::size_t number_of_triangles_split = 0;             ///< input triangles made of several mesh facets
  double time_filtering = 0.;                            ///< dropping encroaching interior points
  double time_insertion = 0.;                            ///< Delaunay insertion of all points
  double time_recovery = 0.;                             ///< Steiner points until every input triangle is present
  double time_labelling = 0.;                            ///< regions, patches, vertex dimensions, clean-up

  /// interior points that are not mesh vertices (all reasons)
  std::size_t number_of_interior_points_dropped() const
  {
    return number_of_interior_points_duplicate + number_of_interior_points_on_surfaces +
           number_of_interior_points_encroaching + number_of_interior_points_outside;
  }
  /// Steiner points inserted, on edges and triangles
  std::size_t number_of_steiner_points() const
  {
    return number_of_steiner_points_on_edges + number_of_steiner_points_on_triangles;
  }
  /// share (0 to 1) of the input triangles that are a single mesh facet
  double share_of_triangles_kept_whole() const
  {
    const std::size_t n = number_of_triangles_kept_whole + number_of_triangles_split;
    return n == 0 ? 1. : double(number_of_triangles_kept_whole) / double(n);
  }
};

/// writes the report in a few lines
inline std::ostream& operator<<(std::ostream& os, const Tetrahedralization_report& r)
{
  os << "vertices " << r.number_of_vertices << ", cells " << r.number_of_cells << ", surface facets "
     << r.number_of_facets << "\n"
     << "interior points: " << r.number_of_interior_points_inserted << " inserted, "
     << r.number_of_interior_points_duplicate << " duplicate, " << r.number_of_interior_points_on_surfaces
     << " on surfaces, " << r.number_of_interior_points_encroaching
     << " encroaching, " << r.number_of_interior_points_outside << " outside\n";
  if(r.number_of_guard_points > 0)
    os << "guard points beyond tilted outer walls (the recovery failed without them): " << r.number_of_guard_points
       << " (" << r.number_of_guard_points_inside << " inside a region)\n";
  os
     << "Steiner points: " << r.number_of_steiner_points_on_edges << " on edges, "
     << r.number_of_steiner_points_on_triangles << " on triangles\n"
     << "input triangles kept whole: " << r.number_of_triangles_kept_whole << " of "
     << (r.number_of_triangles_kept_whole + r.number_of_triangles_split) << " ("
     << 100. * r.share_of_triangles_kept_whole() << " %)\n"
     << "time (s): filtering " << r.time_filtering << ", insertion " << r.time_insertion << ", recovery "
     << r.time_recovery << ", labelling " << r.time_labelling;
  return os;
}

namespace internal {

// Marks the interior points to drop: duplicates of model points or of earlier
// interior points, points on input triangles, and (if asked) points in the closed diametral ball of an
// input edge or the closed equatorial ball of a well-shaped input triangle,
// where they would keep it out of the Delaunay triangulation - but only balls
// that hold no other model point: an element that model points encroach upon
// gets split anyway, and dropping would only empty its surroundings.
template <class GeomTraits, class Recovery>
void mark_dropped_interior_points(const Geological_model_3<GeomTraits>& model,
                                  const std::vector<typename GeomTraits::Point_3>& interior,
                                  const Recovery& recovery, bool drop_encroaching, double ratio_bound,
                                  std::vector<char>& dropped, Tetrahedralization_report& report)
{
  typedef typename GeomTraits::Point_3 Point_3;
  const GeomTraits gt;
  auto less = [&](const Point_3& a, const Point_3& b) { return gt.compare_xyz_3_object()(a, b) == CGAL::SMALLER; };

  dropped.assign(interior.size(), 0);
  std::vector<Point_3> model_sorted = model.points();
  std::sort(model_sorted.begin(), model_sorted.end(), less);
  std::vector<std::size_t> order(interior.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return less(interior[a], interior[b]); });
  for(std::size_t k = 0; k < order.size(); ++k)
  {
    const Point_3& p = interior[order[k]];
    if((k > 0 && interior[order[k - 1]] == p) ||
       std::binary_search(model_sorted.begin(), model_sorted.end(), p, less))
    {
      dropped[order[k]] = 1;
      ++report.number_of_interior_points_duplicate;
    }
  }
  if(interior.empty()) return;

  std::vector<std::size_t> kept;
  for(std::size_t i = 0; i < interior.size(); ++i)
    if(!dropped[i]) kept.push_back(i);
  const Point_index_tree<GeomTraits> interior_tree(interior, kept.begin(), kept.end());
  const Point_index_tree<GeomTraits> model_tree(model.points());
  std::vector<std::size_t> found;
  // `inside` is the exact test (the trees report a little more than the ball)
  auto drop_in = [&](const Point_3& center, double radius, const std::array<std::size_t, 3>& corners,
                     auto&& inside) {
    model_tree.points_in_ball(center, radius, found);
    for(std::size_t i : found)
      if(i != corners[0] && i != corners[1] && i != corners[2] && inside(model.point(i))) return;
    interior_tree.points_in_ball(center, radius, found);
    for(std::size_t i : found)
      if(!dropped[i] && inside(interior[i]))
      {
        dropped[i] = 1;
        ++report.number_of_interior_points_encroaching;
      }
  };
  auto side = gt.side_of_bounded_sphere_3_object();

  // a point on an input triangle would be a vertex of every facet over it
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& tri = model.triangle(t);
    const typename GeomTraits::Triangle_3 triangle(model.point(tri[0]), model.point(tri[1]), model.point(tri[2]));
    const Point_3 center = CGAL::centroid(triangle);
    double r2 = 0.;
    for(int k = 0; k < 3; ++k)
      r2 = (std::max)(r2, CGAL::to_double(CGAL::squared_distance(center, triangle.vertex(k))));
    interior_tree.points_in_ball(center, std::sqrt(r2), found);
    for(std::size_t i : found)
      if(!dropped[i] && CGAL::coplanar(triangle[0], triangle[1], triangle[2], interior[i]) &&
         triangle.has_on(interior[i]))
      {
        dropped[i] = 1;
        ++report.number_of_interior_points_on_surfaces;
      }
  }
  if(!drop_encroaching) return;

  for(const auto& e : recovery.edge_ends())
  {
    const Point_3& a = model.point(e[0]);
    const Point_3& b = model.point(e[1]);
    drop_in(CGAL::midpoint(a, b), 0.5 * std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))),
            {{e[0], e[1], e[1]}}, [&](const Point_3& p) { return side(a, b, p) != CGAL::ON_UNBOUNDED_SIDE; });
  }
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& tri = model.triangle(t);
    const Point_3& a = model.point(tri[0]);
    const Point_3& b = model.point(tri[1]);
    const Point_3& c = model.point(tri[2]);
    const double r2 = CGAL::to_double(CGAL::squared_radius(a, b, c));
    const double l2 = (std::min)({CGAL::to_double(CGAL::squared_distance(a, b)),
                                  CGAL::to_double(CGAL::squared_distance(b, c)),
                                  CGAL::to_double(CGAL::squared_distance(c, a))});
    // a needle or cap has a huge ball, and gets split anyway
    if(!(r2 <= ratio_bound * ratio_bound * l2)) continue;
    drop_in(CGAL::circumcenter(a, b, c), std::sqrt(r2), tri,
            [&](const Point_3& p) { return side(a, b, c, p) != CGAL::ON_UNBOUNDED_SIDE; });
  }
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Builds the tetrahedral mesh of a geological model from its points and the
relaxed interior bubble centres: one Delaunay triangulation of all points,
in which every input triangle is then recovered exactly as a union of mesh
facets by adding Steiner points on input edges and triangles (input points
never move, Steiner points never leave the input surfaces), and whose cells
are labelled with their regions.

The steps:
1. interior points on a model point, on an earlier interior point or on an
   input triangle are dropped; so are (by default) those in the closed diametral ball of an input
   edge or the closed equatorial ball of a well-shaped input triangle, which
   would keep it out of the triangulation, when no other model point lies in
   that ball (else the element is split anyway);
2. all points go into the triangulation of `c3t3` (spatially sorted,
   sequential insertion: the triangulation of a point set is unique, also in
   degenerate (cospherical) cases since CGAL breaks ties by a symbolic
   perturbation ordered by the points' coordinates, and sequential insertion
   keeps the storage order, hence vertex numbering in files, the same from
   run to run);
3. input edges, then input triangles, are recovered: a missing subsegment
   is split where the vertex encroaching most upon it asks for (on a sphere
   around an input end it shares a surface with, or at its projection), or
   else at a dyadic distance from an end (power-of-two shells next to input
   vertices); a missing sub-triangle gets its circumcentre unless that
   encroaches upon a subsegment, which is then split instead. Only edges and
   triangles near an insertion are checked again;
4. facets on input triangles enter the complex with patch index + 1, cells
   get the region on their side by a flood fill that crosses no such facet
   (the flat cells that rounded Steiner points can make on a plane are put
   on one side of it); interior points outside every region are removed.

If the recovery fails and the model has tilted outer walls (planar only up to
the rounding of their points, on the convex hull), steps 2 and 3 run once
more with guard points: the interior points facing such a wall mirrored
beyond it, so that the wall's facets seen from outside are Delaunay ones as
seen from inside. They lie outside the model and are removed in step 4
(`Tetrahedralization_report::number_of_guard_points`).

Sequential by design: CGAL's parallel insertion needs a `Parallel_tag`
triangulation, whose storage order (vertex numbering in files, and the order
in which recovery meets ties) depends on thread scheduling; insertion is a
few percent of the time here anyway.

\param model a valid geological model (see `validate_geological_model()`)
\param interior_points points inside the regions (relaxed bubble centres)
\param c3t3 the output; cleared first
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{drop_encroaching_points}
    \cgalParamDescription{whether interior points that encroach on input edges or triangles are dropped}
    \cgalParamType{bool}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{drop_ball_ratio_bound}
    \cgalParamDescription{a triangle's equatorial ball drops points only if its radius is at most this
      times the triangle's shortest edge (`1`: smallest angle at least 30 degrees)}
    \cgalParamType{double}
    \cgalParamDefault{`1`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_number_of_steiner_points}
    \cgalParamDescription{beyond this many Steiner points recovery stops with an error}
    \cgalParamType{std::size_t}
    \cgalParamDefault{20 times the number of model points and triangles, plus 10000}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_split_length}
    \cgalParamDescription{recovery stops with an error rather than cut an input edge into pieces shorter than
      this fraction of the bounding-box diagonal}
    \cgalParamType{double}
    \cgalParamDefault{`1e-9`}
  \cgalParamNEnd
  \cgalParamNBegin{surface_vertex_supports}
    \cgalParamDescription{filled with the surface vertices of the mesh, which of them are Steiner points,
      and the input triangles each lies on; hand it to `remove_slivers()` to collapse Steiner points}
    \cgalParamType{`Surface_vertex_supports<Mesh_complex_3<GeomTraits>::Triangulation>*`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{progress on `std::cout`}
    \cgalParamType{bool}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what was done (`Tetrahedralization_report`)
\throws Tetrahedralization_error naming the triangle, edge or cell when recovery
  or labelling fails; `c3t3` is then unspecified.
*/
template <class GeomTraits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Tetrahedralization_report
tetrahedralize_bubbles(const Geological_model_3<GeomTraits>& model,
                       const std::vector<typename GeomTraits::Point_3>& interior_points,
                       Mesh_complex_3<GeomTraits>& c3t3,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef Mesh_complex_3<GeomTraits>           C3T3;
  typedef typename C3T3::Triangulation         Tr;
  typedef typename Tr::Vertex_handle           Vertex_handle;
  typedef typename Tr::Cell_handle             Cell_handle;
  typedef typename GeomTraits::Point_3         Point_3;
  typedef internal::Surface_recovery<Tr, GeomTraits> Recovery;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  Tetrahedralization_report report;
  c3t3.clear();
  if(model.number_of_triangles() == 0)
    throw Tetrahedralization_error("the model has no triangles");
  for(std::size_t i = 0; i < interior_points.size(); ++i)
  {
    const Point_3& p = interior_points[i];
    if(!(std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
         std::isfinite(CGAL::to_double(p.z()))))
      throw Tetrahedralization_error("interior point " + std::to_string(i) + " has a coordinate that is not finite");
  }

  const bool drop = choose_parameter(get_parameter(np, internal_np::drop_encroaching_points), true);
  const double ratio_bound = choose_parameter(get_parameter(np, internal_np::drop_ball_ratio_bound), 1.);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const double diagonal = bbox_diagonal(model);
  typename Recovery::Options options;
  options.maximum_number_of_steiner_points = choose_parameter(
    get_parameter(np, internal_np::maximum_number_of_steiner_points),
    std::size_t(20 * (model.number_of_points() + model.number_of_triangles()) + 10000));
  options.minimum_split_length = diagonal * choose_parameter(get_parameter(np, internal_np::minimum_split_length), 1e-9);
  options.verbose = verbose;

  Tr& tr = c3t3.triangulation();
  std::unique_ptr<Recovery> recovery_holder(new Recovery(model, tr, options));

  // 1. drop interior points
  CGAL::Real_timer timer;
  timer.start();
  std::vector<char> dropped;
  internal::mark_dropped_interior_points(model, interior_points, *recovery_holder, drop, ratio_bound, dropped, report);
  std::vector<Point_3> kept;
  for(std::size_t i = 0; i < interior_points.size(); ++i)
    if(!dropped[i]) kept.push_back(interior_points[i]);
  const std::size_t number_of_kept = kept.size();
  report.time_filtering = timer.time();
  if(verbose)
    std::cout << "tetrahedralize: " << kept.size() << " interior points kept, "
              << report.number_of_interior_points_duplicate << " duplicate, "
              << report.number_of_interior_points_encroaching << " encroaching (" << report.time_filtering << " s)"
              << std::endl;

  // 2. one Delaunay triangulation of everything, and 3. the conforming
  // recovery of the input edges and triangles
  // a progress line for each step: a model with a flat layer spent 79 s in this stage
  const auto announce = internal::step_announcer(np, "tetrahedralization");
  auto triangulate = [&](Recovery& recovery) {
    announce("inserting the points");
    timer.reset();
    recovery.insert_points(kept);
    report.time_insertion += timer.time();
    if(verbose)
      std::cout << "tetrahedralize: " << tr.number_of_vertices() << " vertices inserted (" << timer.time() << " s)"
                << std::endl;
    announce("recovering the surfaces");
    timer.reset();
    recovery.recover();
    report.time_recovery += timer.time();
  };
  try
  {
    triangulate(*recovery_holder);
  }
  catch(const Tetrahedralization_error&)
  {
    // Tilted outer walls can keep the recovery from deciding the side of its
    // flat cells: once more with guard points beyond them, if there are any
    // (internal/outer_wall_guards.h), dropped by the same rules. Not from the
    // start: on walls of needles they cost Steiner points and poorer
    // tetrahedra (modelA5 turned by 30 degrees: 35 -> 44 % under 10 degrees).
    std::vector<Point_3> all = kept;
    const std::vector<Point_3> guards = internal::outer_wall_guards(model, *recovery_holder, kept);
    if(guards.empty()) throw;
    all.insert(all.end(), guards.begin(), guards.end());
    std::vector<char> all_dropped;
    Tetrahedralization_report scratch;
    internal::mark_dropped_interior_points(model, all, *recovery_holder, drop, ratio_bound, all_dropped, scratch);
    for(std::size_t i = number_of_kept; i < all.size(); ++i)
      if(!all_dropped[i]) kept.push_back(all[i]);
    report.number_of_guard_points = kept.size() - number_of_kept;
    if(verbose)
      std::cout << "tetrahedralize: recovery failed, again with " << report.number_of_guard_points
                << " guard points beyond the tilted outer walls" << std::endl;
    recovery_holder.reset();
    tr.clear();
    recovery_holder.reset(new Recovery(model, tr, options));
    triangulate(*recovery_holder);
  }
  const Recovery& recovery = *recovery_holder;
  report.number_of_steiner_points_on_edges = recovery.number_of_edge_points();
  report.number_of_steiner_points_on_triangles = recovery.number_of_triangle_points();
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    (recovery.is_kept_whole(t) ? report.number_of_triangles_kept_whole : report.number_of_triangles_split) += 1;
  if(verbose)
    std::cout << "tetrahedralize: " << recovery.number_of_edge_points() << " Steiner points on edges, "
              << recovery.number_of_triangle_points() << " on triangles (" << report.time_recovery << " s)"
              << std::endl;

  // 4. labels, vertex dimensions, clean-up
  announce("labelling the regions");
  timer.reset();
  internal::label_regions(model, recovery, c3t3);
  if(verbose) std::cout << "tetrahedralize: regions labelled (" << timer.time() << " s)" << std::endl;
  std::vector<std::size_t> patch_of_point(model.number_of_points(), no_index);
  for(std::size_t t = model.number_of_triangles(); t-- > 0;)
    for(std::size_t v : model.triangle(t)) patch_of_point[v] = model.patch_of_triangle(t);
  Surface_vertex_supports<Tr>* const supports =
    choose_parameter(get_parameter(np, internal_np::surface_vertex_supports), static_cast<Surface_vertex_supports<Tr>*>(nullptr));
  if(supports) supports->clear();
  std::vector<Cell_handle> cells;
  for(const auto& r : recovery.records())
  {
    std::size_t patch = no_index;
    switch(r.kind)
    {
    case internal::Vertex_kind::input_point: patch = patch_of_point[r.element]; break;
    case internal::Vertex_kind::edge_point: patch = model.patch_of_triangle(recovery.triangle_of_edge(r.element)); break;
    case internal::Vertex_kind::triangle_point: patch = model.patch_of_triangle(r.element); break;
    default: break;
    }
    const Vertex_handle v = r.vh;
    if(patch != no_index)
    {
      c3t3.set_dimension(v, 2);
      c3t3.set_index(v, int(patch) + 1);
      if(supports)
      {
        const auto support = recovery.support(std::size_t(&r - recovery.records().data()));
        supports->add(v, r.kind != internal::Vertex_kind::input_point, support.first, support.second);
      }
      continue;
    }
    cells.clear();
    tr.incident_cells(v, std::back_inserter(cells));
    int region = 0;
    for(Cell_handle c : cells)
      if(c3t3.is_in_complex(c)) { region = c3t3.subdomain_index(c); break; }
    const bool guard = r.kind == internal::Vertex_kind::interior_point && r.element >= number_of_kept;
    if(region == 0)
    {
      c3t3.set_dimension(v, -1);
      if(r.kind == internal::Vertex_kind::interior_point && !guard) ++report.number_of_interior_points_outside;
      continue;
    }
    c3t3.set_dimension(v, 3);
    c3t3.set_index(v, region);
    if(guard) ++report.number_of_guard_points_inside;
    else if(r.kind == internal::Vertex_kind::interior_point) ++report.number_of_interior_points_inserted;
  }
  if(verbose) std::cout << "tetrahedralize: vertex dimensions set (" << timer.time() << " s)" << std::endl;
  // interior points outside the model: their removal only touches cells outside
  if(report.number_of_interior_points_outside > 0 || report.number_of_guard_points > 0)
    c3t3.remove_isolated_vertices();
  report.time_labelling = timer.time();

  report.number_of_vertices = tr.number_of_vertices();
  report.number_of_cells = c3t3.number_of_cells_in_complex();
  report.number_of_facets = c3t3.number_of_facets_in_complex();
  if(verbose) std::cout << report << std::endl;
  return report;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_TETRAHEDRALIZE_BUBBLES_H
