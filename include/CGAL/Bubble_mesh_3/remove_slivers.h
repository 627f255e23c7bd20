// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_REMOVE_SLIVERS_H
#define CGAL_BUBBLE_MESH_3_REMOVE_SLIVERS_H

#include <CGAL/Bubble_mesh_3/Surface_vertex_supports.h>
#include <CGAL/Bubble_mesh_3/internal/collapse_steiner_points.h>
#include <CGAL/Bubble_mesh_3/internal/flip_slivers.h>
#include <CGAL/Bubble_mesh_3/internal/insert_sliver_vertices.h>
#include <CGAL/Bubble_mesh_3/internal/perturb_interior_vertices.h>
#include <CGAL/Bubble_mesh_3/internal/sliver_parameters.h>
#include <CGAL/Bubble_mesh_3/internal/stage_callback.h>

#include <CGAL/Kd_tree.h>
#include <CGAL/Mesh_optimization_return_code.h>
#include <CGAL/Named_function_parameters.h>
// Slivers_exuder.h uses the work-sharing types without including their header
#include <CGAL/Mesh_3/Worksharing_data_structures.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/property_map.h>
#include <CGAL/tetrahedral_remeshing.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <exception>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

What `remove_slivers()` did. Angles are smallest dihedral angles in degrees,
over the cells of the complex; times are in seconds.
*/
struct Sliver_removal_report
{
  double sliver_bound = 0.;                               ///< the bound used
  std::size_t number_of_cells_before = 0;                 ///< cells in the complex, before
  std::size_t number_of_cells_after = 0;                  ///< cells in the complex, after
  double min_dihedral_angle_before = 0.;                  ///< smallest dihedral angle, before
  double min_dihedral_angle_after_perturbation = 0.;      ///< ... after step 1
  double min_dihedral_angle_after_exudation = 0.;         ///< ... after step 2
  double min_dihedral_angle_after_polish = 0.;            ///< ... after step 3
  double min_dihedral_angle_after_flips = 0.;             ///< ... after the first flips of step 4
  double min_dihedral_angle_after = 0.;                   ///< ... at the end
  std::size_t number_of_slivers_before = 0;               ///< cells under the bound, before
  std::size_t number_of_slivers_after_perturbation = 0;   ///< ... after step 1
  std::size_t number_of_slivers_after_exudation = 0;      ///< ... after step 2
  std::size_t number_of_slivers_after_polish = 0;         ///< ... after step 3
  std::size_t number_of_slivers_after_flips = 0;          ///< ... after the first flips of step 4
  std::size_t number_of_slivers_after = 0;                ///< ... at the end

  bool perturbation_done = false;          ///< step 1 ran
  bool perturbation_skipped_nonzero_weights = false; ///< step 1 not run: the triangulation has weights
  bool skipped_not_regular = false; ///< steps 1 and 2 not run: the triangulation is not regular (step 3 or 4 ran before)
  /// passes of the perturbation over the slivers
  std::size_t number_of_perturbation_passes = 0;
  std::size_t number_of_vertices_tried = 0; ///< interior vertices of slivers the perturbation worked on
  std::size_t number_of_moves = 0;          ///< accepted moves
  std::size_t number_of_vertices_moved = 0; ///< distinct vertices among them
  std::size_t number_of_candidates_rejected = 0; ///< positions refused: outside the region or cutting a complex facet

  /// smoothing passes over all interior vertices (step 1, after the perturbation)
  std::size_t number_of_smoothing_passes = 0;
  std::size_t number_of_smoothing_moves = 0; ///< accepted smoothing moves
  double time_smoothing = 0.;                ///< seconds spent smoothing

  bool exudation_done = false;     ///< step 2 ran and its result was kept
  bool exudation_reverted = false; ///< step 2 ran but broke a check (facets, volumes, angles) and was undone
  std::string exudation_reverted_because; ///< which check, when undone
  CGAL::Mesh_optimization_return_code exudation_code = CGAL::MESH_OPTIMIZATION_UNKNOWN_ERROR; ///< as returned by `exude_mesh_3()`

  bool polish_done = false;     ///< step 3 ran and its result was kept
  bool polish_reverted = false; ///< step 3 ran but broke a check, or did not help, and was undone
  std::string polish_reverted_because; ///< which check, when undone

  bool collapses_done = false;                  ///< the Steiner-point collapses of step 4 ran
  /// Steiner points of the recovery collapsed onto a neighbour on the same input triangles
  std::size_t number_of_steiner_points_collapsed = 0;
  std::size_t number_of_steiner_points_left = 0; ///< Steiner points of the recovery still in the mesh (when known)
  /// input triangles still cut by Steiner points (when known): the others are one facet each
  std::size_t number_of_triangles_split = 0;
  bool flips_done = false;                      ///< the flips of step 4 ran
  std::size_t number_of_2_3_flips = 0;          ///< 2-3 flips kept (two cells sharing a facet made three)
  std::size_t number_of_edge_removals = 0;      ///< edge removals kept (n cells around an edge made 2n - 4)
  bool insertion_done = false;                  ///< step 4 ran
  /// passes of the interior-vertex insertion
  std::size_t number_of_insertion_passes = 0;
  std::size_t number_of_slivers_tried = 0;      ///< cells under the bound step 4 worked on
  std::size_t number_of_vertices_inserted = 0;  ///< new interior vertices (one per replaced cavity)
  std::size_t number_of_slivers_forced = 0;     ///< cells under the bound left by step 4: an edge on a complex facet with an angle under 10 degrees

  bool time_limit_reached = false; ///< a step stopped, or was skipped, for lack of time
  /// seconds spent in step 1, the perturbation
  double time_perturbation = 0.;
  double time_exudation = 0.;      ///< including the checks and the back-up copy
  double time_polish = 0.;         ///< including the checks and the back-up copy
  /// seconds spent collapsing Steiner points
  double time_collapses = 0.;
  /// seconds spent flipping
  double time_flips = 0.;
  /// seconds spent inserting interior vertices
  double time_insertion = 0.;
  double time = 0.;                ///< everything
};

/// writes the report in a few lines
inline std::ostream& operator<<(std::ostream& os, const Sliver_removal_report& r)
{
  os << "sliver removal (bound " << r.sliver_bound << " degrees): min dihedral " << r.min_dihedral_angle_before
     << " -> " << r.min_dihedral_angle_after_perturbation << " (perturbation) -> "
     << r.min_dihedral_angle_after_exudation << " (exudation) -> " << r.min_dihedral_angle_after_polish
     << " (polish) -> " << r.min_dihedral_angle_after_flips << " (flips) -> " << r.min_dihedral_angle_after
     << " (insertion and flips)\n"
     << "  cells under the bound: " << r.number_of_slivers_before << " -> " << r.number_of_slivers_after_perturbation
     << " -> " << r.number_of_slivers_after_exudation << " -> " << r.number_of_slivers_after_polish << " -> "
     << r.number_of_slivers_after_flips << " -> " << r.number_of_slivers_after << " (of "
     << r.number_of_cells_after << " cells)\n"
     << "  perturbation: " << (r.perturbation_done ? "" : "not run, ")
     << (r.perturbation_skipped_nonzero_weights ? "weights not zero, " : "")
     << (r.skipped_not_regular ? "triangulation not regular, " : "") << r.number_of_perturbation_passes
     << " passes, " << r.number_of_vertices_tried << " vertices tried, " << r.number_of_moves << " moves of "
     << r.number_of_vertices_moved << " vertices, " << r.number_of_candidates_rejected << " positions refused\n"
     << "  smoothing: " << r.number_of_smoothing_passes << " passes, " << r.number_of_smoothing_moves << " moves ("
     << r.time_smoothing << " s)\n"
     << "  exudation: "
     << (r.exudation_done ? "kept" : (r.exudation_reverted ? "undone, " + r.exudation_reverted_because : "not run"))
     << " (code " << int(r.exudation_code) << ")"
     << ", polish: " << (r.polish_done ? "kept" : (r.polish_reverted ? "undone, " + r.polish_reverted_because : "not run"))
     << (r.time_limit_reached ? ", time limit reached" : "") << "\n"
     << "  Steiner points: " << (r.collapses_done ? "" : "collapses not run, ") << r.number_of_steiner_points_collapsed
     << " collapsed, " << r.number_of_steiner_points_left << " left, on " << r.number_of_triangles_split
     << " input triangles\n"
     << "  flips: " << (r.flips_done ? "" : "not run, ") << r.number_of_2_3_flips << " 2-3 flips, "
     << r.number_of_edge_removals << " edge removals\n"
     << "  insertion: " << (r.insertion_done ? "" : "not run, ") << r.number_of_insertion_passes << " passes, "
     << r.number_of_slivers_tried << " slivers tried, " << r.number_of_vertices_inserted << " vertices inserted, "
     << r.number_of_slivers_forced << " left at surface angles under 10 degrees\n"
     << "  time (s): perturbation " << r.time_perturbation << ", exudation " << r.time_exudation << ", polish "
     << r.time_polish << ", collapses " << r.time_collapses << ", flips " << r.time_flips << ", insertion " << r.time_insertion << ", total " << r.time;
  return os;
}

namespace internal {

// smallest dihedral angle and cells under the bound, over the complex
template <class C3T3>
Cell_set_quality complex_quality(const C3T3& c3t3, double bound)
{
  Cell_set_quality q;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    q.add(cell_smallest_dihedral_angle(c3t3.triangulation(), c), bound);
  return q;
}

// What the steps that may not touch the surfaces must leave as it was: the
// complex facets (vertex triples, which survive since surface vertices are
// never removed) with their patches, the surface vertices and their positions
// and labels, and the volume of each region.
template <class C3T3>
struct Complex_snapshot
{
  typedef typename C3T3::Triangulation         Tr;
  typedef typename Tr::Vertex_handle           Vertex_handle;
  typedef typename C3T3::Surface_patch_index   Surface_patch_index;
  typedef typename C3T3::Subdomain_index       Subdomain_index;
  typedef typename C3T3::Index                 Index;
  typedef std::array<Vertex_handle, 3>         Triple;

  std::map<Triple, Surface_patch_index> facets;
  std::map<Vertex_handle, std::pair<int, Index> > surface_vertices; // dimension and index
  std::map<Vertex_handle, typename Tr::Bare_point> surface_points;
  std::map<Subdomain_index, double> volumes;

  static Triple triple(const typename Tr::Facet& f)
  {
    Triple t;
    for(int k = 0, j = 0; k < 4; ++k)
      if(k != f.second) t[j++] = f.first->vertex(k);
    std::sort(t.begin(), t.end());
    return t;
  }

  static std::map<Subdomain_index, double> region_volumes(const C3T3& c3t3)
  {
    std::map<Subdomain_index, double> v;
    const Tr& tr = c3t3.triangulation();
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
      v[c3t3.subdomain_index(c)] += std::abs(CGAL::to_double(tr.tetrahedron(c).volume()));
    return v;
  }

  explicit Complex_snapshot(const C3T3& c3t3)
  {
    const Tr& tr = c3t3.triangulation();
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    {
      facets[triple(*f)] = c3t3.surface_patch_index(*f);
      for(int k = 0; k < 4; ++k)
        if(k != f->second)
        {
          const Vertex_handle v = f->first->vertex(k);
          surface_vertices[v] = std::make_pair(c3t3.in_dimension(v), c3t3.index(v));
          surface_points[v] = tr.geom_traits().construct_point_3_object()(v->point());
        }
    }
    volumes = region_volumes(c3t3);
  }

  // what broke, or an empty string: every facet is there with its patch and
  // nothing more, surface points did not move, region volumes agree to
  // `volume_tolerance` (relative)
  std::string broken(const C3T3& c3t3, double volume_tolerance) const
  {
    const Tr& tr = c3t3.triangulation();
    if(c3t3.number_of_facets_in_complex() != facets.size()) return "number of complex facets changed";
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    {
      auto it = facets.find(triple(*f));
      if(it == facets.end()) return "a complex facet changed";
      if(!(it->second == c3t3.surface_patch_index(*f))) return "a patch index changed";
    }
    for(const auto& vp : surface_points)
      if(!(tr.geom_traits().construct_point_3_object()(vp.first->point()) == vp.second))
        return "a surface vertex moved";
    const std::map<Subdomain_index, double> now = region_volumes(c3t3);
    if(now.size() != volumes.size()) return "a region vanished";
    for(const auto& rv : volumes)
    {
      auto it = now.find(rv.first);
      if(it == now.end() || !(std::abs(it->second - rv.second) <= volume_tolerance * rv.second))
        return "a region volume changed";
    }
    return std::string();
  }
};

// The tetrahedral remesher labels vertices its own way (dimension 1 and 0 on
// curves and corners, complex edges and corners added): put back the labels of
// the surface vertices, give new vertices dimension 3, drop what it added.
template <class C3T3>
void restore_vertex_labels(C3T3& c3t3, const Complex_snapshot<C3T3>& snapshot,
                           const std::vector<std::pair<typename C3T3::Triangulation::Vertex_handle,
                                                       typename C3T3::Triangulation::Vertex_handle> >& old_edges,
                           const std::vector<typename C3T3::Triangulation::Vertex_handle>& old_corners)
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  Tr& tr = c3t3.triangulation();
  std::vector<std::pair<Vertex_handle, Vertex_handle> > edges;
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
  {
    std::pair<Vertex_handle, Vertex_handle> vv(e->first->vertex(e->second), e->first->vertex(e->third));
    if(vv.second < vv.first) std::swap(vv.first, vv.second);
    if(std::find(old_edges.begin(), old_edges.end(), vv) == old_edges.end()) edges.push_back(vv);
  }
  for(const auto& vv : edges) c3t3.remove_from_complex(vv.first, vv.second);
  std::vector<Vertex_handle> corners;
  for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
    if(std::find(old_corners.begin(), old_corners.end(), Vertex_handle(v)) == old_corners.end())
      corners.push_back(v);
  for(Vertex_handle v : corners) c3t3.remove_from_complex(v);
  std::vector<typename Tr::Cell_handle> cells;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
  {
    auto it = snapshot.surface_vertices.find(v);
    if(it != snapshot.surface_vertices.end())
    {
      c3t3.set_dimension(v, it->second.first);
      c3t3.set_index(v, it->second.second);
      continue;
    }
    cells.clear();
    tr.incident_cells(v, std::back_inserter(cells));
    for(auto c : cells)
      if(c3t3.is_in_complex(c))
      {
        c3t3.set_dimension(v, 3);
        c3t3.set_index(v, typename C3T3::Index(c3t3.subdomain_index(c)));
        break;
      }
  }
}

// Sizing field of the polish: the mean length of the edges at the vertex
// nearest to a point, so that the remesher keeps the size the mesh has.
template <class Tr>
class Local_edge_length
{
  typedef CGAL::Simple_cartesian<double>                                          SK;
  typedef typename CGAL::Pointer_property_map<SK::Point_3>::type                   Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<SK> > Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits>                              Search;

public:
  explicit Local_edge_length(const Tr& tr) : tr_(tr)
  {
    std::vector<typename Tr::Vertex_handle> around;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    {
      around.clear();
      tr.finite_adjacent_vertices(v, std::back_inserter(around));
      double sum = 0.;
      for(auto w : around) sum += std::sqrt(CGAL::squared_distance(to_sk(v->point()), to_sk(w->point())));
      points_.push_back(to_sk(v->point()));
      lengths_.push_back(around.empty() ? 0. : sum / double(around.size()));
    }
    std::vector<std::size_t> ids(points_.size());
    for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
    map_ = CGAL::make_property_map(points_);
    tree_ = std::make_shared<typename Search::Tree>(ids.begin(), ids.end(), typename Search::Tree::Splitter(),
                                                    Traits(map_));
    tree_->build();
  }
  double operator()(const typename Tr::Point& p) const
  {
    Search search(*tree_, to_sk(p), 1, 0, true, typename Search::Distance(map_));
    return lengths_[search.begin()->first];
  }

private:
  SK::Point_3 to_sk(const typename Tr::Point& p) const
  {
    const Vec3 c = to_vec3(tr_.geom_traits().construct_point_3_object()(p));
    return SK::Point_3(c[0], c[1], c[2]);
  }

  const Tr& tr_;
  std::vector<SK::Point_3> points_;
  std::vector<double> lengths_;
  Point_map map_;
  std::shared_ptr<typename Search::Tree> tree_;
};

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Removes slivers (tetrahedra with a small dihedral angle) from a mesh while
keeping its surfaces: no vertex on a complex facet ever moves, every facet of
the complex stays with its surface patch index, every cell keeps its region,
hence region volumes do not change. Four steps:

1. **Perturbation** of interior vertices: each vertex of dimension 3 of a cell
   whose smallest dihedral angle is under `sliver_bound`, worst cell first, is
   tried at positions in a ball (radius `perturbation_radius_factor` times its
   shortest incident edge): away from the face opposite it in each of its
   slivers, towards the centroid of its neighbours, and at seeded random
   points. A move is a removal and a re-insertion (the triangulation stays
   regular); a position is allowed only if its conflict zone lies in the
   vertex's region and cuts no complex facet, and is taken only if the cells
   it makes have a larger smallest dihedral angle than the cells it destroys,
   and no more cells under the bound. Passes repeat while they move something.
2. **Exudation** (off by default): CGAL's `exude_mesh_3()` with the same
   bound. It changes only the weights of the regular triangulation, but around
   surface vertices it re-triangulates the complex facets it meets (its
   "umbrella"), and cells that are nearly flat break its computations (a CGAL
   assertion). So this function checks what must not change (complex facets
   with their patches, surface points, region volumes) and that the smallest
   angle got no worse, and undoes the step (from a copy) otherwise, saying why
   in the report.
3. **Polish** (off by default): CGAL's `tetrahedral_isotropic_remeshing()` with
   `remesh_boundaries(false)` (interior vertices only; interior edges split,
   collapsed and flipped), with a sizing field taken from the local edge
   lengths; checked and undone like step 2, and undone as well if the count of
   cells under the bound or the smallest angle got worse. Its output is **no
   longer a regular triangulation**: after it, do not call `exude_mesh_3()`,
   `remove_slivers()` or anything else that needs the empty-sphere property;
   writers and quality measures are fine.
4. **Steiner points collapsed, flips and insertion** of interior vertices.
   Given the `surface_vertex_supports` that `tetrahedralize_bubbles()`
   filled, each Steiner point of the recovery, in recording order, is
   collapsed onto the neighbour that makes the best cells among those lying
   on every input triangle the point lies on (the cells around the edge
   vanish, the others take the neighbour for the point): kept if the result
   is a triangulation (link condition), every changed cell is positive by the
   exact predicate, every facet between two regions stays a complex facet,
   and the changed cells have fewer cells under the bound (none with an angle
   under the mesh's smallest) or as many and none worse than the old star.
   Surfaces, patches and region volumes stay; the input triangles the point
   cut get fewer pieces, often one again. Then each cell still
   under `sliver_bound`, worst first, is flipped away if one of its 2-3 flips
   (two cells sharing a non-complex facet become three) or edge removals (the
   3 to 7 cells around an edge that is on no complex facet become a best
   triangulation of the edge's ring, by dynamic programming) makes cells that
   beat the ones replaced; the boundary of the replaced cells stays, so
   complex facets and volumes stay. This removes slivers whose four vertices
   lie on the top and bottom of a thin layer. Then each cell still under
   the bound, worst first, with the cells around it (one to three rings of neighbours
   across facets not in the complex, in its region; for a cell under 10
   degrees that they leave above the bound, also the cells around each of
   its edges, split near the edge's middle) is replaced by the star
   of a new vertex placed in the kernel of that cavity (its centroid, the
   centroid of the cavity's vertices, and seeded random points around the
   best so far), if the new cells beat the cells they replace (larger
   smallest angle, no more cells under the bound). The cavity's boundary is
   kept, so complex facets, surface vertices and region volumes are too. This
   reaches the slivers with all four vertices on surfaces (across thin layers,
   between Steiner points of recovered surfaces), which step 1 cannot move.
   Cells with an edge on a complex facet that has an angle under 10 degrees
   are left: the surface forces them (the quality report counts them apart).
   Like step 3, it leaves a triangulation that is **no longer regular**; a
   later call skips steps 1 and 2 (the report says so) and runs step 4 again.

With `maximum_running_time` the result depends on the speed of the machine;
without it (the default), the same input and seed give the same mesh.

\tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3` over a
  `CGAL::Mesh_triangulation_3` (such as `Mesh_complex_3`): cells in the complex
  carry their region, facets on surfaces their patch, vertices on complex facets
  have dimension 2 (or less) and the others dimension 3.

\param c3t3 the mesh, changed in place
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{sliver_bound}
    \cgalParamDescription{a cell whose smallest dihedral angle (degrees) is under this is a sliver,
      for the perturbation and for the exuder}
    \cgalParamType{double}
    \cgalParamDefault{`15`: the report's headline threshold is 10 degrees; aiming a little higher
      leaves fewer cells just under 10, while a bound near 20 spends time on cells that are fine}
  \cgalParamNEnd
  \cgalParamNBegin{perturb_interior_vertices}
    \cgalParamDescription{whether step 1 runs}
    \cgalParamType{bool}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{exude_slivers}
    \cgalParamDescription{whether step 2 runs}
    \cgalParamType{bool}
    \cgalParamDefault{`false`: on the meshes of `tetrahedralize_bubbles()` (generated and GOCAD
      models) `exude_mesh_3()` changed complex facets every time, so the step was undone after
      running for up to its whole time budget (it keeps them on meshes without nearly flat cells)}
  \cgalParamNEnd
  \cgalParamNBegin{polish_interior}
    \cgalParamDescription{whether step 3 runs}
    \cgalParamType{bool}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_smoothing_passes}
    \cgalParamDescription{passes of a smoothing of all interior vertices after step 1: each vertex moves towards
      the optimal-Delaunay point of its star or the centroid of its neighbours (or half way) where that lowers the
      mean aspect ratio of the cells it changes, with no smaller dihedral angle and no more cells under the bound;
      moves are re-insertions checked like the perturbation's (step 1b; needs a regular triangulation)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{surface_vertex_supports}
    \cgalParamDescription{the Steiner points of the recovery and the input triangles under every surface
      vertex, as `tetrahedralize_bubbles()` fills them for this mesh; without it no Steiner point is
      collapsed. Not used after a step 2 or 3 that ran (it may swap in a copy of the triangulation)}
    \cgalParamType{`Surface_vertex_supports<C3T3::Triangulation>*`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{collapse_steiner_points}
    \cgalParamDescription{whether step 4 collapses Steiner points (needs `surface_vertex_supports`)}
    \cgalParamType{bool}
    \cgalParamDefault{the value of `flip_slivers`}
  \cgalParamNEnd
  \cgalParamNBegin{flip_slivers}
    \cgalParamDescription{whether the flips of step 4 run (before and after the insertion)}
    \cgalParamType{bool}
    \cgalParamDefault{the value of `perturb_interior_vertices`, like `insert_interior_vertices`}
  \cgalParamNEnd
  \cgalParamNBegin{insert_interior_vertices}
    \cgalParamDescription{whether step 4 runs}
    \cgalParamType{bool}
    \cgalParamDefault{the value of `perturb_interior_vertices`, so that switching the interior-vertex
      work off switches both steps off}
  \cgalParamNEnd
  \cgalParamNBegin{perturbation_radius_factor}
    \cgalParamDescription{largest move, as a fraction of the vertex's shortest incident edge}
    \cgalParamType{double}
    \cgalParamDefault{`0.3`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_perturbation_directions}
    \cgalParamDescription{seeded random positions tried per vertex and pass (step 1), and per cavity
      and search round (step 4)}
    \cgalParamType{unsigned int}
    \cgalParamDefault{`8`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{largest number of passes of step 1, and of step 4}
    \cgalParamType{std::size_t}
    \cgalParamDefault{`5`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{seed of the random positions}
    \cgalParamType{unsigned int}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_running_time}
    \cgalParamDescription{time budget in seconds for all steps (the perturbation may use 60 % of it
      when the exudation runs too); `0` means no limit. Set one when `exude_slivers` is on: the
      exuder's own running time has no bound}
    \cgalParamType{double}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{the report on `std::cout` at the end}
    \cgalParamType{bool}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what was done, with the smallest dihedral angle and the count of
  cells under the bound before and after each step (`Sliver_removal_report`)
*/
template <class C3T3, class NamedParameters = CGAL::parameters::Default_named_parameters>
Sliver_removal_report remove_slivers(C3T3& c3t3, const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle   Vertex_handle;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const double bound = choose_parameter(get_parameter(np, internal_np::sliver_bound), 15.);
  const bool perturb = choose_parameter(get_parameter(np, internal_np::perturb_interior_vertices), true);
  const bool exude = choose_parameter(get_parameter(np, internal_np::exude_slivers), false);
  const bool polish = choose_parameter(get_parameter(np, internal_np::polish_interior), false);
  const std::size_t smoothing_passes =
    choose_parameter(get_parameter(np, internal_np::number_of_smoothing_passes), std::size_t(0));
  const bool insert = choose_parameter(get_parameter(np, internal_np::insert_interior_vertices), perturb);
  const bool flip = choose_parameter(get_parameter(np, internal_np::flip_slivers), perturb);
  Surface_vertex_supports<Tr>* const supports =
    choose_parameter(get_parameter(np, internal_np::surface_vertex_supports), static_cast<Surface_vertex_supports<Tr>*>(nullptr));
  const bool collapse = supports != nullptr && choose_parameter(get_parameter(np, internal_np::collapse_steiner_points), flip);
  const double radius_factor = choose_parameter(get_parameter(np, internal_np::perturbation_radius_factor), 0.3);
  const unsigned int directions =
    choose_parameter(get_parameter(np, internal_np::number_of_perturbation_directions), 8u);
  const std::size_t passes = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 5);
  const unsigned int seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const double budget = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  // a progress line for each step: on a model with flat layers the whole stage ran 6 minutes
  const auto announce = internal::step_announcer(np, "sliver removal");
  const double limit = budget > 0. ? budget : std::numeric_limits<double>::infinity();
  // region volumes are sums of the same cells' volumes in another order
  const double volume_tolerance = 1e-9;

  CGAL::Real_timer total;
  total.start();
  Sliver_removal_report r;
  r.sliver_bound = bound;
  r.number_of_cells_before = c3t3.number_of_cells_in_complex();
  internal::Cell_set_quality q = internal::complex_quality(c3t3, bound);
  r.min_dihedral_angle_before = q.min_angle;
  r.number_of_slivers_before = q.under_bound;
  auto record = [&](double& angle, std::size_t& slivers) {
    q = internal::complex_quality(c3t3, bound);
    angle = q.min_angle;
    slivers = q.under_bound;
  };
  r.min_dihedral_angle_after_perturbation = r.min_dihedral_angle_before;
  r.number_of_slivers_after_perturbation = r.number_of_slivers_before;
  // Steps 2 and 3 are checked: kept if nothing that must stay changed and the
  // smallest angle (and for the polish the count under the bound) got no
  // worse than `r.*_after`, else undone from `backup`.
  auto keep_or_undo = [&](const internal::Complex_snapshot<C3T3>& snapshot, C3T3& backup, std::string broken,
                          bool count_must_not_grow, bool& done, bool& reverted, std::string& because) {
    internal::Cell_set_quality now;
    if(broken.empty()) broken = snapshot.broken(c3t3, volume_tolerance);
    if(broken.empty()) now = internal::complex_quality(c3t3, bound);
    if(broken.empty() && now.min_angle < r.min_dihedral_angle_after) broken = "smallest angle worse";
    if(broken.empty() && count_must_not_grow && now.under_bound > r.number_of_slivers_after)
      broken = "more cells under the bound";
    if(broken.empty())
    {
      done = true;
      r.min_dihedral_angle_after = now.min_angle;
      r.number_of_slivers_after = now.under_bound;
      return;
    }
    c3t3.swap(backup);
    // the copy's edge-facet counts are keyed by the other triangulation's vertices
    c3t3.clear_manifold_info();
    reverted = true;
    because = broken;
  };

  // steps 1 and 2 need the empty-sphere property, which steps 3 and 4 of an
  // earlier call may have taken away (the smoothing runs even with no sliver)
  const bool needs_regular = smoothing_passes > 0 || ((perturb || exude) && r.number_of_slivers_before > 0);
  const bool regular = !needs_regular || internal::is_regular_triangulation(c3t3.triangulation());
  r.skipped_not_regular = !regular;

  // 1. perturbation
  if(perturb && regular && r.number_of_slivers_before > 0)
  {
    announce("moving bubbles");
    CGAL::Real_timer timer;
    timer.start();
    internal::Interior_vertex_perturber<C3T3> perturber(c3t3, bound, radius_factor, directions, seed);
    const internal::Perturbation_statistics s = perturber(passes, exude ? 0.6 * limit : limit);
    r.perturbation_done = !s.skipped_nonzero_weights;
    r.perturbation_skipped_nonzero_weights = s.skipped_nonzero_weights;
    r.number_of_perturbation_passes = s.number_of_passes;
    r.number_of_vertices_tried = s.number_of_vertices_tried;
    r.number_of_moves = s.number_of_moves;
    r.number_of_vertices_moved = s.number_of_vertices_moved;
    r.number_of_candidates_rejected = s.number_of_candidates_rejected;
    r.time_limit_reached = s.time_limit_reached;
    record(r.min_dihedral_angle_after_perturbation, r.number_of_slivers_after_perturbation);
    r.time_perturbation = timer.time();
  }
  // 1b. smoothing of all interior vertices: each move keeps the smallest
  // angle and the count under the bound of what it changes
  if(smoothing_passes > 0 && regular)
  {
    CGAL::Real_timer timer;
    timer.start();
    internal::Interior_vertex_perturber<C3T3> smoother(c3t3, bound, radius_factor, directions, seed);
    const internal::Perturbation_statistics s = smoother.smooth(smoothing_passes, limit - total.time());
    r.number_of_smoothing_passes = s.number_of_passes;
    r.number_of_smoothing_moves = s.number_of_moves;
    if(s.time_limit_reached) r.time_limit_reached = true;
    record(r.min_dihedral_angle_after_perturbation, r.number_of_slivers_after_perturbation);
    r.time_smoothing = timer.time();
  }
  r.min_dihedral_angle_after = r.min_dihedral_angle_after_perturbation;
  r.number_of_slivers_after = r.number_of_slivers_after_perturbation;

  // 2. exudation, checked; a copy to go back to, since the exuder's own
  // guarantees are not part of its documentation
  if(exude && regular && r.number_of_slivers_after_perturbation > 0)
  {
    announce("exudation");
    CGAL::Real_timer timer;
    timer.start();
    const double left = limit - total.time();
    if(left <= 0.) r.time_limit_reached = true;
    else
    {
      const internal::Complex_snapshot<C3T3> snapshot(c3t3);
      C3T3 backup(c3t3);
      // exude_mesh_3 reads a time limit of 0 as "no limit"; with CGAL's
      // assertions on it can throw on meshes it was not made for
      std::string broken;
      try
      {
        r.exudation_code = CGAL::exude_mesh_3(c3t3, CGAL::parameters::sliver_bound = bound,
                                              CGAL::parameters::time_limit = (budget > 0. ? left : 0.));
      }
      catch(const std::exception& e)
      {
        broken = std::string("exude_mesh_3 failed: ") + e.what();
      }
      if(r.exudation_code == CGAL::TIME_LIMIT_REACHED) r.time_limit_reached = true;
      keep_or_undo(snapshot, backup, broken, false, r.exudation_done, r.exudation_reverted,
                   r.exudation_reverted_because);
    }
    r.time_exudation = timer.time();
  }
  r.min_dihedral_angle_after_exudation = r.min_dihedral_angle_after;
  r.number_of_slivers_after_exudation = r.number_of_slivers_after;

  // 3. polish, checked like the exudation and kept only if it helps
  if(polish && c3t3.number_of_cells_in_complex() > 0)
  {
    announce("polishing");
    CGAL::Real_timer timer;
    timer.start();
    if(limit - total.time() <= 0.) r.time_limit_reached = true;
    else
    {
      const internal::Complex_snapshot<C3T3> snapshot(c3t3);
      std::vector<std::pair<Vertex_handle, Vertex_handle> > old_edges;
      for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
      {
        std::pair<Vertex_handle, Vertex_handle> vv(e->first->vertex(e->second), e->first->vertex(e->third));
        if(vv.second < vv.first) std::swap(vv.first, vv.second);
        old_edges.push_back(vv);
      }
      std::vector<Vertex_handle> old_corners;
      for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
        old_corners.push_back(v);
      C3T3 backup(c3t3);

      const internal::Local_edge_length<Tr> sizing(c3t3.triangulation());
      std::string broken;
      try
      {
        CGAL::tetrahedral_isotropic_remeshing(c3t3, sizing,
                                              CGAL::parameters::remesh_boundaries(false).number_of_iterations(1));
      }
      catch(const std::exception& e)
      {
        broken = std::string("tetrahedral_isotropic_remeshing failed: ") + e.what();
      }
      // the remesher's own vertex labels go, ours come back, before the checks
      if(broken.empty()) internal::restore_vertex_labels(c3t3, snapshot, old_edges, old_corners);
      keep_or_undo(snapshot, backup, broken, true, r.polish_done, r.polish_reverted, r.polish_reverted_because);
    }
    r.time_polish = timer.time();
  }

  r.min_dihedral_angle_after_polish = r.min_dihedral_angle_after;
  r.number_of_slivers_after_polish = r.number_of_slivers_after;

  // 4. Steiner points collapsed, flips and insertion, for what no move
  // reached; flips again after the insertion, whose stars open new ones.
  // The supports name vertices of this triangulation: not after a step 2 or
  // 3 that ran (it may have swapped in a copy).
  auto count_steiner_points = [&]() {
    r.number_of_steiner_points_left = supports->number_of_steiner_points();
    r.number_of_triangles_split = supports->number_of_triangles_with_steiner_points();
  };
  if(supports) count_steiner_points();
  const bool may_collapse =
    collapse && !(r.exudation_done || r.exudation_reverted || r.polish_done || r.polish_reverted);
  auto collapses = [&]() -> std::size_t {
    if(!may_collapse || r.number_of_slivers_after == 0) return 0;
    std::size_t done = 0;
    CGAL::Real_timer timer;
    timer.start();
    const double left = limit - total.time();
    if(left <= 0.) r.time_limit_reached = true;
    else
    {
      internal::Steiner_point_collapser<C3T3, Surface_vertex_supports<Tr> > collapser(
        c3t3, *supports, bound, r.min_dihedral_angle_after);
      const internal::Collapse_statistics s = collapser(passes, left);
      r.collapses_done = true;
      r.number_of_steiner_points_collapsed += s.number_of_collapses;
      done = s.number_of_collapses;
      count_steiner_points();
      if(s.time_limit_reached) r.time_limit_reached = true;
      record(r.min_dihedral_angle_after, r.number_of_slivers_after);
    }
    r.time_collapses += timer.time();
    return done;
  };
  auto flips = [&]() {
    if(!flip || r.number_of_slivers_after == 0) return;
    CGAL::Real_timer timer;
    timer.start();
    const double left = limit - total.time();
    if(left <= 0.) r.time_limit_reached = true;
    else
    {
      internal::Sliver_flipper<C3T3> flipper(c3t3, bound);
      const internal::Flip_statistics s = flipper(passes, left);
      r.flips_done = true;
      r.number_of_2_3_flips += s.number_of_2_3_flips;
      r.number_of_edge_removals += s.number_of_edge_removals;
      if(s.time_limit_reached) r.time_limit_reached = true;
      record(r.min_dihedral_angle_after, r.number_of_slivers_after);
    }
    r.time_flips += timer.time();
  };
  // collapses and flips open each other's moves: alternate while collapses pay
  if((may_collapse || flip) && r.number_of_slivers_after > 0)
    announce(may_collapse ? "collapsing Steiner points and flipping" : "flipping");
  for(std::size_t round = 0; round < 3; ++round)
  {
    const std::size_t collapsed = collapses();
    flips();
    if(collapsed == 0) break;
  }
  r.min_dihedral_angle_after_flips = r.min_dihedral_angle_after;
  r.number_of_slivers_after_flips = r.number_of_slivers_after;
  if(insert && r.number_of_slivers_after > 0)
  {
    announce("inserting vertices");
    CGAL::Real_timer timer;
    timer.start();
    const double left = limit - total.time();
    if(left <= 0.) r.time_limit_reached = true;
    else
    {
      internal::Sliver_vertex_inserter<C3T3> inserter(c3t3, bound, directions, seed);
      const internal::Insertion_statistics s = inserter(passes, left);
      r.insertion_done = true;
      r.number_of_insertion_passes = s.number_of_passes;
      r.number_of_slivers_tried = s.number_of_slivers_tried;
      r.number_of_vertices_inserted = s.number_of_vertices_inserted;
      r.number_of_slivers_forced = s.number_of_slivers_forced;
      if(s.time_limit_reached) r.time_limit_reached = true;
      record(r.min_dihedral_angle_after, r.number_of_slivers_after);
    }
    r.time_insertion = timer.time();
    // the new vertices open collapses that were refused before
    collapses();
    flips();
  }

  r.number_of_cells_after = c3t3.number_of_cells_in_complex();
  r.time = total.time();
  if(verbose) std::cout << r << std::endl;
  return r;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_REMOVE_SLIVERS_H
