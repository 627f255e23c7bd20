// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_RECOVER_SURFACE_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_RECOVER_SURFACE_H

// Conforming surface recovery. All points are in one Delaunay triangulation;
// Steiner points are added on input edges and triangles (never elsewhere)
// until every input triangle is a union of triangulation facets.
//
// Edges first. A subsegment that is not a triangulation edge is split where
// the vertex that encroaches most upon it (largest angle, in its diametral
// ball) asks for, after Si's edge recovery in TetGen: at that vertex's
// distance from an input end of the subsegment if it lies on an edge or
// triangle leaving that end (both then lie on one sphere around the end and
// stop encroaching on each other), else at its projection (points on nearly
// parallel edges line up across the strip between them). When that is too
// close to an end, the split is at the "roundest" dyadic distance of the
// middle half from one end of the edge: a power of two next to an input
// vertex (Shewchuk's concentric shells), and the same distances on edges that
// leave a vertex at a small angle.
//
// Then triangles. A triangle is present when the triangulation's facets on it
// number as many as any triangulation of its points (b boundary points, i
// inner points: b + 2i - 2). Otherwise the 2D constrained Delaunay
// triangulation of its points gives a missing sub-facet; its circumcentre is
// inserted unless it lies outside the triangle or in the diametral ball of a
// subsegment, which is then split instead (as in Delaunay refinement).
//
// Rounded Steiner points are only nearly on their plane, so four points of
// one plane can make a flat cell: see surface_facets_on_triangle().
//
// Termination is enforced by a bound on the number of Steiner points and a
// lower bound on subsegment lengths: past them, the triangle or edge being
// recovered is named in a Tetrahedralization_error.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/union_find.h>
#include <CGAL/Bubble_mesh_3/internal/cocircular_weights.h>
#include <CGAL/Bubble_mesh_3/internal/near_coplanarity.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/centroid.h>
#include <CGAL/iterator.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

Thrown by `tetrahedralize_bubbles()` when the mesh cannot be built: an input
triangle or edge that cannot be recovered (its index, patch and coordinates
are in the message), two regions meeting where no input surface separates
them, or a Steiner point budget exceeded. No partial mesh is returned.
*/
class Tetrahedralization_error : public std::runtime_error
{
public:
  explicit Tetrahedralization_error(const std::string& what) : std::runtime_error(what) {}
};

namespace internal {

/// what a vertex of the triangulation is
enum class Vertex_kind : unsigned char
{
  input_point,    // model point `element`
  edge_point,     // Steiner point on input edge `element`
  triangle_point, // Steiner point inside input triangle `element`
  interior_point  // interior (bubble) point `element`
};

template <class Tr, class GeomTraits>
class Surface_recovery
{
public:
  typedef GeomTraits                         Geom_traits;
  typedef typename GeomTraits::Point_3       Point_3;
  typedef typename GeomTraits::Vector_3      Vector_3;
  typedef typename GeomTraits::Point_2       Point_2;
  typedef Geological_model_3<GeomTraits>     Model;
  typedef typename Tr::Weighted_point        Weighted_point;
  typedef typename Tr::Vertex_handle         Vertex_handle;
  typedef typename Tr::Cell_handle           Cell_handle;
  typedef typename Tr::Facet                 Facet;

  struct Vertex_record
  {
    Vertex_handle vh;
    Vertex_kind kind;
    std::size_t element; // see Vertex_kind
    double t;            // position on the input edge (0 at its first end) for edge points
  };

  struct Options
  {
    std::size_t maximum_number_of_steiner_points = 1000000;
    double minimum_split_length = 0.; // absolute
    bool verbose = false;
  };

private:
  // 2D constrained Delaunay triangulation of the points of one input triangle
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, GeomTraits>       Vb2;
  typedef CGAL::Constrained_triangulation_face_base_2<GeomTraits>                    Cfb2;
  typedef CGAL::Triangulation_face_base_with_info_2<int, GeomTraits, Cfb2>           Fb2;
  typedef CGAL::Triangulation_data_structure_2<Vb2, Fb2>                             Tds2;
  typedef CGAL::Constrained_Delaunay_triangulation_2<GeomTraits, Tds2, CGAL::Exact_predicates_tag> CDT;

  struct Subsegment { std::size_t edge, u, v; };

public:
  Surface_recovery(const Model& model, Tr& tr, const Options& options)
    : model_(model), tr_(tr), options_(options)
  {
    build_edges();
    build_plane_groups();
  }

  /// inserts the model points, then the `interior` points, in spatial order
  void insert_points(const std::vector<Point_3>& interior)
  {
    const std::size_t n_model = model_.number_of_points();
    std::vector<Point_3> pts;
    pts.reserve(n_model + interior.size());
    pts.insert(pts.end(), model_.points().begin(), model_.points().end());
    pts.insert(pts.end(), interior.begin(), interior.end());

    records_.resize(pts.size());
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      Vertex_record& r = records_[i];
      if(i < n_model) { r.kind = Vertex_kind::input_point; r.element = i; }
      else { r.kind = Vertex_kind::interior_point; r.element = i - n_model; }
      r.t = 0.;
    }

    // what CGAL's range insertion does, keeping the vertex of each point
    std::vector<std::size_t> order(pts.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    typedef CGAL::Spatial_sort_traits_adapter_3<GeomTraits,
              typename CGAL::Pointer_property_map<Point_3>::const_type> Sort_traits;
    const std::vector<Point_3>& cpts = pts;
    CGAL::spatial_sort(order.begin(), order.end(), Sort_traits(CGAL::make_property_map(cpts)));

    // tiny weights that give ties of cocircular input quads to the input's diagonals
    const std::vector<double> weights = cocircular_tie_weights(model_);
    Cell_handle hint;
    for(std::size_t i : order)
    {
      const std::size_t nv = tr_.number_of_vertices();
      Vertex_handle v = tr_.insert(Weighted_point(pts[i], i < n_model ? weights[i] : 0.), hint);
      if(v == Vertex_handle() || tr_.number_of_vertices() != nv + 1)
        throw Tetrahedralization_error(describe_point_kind(i) + " at " + to_string(pts[i]) +
                                       " coincides with another point");
      records_[i].vh = v;
      set_id(v, i);
      hint = v->cell();
    }
  }

  /// recovers all input edges and triangles; throws Tetrahedralization_error on failure
  void recover()
  {
    triangle_dirty_.assign(model_.number_of_triangles(), 1);
    edge_dirty_.assign(edge_ends_.size(), 1);
    CGAL::Real_timer timer;
    timer.start();
    for(std::size_t pass = 0;; ++pass)
    {
      // only what an insertion touched since its last check can have changed
      bool checked = false;
      for(std::size_t e = 0; e < edge_ends_.size(); ++e)
      {
        if(!edge_dirty_[e]) continue;
        edge_dirty_[e] = 0;
        checked = true;
        for(std::size_t k = 0; k + 1 < edge_points_[e].size(); ++k)
          queue_.push_back(Subsegment{e, edge_points_[e][k], edge_points_[e][k + 1]});
      }
      recover_queued_subsegments(no_index_);
      for(std::size_t t = 0; t < model_.number_of_triangles(); ++t)
      {
        if(!triangle_dirty_[t]) continue;
        checked = true;
        recover_triangle(t);
      }
      if(options_.verbose)
        std::cout << "  recovery pass " << pass << ": " << number_of_edge_points_ << " points on edges, "
                  << number_of_triangle_points_ << " on triangles (" << timer.time() << " s)" << std::endl;
      if(!checked) break;
    }
  }

  // ---- queries ---------------------------------------------------------------

  bool is_on_triangle(std::size_t id, std::size_t t) const
  {
    const Vertex_record& r = records_[id];
    switch(r.kind)
    {
    case Vertex_kind::input_point:
    {
      const auto& tri = model_.triangle(t);
      return tri[0] == r.element || tri[1] == r.element || tri[2] == r.element;
    }
    case Vertex_kind::edge_point:
      return triangle_edges_[t][0] == r.element || triangle_edges_[t][1] == r.element ||
             triangle_edges_[t][2] == r.element;
    case Vertex_kind::triangle_point:
      return r.element == t;
    default:
      return false;
    }
  }

  /// vertex ids on triangle `t`: its boundary in order (from its first
  /// corner, following its orientation), then its inner Steiner points
  void points_on_triangle(std::size_t t, std::vector<std::size_t>& out, std::size_t* boundary_size = nullptr) const
  {
    out.clear();
    const auto& tri = model_.triangle(t);
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t e = triangle_edges_[t][k];
      const std::vector<std::size_t>& l = edge_points_[e];
      if(edge_ends_[e][0] == tri[k])
        out.insert(out.end(), l.begin(), l.end() - 1);
      else
        out.insert(out.end(), l.rbegin(), l.rend() - 1);
    }
    if(boundary_size) *boundary_size = out.size();
    out.insert(out.end(), triangle_points_[t].begin(), triangle_points_[t].end());
  }

  /// the triangulation facets on triangle `t`, each once; returns their number
  std::size_t facets_on_triangle(std::size_t t, std::vector<Facet>* out) const
  {
    // walk from its boundary subsegments across the facets whose third vertex lies on it
    std::vector<std::size_t> pts;
    std::size_t nb = 0;
    points_on_triangle(t, pts, &nb);
    std::vector<std::pair<std::size_t, std::size_t> > stack;
    for(std::size_t i = 0; i < nb; ++i) stack.emplace_back(pts[i], pts[(i + 1) % nb]);
    std::unordered_set<std::uint64_t> seen;
    std::vector<std::pair<std::array<std::size_t, 3>, Facet> > found;
    while(!stack.empty())
    {
      std::pair<std::size_t, std::size_t> uv = stack.back();
      stack.pop_back();
      if(uv.first > uv.second) std::swap(uv.first, uv.second);
      if(!seen.insert((std::uint64_t(uv.first) << 32) | std::uint64_t(uv.second)).second) continue;
      const Vertex_handle vu = records_[uv.first].vh, vv = records_[uv.second].vh;
      Cell_handle c;
      int i, j;
      if(!tr_.is_edge(vu, vv, c, i, j)) continue;
      typename Tr::Facet_circulator fc = tr_.incident_facets(typename Tr::Edge(c, i, j)), done = fc;
      do
      {
        const Facet f = *fc;
        Vertex_handle w;
        for(int k = 0; k < 4; ++k)
        {
          const Vertex_handle x = f.first->vertex(k);
          if(k != f.second && x != vu && x != vv) w = x;
        }
        if(tr_.is_infinite(w)) continue;
        const std::size_t wid = id_of(w);
        if(!is_on_triangle(wid, t)) continue;
        std::array<std::size_t, 3> key = {{uv.first, uv.second, wid}};
        std::sort(key.begin(), key.end());
        if(!is_on_one_edge(key)) found.emplace_back(key, f); // else flat: it has no area
        stack.emplace_back(uv.first, wid);
        stack.emplace_back(uv.second, wid);
      } while(++fc != done);
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    found.erase(std::unique(found.begin(), found.end(),
                            [](const auto& a, const auto& b) { return a.first == b.first; }),
                found.end());
    if(out)
    {
      out->clear();
      for(const auto& f : found) out->push_back(f.second);
    }
    return found.size();
  }

  /// number of facets a triangulation of the points of triangle `t` has
  std::size_t expected_number_of_facets(std::size_t t) const
  {
    std::size_t boundary = 0;
    for(int k = 0; k < 3; ++k) boundary += edge_points_[triangle_edges_[t][k]].size() - 1;
    return boundary + 2 * triangle_points_[t].size() - 2;
  }

  /// a facet of the recovered surface on an input triangle
  struct Surface_facet
  {
    Facet facet;
    bool first_is_positive; ///< whether `facet.first` lies on the triangle's positive (normal) side
  };

  /*
  The facets of the recovered surface on triangle `t`; returns false if the
  flat cells around it cannot be put on one side (see below).

  Steiner points are rounded, so points on one plane are only nearly
  coplanar, and four nearly cocircular ones can make a flat cell whose four
  facets all lie on the plane (both diagonals of the quadrilateral). A cell is
  flat when its four vertices lie on one plane group (coplanar input
  triangles joined by vertices). The surface is the boundary between the
  cells below and above the plane (w.r.t. the group's normal); a flat cell is
  put outside the model when the whole group bounds it on one side (there,
  nothing on that side keeps the near-planar circumsphere of a flat cell from
  being empty, so flat cells are common on outer boundaries, and outside they
  leave no zero-volume tetrahedron in the mesh), else above; unless one of its
  facets spans several triangles of the group (such a facet cannot be a
  surface facet): then it goes to the side of the cell across that facet.
  */
  bool surface_facets_on_triangle(std::size_t t, std::vector<Surface_facet>& out) const
  {
    out.clear();
    std::vector<Facet> facets;
    facets_on_triangle(t, &facets);
    const std::size_t g = plane_group_[t];
    const auto& tri = model_.triangle(t);
    const Point_3& A = model_.point(tri[0]);
    const Point_3& B = model_.point(tri[1]);
    const Point_3& C = model_.point(tri[2]);
    const int sigma = triangle_normal(t) * group_normal_[g] > 0 ? 1 : -1;
    bool consistent = true;
    std::unordered_map<Cell_handle, int> color; // flat cells: +1 above, -1 below

    // +1 if the cell `c`, which is not flat, lies above the group's plane; `i`
    // is the index in `c` of the vertex opposite a facet on the plane. Exact
    // on the input triangle's corners and that vertex; an infinite cell lies
    // on the side away from the model.
    auto side_of = [&](Cell_handle c, int i) {
      CGAL::Orientation o;
      if(tr_.is_infinite(c)) o = CGAL::Orientation(-CGAL::orientation(A, B, C, centroid_));
      else o = CGAL::orientation(A, B, C, point(id_of(c->vertex(i))));
      if(o == CGAL::COPLANAR)
      {
        // a vertex on the plane that is not on the group: the facet's own orientation
        const Facet f(c, i);
        const Point_3 q0 = point(id_of(c->vertex(Tr::vertex_triple_index(i, 0))));
        const Point_3 q1 = point(id_of(c->vertex(Tr::vertex_triple_index(i, 1))));
        const Point_3 q2 = point(id_of(c->vertex(Tr::vertex_triple_index(i, 2))));
        o = CGAL::to_double(CGAL::cross_product(q1 - q0, q2 - q0) * triangle_normal(t)) > 0 ? CGAL::POSITIVE
                                                                                            : CGAL::NEGATIVE;
      }
      return int(o) * sigma;
    };
    auto flat_color = [&](Cell_handle c) {
      auto it = color.find(c);
      if(it != color.end()) return it->second;
      std::vector<Cell_handle> component(1, c);
      color[c] = 0;
      int forced = 0;
      for(std::size_t k = 0; k < component.size(); ++k)
      {
        const Cell_handle x = component[k];
        for(int i = 0; i < 4; ++i)
        {
          std::array<std::size_t, 3> ids;
          for(int j = 0; j < 3; ++j) ids[j] = id_of(x->vertex(Tr::vertex_triple_index(i, j)));
          // a facet on one triangle may separate x from its neighbour; one
          // across triangles or along one edge may not
          if(is_on_one_triangle(ids) && !is_on_one_edge(ids)) continue;
          const Cell_handle y = x->neighbor(i);
          if(is_flat(y, g))
          {
            if(color.emplace(y, 0).second) component.push_back(y);
            continue;
          }
          const int s = side_of(y, tr_.mirror_index(x, i));
          if(forced == 0) forced = s;
          else if(forced != s) consistent = false;
        }
      }
      const int final_color = forced != 0 ? forced : group_outside_[g] != 0 ? group_outside_[g] : 1;
      for(Cell_handle x : component) color[x] = final_color;
      return final_color;
    };

    for(const Facet& f : facets)
    {
      const Facet m = tr_.mirror_facet(f);
      const int c1 = is_flat(f.first, g) ? flat_color(f.first) : side_of(f.first, f.second);
      const int c2 = is_flat(m.first, g) ? flat_color(m.first) : side_of(m.first, m.second);
      if(c1 == c2) continue;
      out.push_back(Surface_facet{f, c1 * sigma > 0});
    }
    return consistent;
  }

  bool is_recovered(std::size_t t) const
  {
    std::vector<Surface_facet> facets;
    return surface_facets_on_triangle(t, facets) && facets.size() == expected_number_of_facets(t);
  }

  /// whether triangle `t` got no Steiner point (then it is a single facet)
  bool is_kept_whole(std::size_t t) const { return expected_number_of_facets(t) == 1; }

  // Mesh_3's vertices carry time stamps, unique among live vertices (none is
  // removed here): a vector indexed by them is a cheap, deterministic map.
  std::size_t id_of(Vertex_handle v) const
  {
    CGAL_assertion(v->time_stamp() < id_by_stamp_.size() && id_by_stamp_[v->time_stamp()] != no_index_);
    return id_by_stamp_[v->time_stamp()];
  }

  const std::vector<Vertex_record>& records() const { return records_; }
  std::size_t number_of_edge_points() const { return number_of_edge_points_; }
  std::size_t number_of_triangle_points() const { return number_of_triangle_points_; }
  std::size_t number_of_edges() const { return edge_ends_.size(); }
  /// the input edges: pairs of model point indices, first < second
  const std::vector<std::array<std::size_t, 2> >& edge_ends() const { return edge_ends_; }
  /// one input triangle having edge `e`
  std::size_t triangle_of_edge(std::size_t e) const { return edge_triangles_[edge_triangles_start_[e]]; }

  /// the input triangles whose closure holds vertex `id` (none for an interior point)
  std::pair<const std::size_t*, const std::size_t*> support(std::size_t id) const
  {
    const Vertex_record& r = records_[id];
    switch(r.kind)
    {
    case Vertex_kind::input_point:
      return std::make_pair(point_triangles_.data() + point_triangles_start_[r.element],
                            point_triangles_.data() + point_triangles_start_[r.element + 1]);
    case Vertex_kind::edge_point:
      return std::make_pair(edge_triangles_.data() + edge_triangles_start_[r.element],
                            edge_triangles_.data() + edge_triangles_start_[r.element + 1]);
    case Vertex_kind::triangle_point:
      return std::make_pair(&r.element, &r.element + 1);
    default:
      return std::make_pair(&r.element, &r.element);
    }
  }

  /// the plane group of triangle `t` (coplanar input triangles joined by vertices)
  std::size_t plane_group(std::size_t t) const { return plane_group_[t]; }
  /// the normal of group `g` (of its first triangle, not normalised)
  const Vector_3& group_normal(std::size_t g) const { return group_normal_[g]; }
  /// +1 / -1 when the model's outside lies above / below every triangle of group `g`, else 0
  int group_outside(std::size_t g) const { return group_outside_[g]; }

  Vector_3 triangle_normal(std::size_t t) const
  {
    const auto& tri = model_.triangle(t);
    return CGAL::cross_product(model_.point(tri[1]) - model_.point(tri[0]),
                               model_.point(tri[2]) - model_.point(tri[0]));
  }

  /// whether vertex `id` lies on a triangle of plane group `g`
  bool is_on_group(std::size_t id, std::size_t g) const
  {
    const Vertex_record& r = records_[id];
    switch(r.kind)
    {
    case Vertex_kind::input_point:
      for(std::size_t k = point_triangles_start_[r.element]; k < point_triangles_start_[r.element + 1]; ++k)
        if(plane_group_[point_triangles_[k]] == g) return true;
      return false;
    case Vertex_kind::edge_point:
      for(std::size_t k = edge_triangles_start_[r.element]; k < edge_triangles_start_[r.element + 1]; ++k)
        if(plane_group_[edge_triangles_[k]] == g) return true;
      return false;
    case Vertex_kind::triangle_point:
      return plane_group_[r.element] == g;
    default:
      return false;
    }
  }

  /// whether the four vertices of `c` lie on plane group `g`
  bool is_flat(Cell_handle c, std::size_t g) const
  {
    for(int i = 0; i < 4; ++i)
      if(tr_.is_infinite(c->vertex(i)) || !is_on_group(id_of(c->vertex(i)), g)) return false;
    return true;
  }

  /// whether vertex `id` lies on input edge `e`
  bool is_on_edge(std::size_t id, std::size_t e) const
  {
    const Vertex_record& r = records_[id];
    if(r.kind == Vertex_kind::edge_point) return r.element == e;
    return r.kind == Vertex_kind::input_point && (r.element == edge_ends_[e][0] || r.element == edge_ends_[e][1]);
  }

  /// whether three vertices lie on one input edge (then they are collinear)
  bool is_on_one_edge(const std::array<std::size_t, 3>& ids) const
  {
    for(std::size_t k = 0; k < 3; ++k)
    {
      const Vertex_record& r = records_[ids[k]];
      if(r.kind != Vertex_kind::edge_point) continue;
      return is_on_edge(ids[0], r.element) && is_on_edge(ids[1], r.element) && is_on_edge(ids[2], r.element);
    }
    // three input points: collinear only if degenerate, which the model excludes
    return false;
  }

  /// whether three vertices lie on one input triangle
  bool is_on_one_triangle(const std::array<std::size_t, 3>& ids) const
  {
    const Vertex_record& r = records_[ids[0]];
    auto on_all = [&](std::size_t t) { return is_on_triangle(ids[1], t) && is_on_triangle(ids[2], t); };
    switch(r.kind)
    {
    case Vertex_kind::input_point:
      for(std::size_t k = point_triangles_start_[r.element]; k < point_triangles_start_[r.element + 1]; ++k)
        if(on_all(point_triangles_[k])) return true;
      return false;
    case Vertex_kind::edge_point:
      for(std::size_t k = edge_triangles_start_[r.element]; k < edge_triangles_start_[r.element + 1]; ++k)
        if(on_all(edge_triangles_[k])) return true;
      return false;
    case Vertex_kind::triangle_point:
      return on_all(r.element);
    default:
      return false;
    }
  }

  /// a readable description of triangle `t`: index, patch, corners
  std::string describe_triangle(std::size_t t) const
  {
    const auto& tri = model_.triangle(t);
    std::string s = model_.where(model_.triangle_source(t)) + "triangle " + std::to_string(t) + " of " +
                    model_.patch_label(model_.patch_of_triangle(t)) + " (";
    for(int k = 0; k < 3; ++k)
      s += (k ? ", " : "") + to_string(model_.point(tri[k]));
    return s + ")";
  }

  static std::string to_string(const Point_3& p)
  {
    std::ostringstream os;
    os.precision(17);
    os << "(" << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " " << CGAL::to_double(p.z()) << ")";
    return os.str();
  }

private:
  static constexpr std::size_t no_index_ = std::size_t(-1);

  // What is being recovered: an input triangle, else (no_index_) an input edge. For
  // error messages, described only when one is thrown: describing every triangle
  // cost 1.4 % of a whole CloudSpin run.
  struct Recovering
  {
    std::size_t triangle, edge;
  };

  // ---- input edges -----------------------------------------------------------

  void build_edges()
  {
    const std::size_t nt = model_.number_of_triangles();
    std::vector<std::pair<std::uint64_t, std::size_t> > half; // (key, 3 t + k)
    half.reserve(3 * nt);
    for(std::size_t t = 0; t < nt; ++t)
    {
      const auto& tri = model_.triangle(t);
      if(tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0] ||
         CGAL::collinear(model_.point(tri[0]), model_.point(tri[1]), model_.point(tri[2])))
        throw Tetrahedralization_error("degenerate input: " + describe_triangle(t) + " has no area");
      for(int k = 0; k < 3; ++k)
        half.emplace_back(key(tri[k], tri[(k + 1) % 3]), 3 * t + k);
    }
    std::sort(half.begin(), half.end());
    triangle_edges_.assign(nt, {{0, 0, 0}});
    for(std::size_t i = 0; i < half.size();)
    {
      std::size_t j = i;
      const std::size_t e = edge_ends_.size();
      const std::size_t t0 = half[i].second / 3;
      const int k0 = int(half[i].second % 3);
      const std::size_t a = model_.triangle(t0)[k0], b = model_.triangle(t0)[(k0 + 1) % 3];
      edge_ends_.push_back({{(std::min)(a, b), (std::max)(a, b)}});
      edge_triangles_start_.push_back(edge_triangles_.size());
      while(j < half.size() && half[j].first == half[i].first)
      {
        triangle_edges_[half[j].second / 3][half[j].second % 3] = e;
        edge_triangles_.push_back(half[j].second / 3);
        ++j;
      }
      edge_index_.emplace(half[i].first, e);
      i = j;
    }
    edge_triangles_start_.push_back(edge_triangles_.size());
    edge_points_.resize(edge_ends_.size());
    for(std::size_t e = 0; e < edge_ends_.size(); ++e)
      edge_points_[e] = {edge_ends_[e][0], edge_ends_[e][1]}; // model point index = vertex id
    triangle_points_.resize(nt);
  }

  // Coplanar triangles (up to rounding) that share a vertex are in one plane group
  // (union-find); the group's normal is that of its first triangle.
  void build_plane_groups()
  {
    const std::size_t np = model_.number_of_points(), nt = model_.number_of_triangles();
    centroid_ = CGAL::centroid(model_.points().begin(), model_.points().end(), CGAL::Dimension_tag<0>());
    point_triangles_start_.assign(np + 1, 0);
    for(std::size_t t = 0; t < nt; ++t)
      for(std::size_t v : model_.triangle(t)) ++point_triangles_start_[v + 1];
    for(std::size_t i = 0; i < np; ++i) point_triangles_start_[i + 1] += point_triangles_start_[i];
    point_triangles_.resize(3 * nt);
    std::vector<std::size_t> fill(point_triangles_start_.begin(), point_triangles_start_.end() - 1);
    for(std::size_t t = 0; t < nt; ++t)
      for(std::size_t v : model_.triangle(t)) point_triangles_[fill[v]++] = t;

    // coplanar up to the rounding of their points (near_coplanarity.h)
    const double tolerance = coplanarity_tolerance(model_);
    std::vector<std::size_t> parent = uf_singletons(nt);
    for(std::size_t v = 0; v < np; ++v)
      for(std::size_t i = point_triangles_start_[v]; i < point_triangles_start_[v + 1]; ++i)
        for(std::size_t j = i + 1; j < point_triangles_start_[v + 1]; ++j)
        {
          const std::size_t t1 = point_triangles_[i], t2 = point_triangles_[j];
          if(uf_find(parent, t1) == uf_find(parent, t2)) continue;
          if(are_nearly_coplanar(model_, t1, t2, tolerance)) uf_union(parent, t1, t2);
        }
    plane_group_.assign(nt, 0);
    std::vector<std::size_t> group_of_root(nt, std::size_t(-1));
    for(std::size_t t = 0; t < nt; ++t)
    {
      std::size_t& g = group_of_root[uf_find(parent, t)];
      if(g == std::size_t(-1))
      {
        g = group_normal_.size();
        group_normal_.push_back(triangle_normal(t));
        group_outside_.push_back(2); // not known yet
      }
      plane_group_[t] = g;
      // the side (w.r.t. the group's normal) where the model's outside is, if
      // every triangle of the group has it on that same side
      const auto& patch = model_.patch(model_.patch_of_triangle(t));
      const int along = triangle_normal(t) * group_normal_[g] > 0 ? 1 : -1;
      const int outside = patch.positive_region == 0 && patch.negative_region != 0   ? along
                          : patch.negative_region == 0 && patch.positive_region != 0 ? -along
                                                                                    : 0;
      int& o = group_outside_[g];
      o = (o == 2 || o == outside) ? outside : 0;
    }

    // for each edge end, the sine of the smallest angle to another edge there
    // (1 from 90 degrees on)
    std::vector<std::size_t>& start = point_edges_start_;
    std::vector<std::size_t>& incident = point_edges_;
    start.assign(np + 1, 0);
    incident.resize(2 * edge_ends_.size());
    for(const auto& e : edge_ends_) { ++start[e[0] + 1]; ++start[e[1] + 1]; }
    for(std::size_t i = 0; i < np; ++i) start[i + 1] += start[i];
    std::vector<std::size_t> pos(start.begin(), start.end() - 1);
    for(std::size_t e = 0; e < edge_ends_.size(); ++e)
    {
      incident[pos[edge_ends_[e][0]]++] = e;
      incident[pos[edge_ends_[e][1]]++] = e;
    }
    end_closeness_.assign(edge_ends_.size(), {{1., 1.}});
    for(std::size_t v = 0; v < np; ++v)
      for(std::size_t i = start[v]; i < start[v + 1]; ++i)
        for(std::size_t j = i + 1; j < start[v + 1]; ++j)
        {
          const std::size_t e1 = incident[i], e2 = incident[j];
          const int k1 = edge_ends_[e1][0] == v ? 0 : 1, k2 = edge_ends_[e2][0] == v ? 0 : 1;
          const Vector_3 u = model_.point(edge_ends_[e1][1 - k1]) - model_.point(v);
          const Vector_3 w = model_.point(edge_ends_[e2][1 - k2]) - model_.point(v);
          const double cos = CGAL::to_double(u * w);
          const double sin = std::sqrt(CGAL::to_double(CGAL::cross_product(u, w).squared_length()));
          const double closeness = cos <= 0. ? 1. : sin / std::sqrt(sin * sin + cos * cos);
          end_closeness_[e1][k1] = (std::min)(end_closeness_[e1][k1], closeness);
          end_closeness_[e2][k2] = (std::min)(end_closeness_[e2][k2], closeness);
        }
  }

  std::uint64_t key(std::size_t a, std::size_t b) const
  {
    if(a > b) std::swap(a, b);
    return std::uint64_t(a) * std::uint64_t(model_.number_of_points()) + std::uint64_t(b);
  }

  double parameter(std::size_t e, std::size_t id) const
  {
    if(id == edge_ends_[e][0]) return 0.;
    if(id == edge_ends_[e][1]) return 1.;
    return records_[id].t;
  }

  // position of vertex `id` in the point list of edge `e`, or no_index_
  std::size_t position(std::size_t e, std::size_t id) const
  {
    const std::vector<std::size_t>& l = edge_points_[e];
    if(id == l.front()) return 0;
    if(id == l.back()) return l.size() - 1;
    const Vertex_record& r = records_[id];
    if(r.kind != Vertex_kind::edge_point || r.element != e) return no_index_;
    auto it = std::lower_bound(l.begin() + 1, l.end() - 1, r.t,
                               [this](std::size_t a, double t) { return records_[a].t < t; });
    return (it != l.end() - 1 && *it == id) ? std::size_t(it - l.begin()) : no_index_;
  }

  /// if (u,v) is a subsegment, its edge and the position of its first end
  bool is_subsegment(std::size_t u, std::size_t v, std::size_t& e, std::size_t& pos) const
  {
    const Vertex_record& ru = records_[u];
    const Vertex_record& rv = records_[v];
    if(ru.kind == Vertex_kind::edge_point) e = ru.element;
    else if(rv.kind == Vertex_kind::edge_point) e = rv.element;
    else if(ru.kind == Vertex_kind::input_point && rv.kind == Vertex_kind::input_point)
    {
      auto it = edge_index_.find(key(u, v));
      if(it == edge_index_.end()) return false;
      e = it->second;
    }
    else
      return false;
    const std::size_t pu = position(e, u), pv = position(e, v);
    if(pu == no_index_ || pv == no_index_) return false;
    if(pu + 1 == pv) { pos = pu; return true; }
    if(pv + 1 == pu) { pos = pv; return true; }
    return false;
  }

  bool is_edge(std::size_t u, std::size_t v) const
  {
    Cell_handle c;
    int i, j;
    return tr_.is_edge(records_[u].vh, records_[v].vh, c, i, j);
  }

  // ---- Steiner points --------------------------------------------------------

  void mark_dirty(std::size_t id)
  {
    const Vertex_record& r = records_[id];
    switch(r.kind)
    {
    case Vertex_kind::input_point:
      for(std::size_t k = point_triangles_start_[r.element]; k < point_triangles_start_[r.element + 1]; ++k)
        triangle_dirty_[point_triangles_[k]] = 1;
      for(std::size_t k = point_edges_start_[r.element]; k < point_edges_start_[r.element + 1]; ++k)
        edge_dirty_[point_edges_[k]] = 1;
      break;
    case Vertex_kind::edge_point:
      for(std::size_t k = edge_triangles_start_[r.element]; k < edge_triangles_start_[r.element + 1]; ++k)
        triangle_dirty_[edge_triangles_[k]] = 1;
      edge_dirty_[r.element] = 1;
      break;
    case Vertex_kind::triangle_point:
      triangle_dirty_[r.element] = 1;
      break;
    default:
      break;
    }
  }

  void set_id(Vertex_handle v, std::size_t id)
  {
    const std::size_t ts = v->time_stamp();
    if(ts >= id_by_stamp_.size()) id_by_stamp_.resize((std::max)(2 * id_by_stamp_.size(), ts + 1), no_index_);
    id_by_stamp_[ts] = id;
  }

  /*
  A Steiner point is rounded, so on the model's outer boundary it may land a
  hair outside the model. On a planar part of the convex hull such a point
  lifts a tent of flat cells over the plane whose facets span several input
  triangles, on the outside as well as the inside, and no refinement removes
  it (each split adds such points). So a point that lies outside a plane group
  the model's outside bounds on one side is moved by ulps into the model: a
  few ulps at most, far below the tolerance of points on their element.
  */
  Point_3 rounded_into_model(const Point_3& p, Vertex_kind kind, std::size_t element) const
  {
    std::vector<std::size_t> outer; // triangles of outer plane groups the point lies on
    auto consider = [&](std::size_t t) {
      const int o = group_outside_[plane_group_[t]];
      if(o == 1 || o == -1) outer.push_back(t);
    };
    if(kind == Vertex_kind::triangle_point) consider(element);
    else
      for(std::size_t k = edge_triangles_start_[element]; k < edge_triangles_start_[element + 1]; ++k)
        consider(edge_triangles_[k]);
    if(outer.empty()) return p;
    std::array<double, 3> c = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    // a coordinate an axis plane of the point holds exactly stays as it is
    std::array<bool, 3> fixed = {{false, false, false}};
    for(std::size_t t : outer)
    {
      const Vector_3& n = group_normal_[plane_group_[t]];
      for(int i = 0; i < 3; ++i)
        if(n[(i + 1) % 3] == 0 && n[(i + 2) % 3] == 0) fixed[i] = true;
    }
    // each step moves the free coordinates by one ulp along the inward
    // normals of the planes the point is outside of, which brings it
    // strictly closer to their inside
    for(int step = 0; step < 64; ++step)
    {
      const Point_3 q(c[0], c[1], c[2]);
      std::array<double, 3> inward = {{0., 0., 0.}};
      for(std::size_t t : outer)
      {
        const std::size_t g = plane_group_[t];
        const auto& tri = model_.triangle(t);
        const int sigma = triangle_normal(t) * group_normal_[g] > 0 ? 1 : -1;
        const int side =
          int(CGAL::orientation(model_.point(tri[0]), model_.point(tri[1]), model_.point(tri[2]), q)) * sigma;
        if(side != group_outside_[g]) continue;
        const Vector_3& n = group_normal_[g];
        const double l = std::sqrt(CGAL::to_double(n.squared_length()));
        for(int i = 0; i < 3; ++i) inward[i] -= group_outside_[g] * CGAL::to_double(n[i]) / l;
      }
      bool moved = false;
      for(int i = 0; i < 3; ++i)
        if(inward[i] != 0. && !fixed[i])
        {
          c[i] = std::nextafter(c[i], inward[i] > 0. ? std::numeric_limits<double>::infinity()
                                                     : -std::numeric_limits<double>::infinity());
          moved = true;
        }
      if(!moved) break;
    }
    return Point_3(c[0], c[1], c[2]);
  }

  std::size_t insert_steiner_point(const Point_3& p, Vertex_kind kind, std::size_t element, double t,
                                   Cell_handle hint, const Recovering& context)
  {
    if(number_of_edge_points_ + number_of_triangle_points_ >= options_.maximum_number_of_steiner_points)
      throw Tetrahedralization_error("surface recovery needs more than " +
                                     std::to_string(options_.maximum_number_of_steiner_points) +
                                     " Steiner points (maximum_number_of_steiner_points), while recovering " +
                                     describe(context));
    const Weighted_point wp(rounded_into_model(p, kind, element));
    typename Tr::Locate_type lt;
    int li, lj;
    const Cell_handle c = tr_.locate(wp, lt, li, lj, hint);
    if(lt == Tr::VERTEX)
      throw Tetrahedralization_error("a Steiner point at " + to_string(p) +
                                     " falls on an existing vertex (numerical limit) while recovering " + describe(context));
    std::vector<Facet> boundary;
    std::vector<Cell_handle> conflict;
    tr_.find_conflicts(wp, c, std::back_inserter(boundary), std::back_inserter(conflict), CGAL::Emptyset_iterator());
    // the edges and triangles whose facets may change
    for(Cell_handle x : conflict)
      for(int i = 0; i < 4; ++i)
        if(!tr_.is_infinite(x->vertex(i))) mark_dirty(id_of(x->vertex(i)));
    const Vertex_handle v = tr_.insert_in_hole(wp, conflict.begin(), conflict.end(), boundary.front().first,
                                               boundary.front().second);
    const std::size_t id = records_.size();
    records_.push_back(Vertex_record{v, kind, element, t});
    set_id(v, id);
    if(kind == Vertex_kind::edge_point) ++number_of_edge_points_;
    else ++number_of_triangle_points_;
    return id;
  }

  std::string describe(const Recovering& r) const
  {
    return r.triangle != no_index_ ? describe_triangle(r.triangle) : describe_edge(r.edge);
  }

  std::string describe_edge(std::size_t e) const
  {
    return "input edge " + to_string(model_.point(edge_ends_[e][0])) + " - " +
           to_string(model_.point(edge_ends_[e][1])) + " of " + describe_triangle(triangle_of_edge(e));
  }

  /// splits the subsegment of `e` that starts at position `pos`; returns the new vertex id
  std::size_t split_subsegment(std::size_t e, std::size_t pos, const Recovering& context,
                               std::size_t reference = no_index_)
  {
    std::vector<std::size_t>& l = edge_points_[e];
    const std::size_t u = l[pos], v = l[pos + 1];
    const Point_3& a = model_.point(edge_ends_[e][0]);
    const Point_3& b = model_.point(edge_ends_[e][1]);
    const double length = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
    const double tu = parameter(e, u), tv = parameter(e, v);
    const double sub = (tv - tu) * length;
    if(!(sub >= 2. * options_.minimum_split_length))
      throw Tetrahedralization_error("cannot recover " + describe(context) + ": " + describe_edge(e) +
                                     " would be split below minimum_split_length near " +
                                     to_string(tr_.geom_traits().construct_point_3_object()(tr_.point(records_[u].vh))));
    // Distances from one end of the edge, split at the "roundest" dyadic
    // distance of the middle half: next to an input vertex, a power of two
    // (concentric shells); further on, points on edges that leave the same
    // vertex at a small angle land at the same distances from it, so that they
    // stop encroaching on each other. The end is the one whose nearest other
    // edge is closer at the subsegment (distance times sine of the angle):
    // the apex of a needle triangle serves its whole length.
    const double tm = 0.5 * (tu + tv);
    const bool from_a = tm * end_closeness_[e][0] <= (1. - tm) * end_closeness_[e][1];
    const double s1 = from_a ? tu * length : (1. - tv) * length;
    const double s2 = from_a ? tv * length : (1. - tu) * length;
    double t = reference == no_index_ ? -1. : reference_parameter(e, pos, reference, length);
    if(t < 0.)
    {
      const double d = roundest_dyadic(s1 + 0.25 * sub, s2 - 0.25 * sub);
      t = from_a ? d / length : 1. - d / length;
    }
    const double ax = CGAL::to_double(a.x()), ay = CGAL::to_double(a.y()), az = CGAL::to_double(a.z());
    const Point_3 p(ax + t * (CGAL::to_double(b.x()) - ax),
                    ay + t * (CGAL::to_double(b.y()) - ay),
                    az + t * (CGAL::to_double(b.z()) - az));
    const std::size_t id = insert_steiner_point(p, Vertex_kind::edge_point, e, t, records_[u].vh->cell(), context);
    l.insert(l.begin() + pos + 1, id);
    queue_.push_back(Subsegment{e, u, id});
    queue_.push_back(Subsegment{e, id, v});
    return id;
  }

  /*
  Where the vertex `r` that keeps subsegment `pos` of edge `e` out of the
  triangulation asks for the split (after Si's edge recovery in TetGen), or -1
  if that is too close to an end (then the dyadic rule applies):
  - `r` lies on an input edge or triangle that leaves an input end of the
    subsegment: at the distance of `r` from that end, so that both lie on one
    sphere around it and stop encroaching on each other;
  - otherwise at the projection of `r`: points on nearly parallel edges line
    up across the thin strip between them instead of refining it to its width.
  */
  double reference_parameter(std::size_t e, std::size_t pos, std::size_t r, double length) const
  {
    const std::vector<std::size_t>& l = edge_points_[e];
    const std::size_t u = l[pos], v = l[pos + 1];
    const double tu = parameter(e, u), tv = parameter(e, v);
    const Point_3 pr = point(r), pu = point(u), pv = point(v);
    const double sub = (tv - tu) * length;
    auto inside = [&](double t) { return t > tu + 0.1 * (tv - tu) && t < tv - 0.1 * (tv - tu); };
    for(int k = 0; k < 2; ++k)
    {
      const bool end_is_input = k == 0 ? pos == 0 : pos + 2 == l.size();
      if(!end_is_input || !leaves(r, k == 0 ? u : v)) continue;
      const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(k == 0 ? pu : pv, pr)));
      const double t = k == 0 ? tu + (tv - tu) * d / sub : tv - (tv - tu) * d / sub;
      if(inside(t)) return t;
    }
    const double lambda = CGAL::to_double((pr - pu) * (pv - pu)) / CGAL::to_double((pv - pu).squared_length());
    const double t = tu + lambda * (tv - tu);
    return inside(t) ? t : -1.;
  }

  /// whether vertex `r` lies on an input edge or triangle that has model point `w` as a corner
  bool leaves(std::size_t r, std::size_t w) const
  {
    const Vertex_record& rr = records_[r];
    switch(rr.kind)
    {
    case Vertex_kind::input_point: return edge_index_.count(key(w, rr.element)) != 0;
    case Vertex_kind::edge_point: return edge_ends_[rr.element][0] == w || edge_ends_[rr.element][1] == w;
    case Vertex_kind::triangle_point:
    {
      const auto& tri = model_.triangle(rr.element);
      return tri[0] == w || tri[1] == w || tri[2] == w;
    }
    default: return false;
    }
  }

  /// the vertex in the closed diametral ball of (u, v) that sees it under the largest angle, or no_index_
  std::size_t encroaching_vertex(std::size_t u, std::size_t v) const
  {
    const Point_3 pu = point(u), pv = point(v);
    std::size_t best = no_index_;
    double best_cos = 2.;
    auto side = tr_.geom_traits().side_of_bounded_sphere_3_object();
    auto consider = [&](Cell_handle c) {
      for(int i = 0; i < 4; ++i)
      {
        const Vertex_handle x = c->vertex(i);
        if(tr_.is_infinite(x) || x == records_[u].vh || x == records_[v].vh) continue;
        const std::size_t id = id_of(x);
        const Point_3 px = point(id);
        if(side(pu, pv, px) == CGAL::ON_UNBOUNDED_SIDE) continue;
        const Vector_3 a = pu - px, b = pv - px;
        const double cos = CGAL::to_double(a * b) / std::sqrt(CGAL::to_double(a.squared_length() * b.squared_length()));
        if(cos < best_cos || (cos == best_cos && id < best)) { best_cos = cos; best = id; }
      }
    };
    // the cells that meet the segment (CGAL 5.5's segment traverser does not
    // take weighted points): from those around u, across facets
    const typename Geom_traits::Segment_3 segment(pu, pv);
    std::vector<Cell_handle> stack;
    tr_.incident_cells(records_[u].vh, std::back_inserter(stack));
    std::unordered_set<Cell_handle> seen(stack.begin(), stack.end());
    while(!stack.empty())
    {
      const Cell_handle c = stack.back();
      stack.pop_back();
      consider(c);
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle n = c->neighbor(i);
        if(tr_.is_infinite(n) || !seen.insert(n).second) continue;
        const typename Geom_traits::Tetrahedron_3 tet(point(id_of(n->vertex(0))), point(id_of(n->vertex(1))),
                                                      point(id_of(n->vertex(2))), point(id_of(n->vertex(3))));
        if(CGAL::do_intersect(tet, segment)) stack.push_back(n);
      }
    }
    return best;
  }

  // the number m 2^k in [lo, hi] (0 <= lo < hi) with the largest k
  static double roundest_dyadic(double lo, double hi)
  {
    for(int k = std::ilogb(hi);; --k)
    {
      const double step = std::ldexp(1., k);
      const double m = std::ceil(lo / step);
      if(m * step <= hi) return m * step;
    }
  }

  void recover_queued_subsegments(std::size_t triangle)
  {
    while(!queue_.empty())
    {
      const Subsegment s = queue_.front();
      queue_.pop_front();
      const std::size_t pu = position(s.edge, s.u);
      if(pu == no_index_ || pu + 1 >= edge_points_[s.edge].size() || edge_points_[s.edge][pu + 1] != s.v)
        continue; // split meanwhile
      if(is_edge(s.u, s.v)) continue;
      split_subsegment(s.edge, pu, Recovering{triangle, s.edge}, encroaching_vertex(s.u, s.v));
    }
  }

  // ---- triangles -------------------------------------------------------------

  void recover_triangle(std::size_t t)
  {
    const auto& tri = model_.triangle(t);
    const Point_3& A = model_.point(tri[0]);
    const Point_3& B = model_.point(tri[1]);
    const Point_3& C = model_.point(tri[2]);
    // an orthonormal frame of the triangle's plane, origin at A
    const Vector_3 ab = B - A, ac = C - A;
    const Vector_3 n = CGAL::cross_product(ab, ac);
    const Vector_3 e1 = ab / std::sqrt(CGAL::to_double(ab.squared_length()));
    Vector_3 e2 = CGAL::cross_product(n, e1);
    e2 = e2 / std::sqrt(CGAL::to_double(e2.squared_length()));
    // the circumcentre of a face of the triangle's 2D triangulation, in 3D
    auto circumcentre_3d = [&](const auto& f) {
      const Point_2 c = CGAL::circumcenter(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      return std::make_pair(c, Point_3(A + CGAL::to_double(c.x()) * e1 + CGAL::to_double(c.y()) * e2));
    };
    auto to_2d = [&](const Point_3& p) {
      const Vector_3 d = p - A;
      return Point_2(d * e1, d * e2);
    };
    const std::array<Point_2, 3> corner = {{Point_2(0, 0), to_2d(B), to_2d(C)}};
    const double area2 = CGAL::to_double(CGAL::area(corner[0], corner[1], corner[2]));
    auto barycentric = [&](const Point_2& p) {
      std::array<double, 3> l;
      for(int k = 0; k < 3; ++k)
        l[k] = CGAL::to_double(CGAL::area(p, corner[(k + 1) % 3], corner[(k + 2) % 3])) / area2;
      return l;
    };
    const Recovering context{t, no_index_};

    std::vector<std::size_t> pts;
    std::vector<Point_3> pts3;
    std::vector<Cell_handle> conflict;
    const int maximum_fold_splits = 64;
    int fold_splits = 0;
    // Rounded Steiner points can keep a triangle from ever being recovered (on a
    // wall off the axis planes, each new point may bring new flat cells): past
    // this many insertions (and four per sub-facet missing then: the largest
    // one halves once the others of its size are split) with neither fewer missing
    // sub-facets nor a largest one half as wide, it is named in an error
    // rather than refined without end. Smaller counts as progress because of
    // bubbles: beside a triangle too wide for its diametral ball to be kept
    // free of them (confine_to_region.h), bubbles tens of metres off a
    // kilometre-wide triangle encroach upon its sub-facets until those are
    // about that small, and meanwhile the count of missing ones grows or stays
    // flat (modelA2 with tilted_size_factor 1.5). Only sub-facets that are no
    // facet of the triangulation count there: those hidden by flat cells of
    // rounded points (a tilted outer wall of CloudSpin turned) shrink without
    // end as well (28 m -> 2 mm in 250 insertions).
    const std::size_t maximum_stalled_insertions = 256;
    // Each insertion triangulates the triangle's points again, so past this
    // many on it only fewer missing sub-facets count: a triangle refined
    // further would cost minutes (the test's 1,016 points take 2.8 s).
    const std::size_t maximum_points_for_shrinking = 4096;
    std::size_t fewest_missing = (std::numeric_limits<std::size_t>::max)(), stalled = 0;
    double largest_missing_r2_then = (std::numeric_limits<double>::max)(); // when progress was last made
    std::size_t missing_then = 0;                                          // idem
    const double smallest_progress_r2 = (std::max)(options_.minimum_split_length * options_.minimum_split_length,
                                                   1e-12 * CGAL::to_double(ab.squared_length()));
    for(;;)
    {
      triangle_dirty_[t] = 0;
      if(is_recovered(t)) return;

      // its boundary subsegments first
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t e = triangle_edges_[t][k];
        for(std::size_t i = 0; i + 1 < edge_points_[e].size(); ++i)
          if(!is_edge(edge_points_[e][i], edge_points_[e][i + 1]))
            queue_.push_back(Subsegment{e, edge_points_[e][i], edge_points_[e][i + 1]});
      }
      if(!queue_.empty())
      {
        recover_queued_subsegments(t);
        continue;
      }

      // the 2D constrained Delaunay triangulation of its points
      std::size_t nb = 0;
      points_on_triangle(t, pts, &nb);
      pts3.clear();
      for(std::size_t id : pts) pts3.push_back(point(id));
      CDT cdt;
      std::vector<typename CDT::Vertex_handle> v2(pts.size());
      for(std::size_t i = 0; i < pts.size(); ++i)
      {
        v2[i] = cdt.insert(to_2d(pts3[i]));
        if(cdt.number_of_vertices() != i + 1)
          throw Tetrahedralization_error("cannot recover " + describe(context) + ": two of its points project to " +
                                         to_string(pts3[i]) + " (numerical limit)");
        v2[i]->info() = pts[i];
      }
      for(std::size_t i = 0; i < nb; ++i)
        cdt.insert_constraint(v2[i], v2[(i + 1) % nb]);
      if(cdt.number_of_vertices() != pts.size())
        throw Tetrahedralization_error("cannot recover " + describe(context) +
                                       ": its boundary crosses itself in its plane (numerical limit)");
      mark_inside(cdt);

      // the largest missing sub-facet: preferably one that is no facet of
      // the triangulation at all, else one that only the flat cells hide
      std::vector<Surface_facet> present;
      surface_facets_on_triangle(t, present);
      std::vector<std::array<std::size_t, 3> > present_keys;
      for(const Surface_facet& sf : present)
      {
        std::array<std::size_t, 3> k;
        for(int j = 0; j < 3; ++j) k[j] = id_of(sf.facet.first->vertex(Tr::vertex_triple_index(sf.facet.second, j)));
        std::sort(k.begin(), k.end());
        present_keys.push_back(k);
      }
      std::sort(present_keys.begin(), present_keys.end());
      typename CDT::Face_handle worst;
      double worst_r2 = -1., largest_missing_r2 = 0.;
      int worst_rank = 2;
      std::size_t missing = 0;
      for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      {
        if(f->info() != 1) continue;
        std::array<std::size_t, 3> ids;
        for(int k = 0; k < 3; ++k) ids[k] = f->vertex(k)->info();
        std::array<std::size_t, 3> k = ids;
        std::sort(k.begin(), k.end());
        if(std::binary_search(present_keys.begin(), present_keys.end(), k)) continue;
        ++missing;
        Cell_handle c;
        int i0, i1, i2;
        const int rank =
          tr_.is_facet(records_[ids[0]].vh, records_[ids[1]].vh, records_[ids[2]].vh, c, i0, i1, i2) ? 1 : 0;
        const double r2 = CGAL::to_double(CGAL::squared_radius(f->vertex(0)->point(), f->vertex(1)->point(),
                                                                f->vertex(2)->point()));
        if(rank == 0) largest_missing_r2 = (std::max)(largest_missing_r2, r2);
        if(rank < worst_rank || (rank == worst_rank && r2 > worst_r2))
        {
          worst_rank = rank;
          worst_r2 = r2;
          worst = f;
        }
      }
      if(missing < fewest_missing ||
         (largest_missing_r2 < 0.25 * largest_missing_r2_then && largest_missing_r2 > smallest_progress_r2 &&
          triangle_points_[t].size() < maximum_points_for_shrinking))
      {
        fewest_missing = (std::min)(fewest_missing, missing);
        largest_missing_r2_then = largest_missing_r2 > 0. ? largest_missing_r2 : (std::numeric_limits<double>::max)();
        missing_then = missing;
        stalled = 0;
      }
      else if(++stalled > maximum_stalled_insertions + 4 * missing_then)
      {
        // rank 0: the largest missing sub-facet is no facet at all, so a point
        // blocks it; otherwise flat cells of rounded points hide them
        std::string why = worst_rank == 0 ? blocking_point(t, circumcentre_3d(worst).second, A, n) : std::string();
        if(why.empty()) why = "numerical limit: its points are rounded off its plane";
        throw Tetrahedralization_error("cannot recover " + describe(context) + ": " + std::to_string(triangle_points_[t].size()) +
                                       " Steiner points on it and still " + std::to_string(missing) +
                                       " sub-facets missing, no fewer and none half as wide for " +
                                       std::to_string(stalled) + " insertions (" + why + ")");
      }
      if(worst == typename CDT::Face_handle())
      {
        // the sub-facets are there but fold over each other: split its longest
        // subsegment. Rounding can make that endless (each split brings new
        // flat cells); a bound turns it into an error that names the triangle.
        if(++fold_splits > maximum_fold_splits)
          throw Tetrahedralization_error("cannot recover " + describe(context) + ": its sub-facets still fold over each other in "
                                         "flat cells after " + std::to_string(maximum_fold_splits) +
                                         " splits of its boundary (numerical limit)");
        std::size_t longest = 0;
        double longest_l2 = -1.;
        for(std::size_t i = 0; i < nb; ++i)
        {
          const double l2 = CGAL::to_double(CGAL::squared_distance(pts3[i], pts3[(i + 1) % nb]));
          if(l2 > longest_l2) { longest_l2 = l2; longest = i; }
        }
        std::size_t e, pos;
        const bool ok = is_subsegment(pts[longest], pts[(longest + 1) % nb], e, pos);
        CGAL_assertion(ok);
        CGAL_USE(ok);
        split_subsegment(e, pos, context);
        recover_queued_subsegments(t);
        continue;
      }

      const std::pair<Point_2, Point_3> centre = circumcentre_3d(worst);
      const Point_2& c2 = centre.first;
      Point_3 c3 = centre.second;
      // on a triangle of an axis plane (the walls of most models) the point
      // is put exactly on the plane: rounded off it, points make flat cells
      {
        std::array<double, 3> xyz = {{CGAL::to_double(c3.x()), CGAL::to_double(c3.y()), CGAL::to_double(c3.z())}};
        for(int i = 0; i < 3; ++i)
          if(A[i] == B[i] && A[i] == C[i]) xyz[i] = CGAL::to_double(A[i]);
        c3 = Point_3(xyz[0], xyz[1], xyz[2]);
      }
      const std::array<double, 3> lambda = barycentric(c2);
      const bool inside = lambda[0] > 0. && lambda[1] > 0. && lambda[2] > 0.;

      // subsegments of its boundary it encroaches upon
      std::vector<std::pair<std::size_t, std::size_t> > encroached; // (edge, first id)
      for(std::size_t i = 0; i < nb; ++i)
      {
        const std::size_t j = (i + 1) % nb;
        if(tr_.geom_traits().side_of_bounded_sphere_3_object()(pts3[i], pts3[j], c3) != CGAL::ON_UNBOUNDED_SIDE)
        {
          std::size_t e, pos;
          const bool ok = is_subsegment(pts[i], pts[j], e, pos);
          CGAL_assertion(ok);
          CGAL_USE(ok);
          encroached.emplace_back(e, edge_points_[e][pos]);
        }
      }
      if(encroached.empty() && !inside)
        encroached.push_back(crossed_subsegment(t, worst, c2, barycentric));
      if(encroached.empty())
      {
        // subsegments of other edges whose diametral ball contains it
        typename Tr::Locate_type lt;
        int li, lj;
        const Weighted_point wp(c3);
        Cell_handle loc = tr_.locate(wp, lt, li, lj, records_[pts[0]].vh->cell());
        if(lt == Tr::VERTEX)
          throw Tetrahedralization_error("cannot recover " + describe(context) + ": its Steiner point " + to_string(c3) +
                                         " falls on an existing vertex (numerical limit)");
        conflict.clear();
        tr_.find_conflicts(wp, loc, CGAL::Emptyset_iterator(), std::back_inserter(conflict),
                           CGAL::Emptyset_iterator());
        for(Cell_handle c : conflict)
          for(int i = 0; i < 4; ++i)
            for(int j = i + 1; j < 4; ++j)
            {
              if(tr_.is_infinite(c->vertex(i)) || tr_.is_infinite(c->vertex(j))) continue;
              const std::size_t u = id_of(c->vertex(i)), v = id_of(c->vertex(j));
              std::size_t e, pos;
              if(!is_subsegment(u, v, e, pos)) continue;
              if(tr_.geom_traits().side_of_bounded_sphere_3_object()(point(u), point(v), c3) ==
                 CGAL::ON_UNBOUNDED_SIDE)
                continue;
              encroached.emplace_back(e, edge_points_[e][pos]);
            }
        if(encroached.empty())
        {
          const std::size_t id = insert_steiner_point(c3, Vertex_kind::triangle_point, t, 0., loc, context);
          triangle_points_[t].push_back(id);
          continue;
        }
      }
      std::sort(encroached.begin(), encroached.end());
      encroached.erase(std::unique(encroached.begin(), encroached.end()), encroached.end());
      for(const auto& s : encroached)
      {
        const std::size_t pos = position(s.first, s.second);
        CGAL_assertion(pos != no_index_);
        split_subsegment(s.first, pos, context);
      }
      recover_queued_subsegments(t);
    }
  }

  // faces reachable from the infinite face without crossing a constraint are outside
  static void mark_inside(CDT& cdt)
  {
    for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = 1;
    std::vector<typename CDT::Face_handle> stack(1, cdt.infinite_face());
    cdt.infinite_face()->info() = 0;
    while(!stack.empty())
    {
      typename CDT::Face_handle f = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i)
      {
        typename CDT::Face_handle g = f->neighbor(i);
        if(g->info() == 0 || cdt.is_constrained(std::make_pair(f, i))) continue;
        g->info() = 0;
        stack.push_back(g);
      }
    }
  }

  /// the boundary subsegment of triangle `t` crossed from sub-facet `f` to `c2` (outside `t`)
  template <class Barycentric>
  std::pair<std::size_t, std::size_t> crossed_subsegment(std::size_t t, typename CDT::Face_handle f,
                                                         const Point_2& c2, const Barycentric& barycentric) const
  {
    const Point_2 g = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    const std::array<double, 3> lg = barycentric(g), lc = barycentric(c2);
    int side = -1;
    double best = 2.;
    for(int k = 0; k < 3; ++k)
      if(lc[k] < 0. && lg[k] > lc[k])
      {
        const double s = lg[k] / (lg[k] - lc[k]);
        if(s < best) { best = s; side = k; }
      }
    CGAL_assertion(side >= 0);
    // the crossing point, as a position along the side from corner side+1 to side+2
    std::array<double, 3> lx;
    for(int k = 0; k < 3; ++k) lx[k] = lg[k] + best * (lc[k] - lg[k]);
    const double w1 = (std::max)(lx[(side + 1) % 3], 0.), w2 = (std::max)(lx[(side + 2) % 3], 0.);
    double w = (w1 + w2 > 0.) ? w2 / (w1 + w2) : 0.5;
    // triangle edge k joins corners k and k+1: the side opposite corner `side` is edge side+1
    const int k = (side + 1) % 3;
    const std::size_t e = triangle_edges_[t][k];
    if(edge_ends_[e][0] != model_.triangle(t)[k]) w = 1. - w;
    const std::vector<std::size_t>& l = edge_points_[e];
    std::size_t pos = 0;
    while(pos + 2 < l.size() && parameter(e, l[pos + 1]) < w) ++pos;
    return std::make_pair(e, l[pos]);
  }

  Point_3 point(std::size_t id) const
  {
    return tr_.geom_traits().construct_point_3_object()(tr_.point(records_[id].vh));
  }

  std::string describe_point_kind(std::size_t i) const
  {
    const Vertex_record& r = records_[i];
    switch(r.kind)
    {
    case Vertex_kind::input_point: return "model point " + std::to_string(r.element);
    case Vertex_kind::edge_point: return "a Steiner point on " + describe_edge(r.element);
    case Vertex_kind::triangle_point: return "a Steiner point on " + describe_triangle(r.element);
    default: return "interior point " + std::to_string(r.element);
    }
  }

  // Why the recovery of triangle t stalls when its largest missing sub-facet,
  // of circumcentre c, is no facet of the triangulation at all: every sphere
  // through its circle holds a point, the diametral one too, so a point off
  // the triangle lies nearer to c than the sub-facet's own vertices (bubbles
  // beside a wide triangle, another surface almost touching it). Names it,
  // with its distance off the plane (through A, normal `normal`); empty if the
  // nearest point is on the triangle after all (rounding).
  std::string blocking_point(std::size_t t, const Point_3& c, const Point_3& A, const Vector_3& normal) const
  {
    const Vertex_handle v = tr_.nearest_power_vertex(c);
    const std::size_t id = tr_.is_infinite(v) ? no_index_ : id_of(v);
    if(id == no_index_ || is_on_triangle(id, t)) return std::string();
    const double off = std::abs(CGAL::to_double((point(id) - A) * normal)) /
                       std::sqrt(CGAL::to_double(normal.squared_length()));
    std::ostringstream os;
    os << "points off it stay inside its sub-facets' diametral balls; nearest to the largest missing one: "
       << describe_point_kind(id) << " at " << to_string(point(id)) << ", " << off << " off its plane";
    return os.str();
  }

  const Model& model_;
  Tr& tr_;
  Options options_;

  std::vector<Vertex_record> records_;
  std::vector<std::size_t> id_by_stamp_;

  std::vector<std::array<std::size_t, 2> > edge_ends_;    // model point indices, first < second
  std::vector<std::size_t> edge_triangles_start_, edge_triangles_;   // triangles of each edge
  std::vector<std::size_t> point_triangles_start_, point_triangles_; // triangles of each model point
  std::vector<std::size_t> point_edges_start_, point_edges_;         // edges of each model point
  std::vector<char> triangle_dirty_, edge_dirty_; // to check again: an insertion changed cells around them
  std::vector<std::size_t> plane_group_;                             // of each triangle
  std::vector<Vector_3> group_normal_;
  std::vector<int> group_outside_; // +1 / -1: the model's outside is above / below the whole group; 0: neither
  Point_3 centroid_; // of the model points: strictly inside their convex hull
  std::vector<std::array<double, 2> > end_closeness_; // sine of the smallest angle at each end of each edge
  std::vector<std::vector<std::size_t> > edge_points_;    // vertex ids along each edge, ends included
  std::unordered_map<std::uint64_t, std::size_t> edge_index_;
  std::vector<std::array<std::size_t, 3> > triangle_edges_; // edge k joins corners k and k+1
  std::vector<std::vector<std::size_t> > triangle_points_;  // inner Steiner points of each triangle

  std::deque<Subsegment> queue_;
  std::size_t number_of_edge_points_ = 0;
  std::size_t number_of_triangle_points_ = 0;
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_RECOVER_SURFACE_H
