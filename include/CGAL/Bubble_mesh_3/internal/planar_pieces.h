// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_PLANAR_PIECES_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_PLANAR_PIECES_H

// The machinery of retriangulate_planar_patches(): planar pieces of the
// patches, each triangulated in its plane by a 2D constrained Delaunay
// triangulation, refined by circumcentres (axis-plane pieces for angles and
// size, tilted pieces and single triangles of curved surfaces for size).
//
// Exactness: inside an axis plane new points copy its constant coordinate, and
// an edge in an axis plane keeps that coordinate at its midpoint, so axis
// planes stay exactly planar. Elsewhere new points are rounded: a point lifted
// from a tilted piece's frame, or an edge's rounded midpoint, lies within a few
// rounding units of the plane or line it was computed on, inside the tolerance
// under which the recovery's plane groups (recover_surface.h) and the pieces
// here count triangles as coplanar (near_coplanarity.h); a point off by more is
// not added.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/mesh_quality.h> // smallest_triangle_angle
#include <CGAL/Bubble_mesh_3/internal/near_coplanarity.h>
#include <CGAL/Bubble_mesh_3/internal/vertex_angle.h>
#include <CGAL/Bubble_mesh_3/internal/union_find.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

What `retriangulate_planar_patches()` did. Angles are in degrees.
*/
struct Planar_retriangulation_report
{
  std::size_t number_of_pieces = 0;                 ///< planar pieces (two or more triangles, or one in an axis plane or given new points)
  std::size_t number_of_retriangulated_pieces = 0;  ///< of those, the pieces given a new triangulation
  std::size_t number_of_refined_pieces = 0;         ///< of those, the pieces that got new points
  std::size_t number_of_points_added = 0;           ///< new points (inside pieces and on edges between them)
  std::size_t number_of_refined_tilted_pieces = 0;  ///< of the refined pieces, those not in an axis plane (curved surfaces' triangles)
  std::size_t number_of_excluded_pieces = 0;        ///< pieces left unrefined because their refined triangulation failed its check
  std::size_t number_of_triangles_before = 0;       ///< triangles of the re-triangulated pieces, before
  std::size_t number_of_triangles_after = 0;        ///< and after
  std::size_t number_of_small_angle_triangles_before = 0; ///< of those, with an angle under 10 degrees, before
  std::size_t number_of_small_angle_triangles_after = 0;  ///< and after
  double min_angle_before = 180.;                   ///< smallest triangle angle of the re-triangulated pieces, before
  double min_angle_after = 180.;                    ///< the same, after
};

/// writes the report in one line
inline std::ostream& operator<<(std::ostream& os, const Planar_retriangulation_report& r)
{
  return os << r.number_of_retriangulated_pieces << " of " << r.number_of_pieces << " re-triangulated, "
            << r.number_of_refined_pieces << " with " << r.number_of_points_added << " new points ("
            << r.number_of_refined_tilted_pieces << " tilted"
            << (r.number_of_excluded_pieces ? ", " + std::to_string(r.number_of_excluded_pieces) + " left unrefined" : std::string())
            << "); their triangles "
            << r.number_of_triangles_before << " -> " << r.number_of_triangles_after << ", under 10 deg "
            << r.number_of_small_angle_triangles_before << " -> " << r.number_of_small_angle_triangles_after
            << ", smallest angle " << r.min_angle_before << " -> " << r.min_angle_after << " deg";
}

namespace internal {

template <class Point_3>
double smallest_triangle_angle(const Point_3& a, const Point_3& b, const Point_3& c)
{
  return smallest_triangle_angle(coordinates(a), coordinates(b), coordinates(c)); // mesh_quality.h
}

template <class GeomTraits>
class Planar_pieces
{
  typedef Geological_model_3<GeomTraits>  Model;
  typedef typename GeomTraits::Point_3    Point_3;
  typedef typename GeomTraits::Vector_3   Vector_3;
  typedef typename GeomTraits::Point_2    Point_2;
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, GeomTraits>         Vb;
  typedef CGAL::Constrained_triangulation_face_base_2<GeomTraits>                      Cfb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, GeomTraits, Cfb>              Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb>                                 Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<GeomTraits, Tds, CGAL::No_constraint_intersection_tag> CDT;
  typedef std::array<std::size_t, 3> Triangle;

  // a subsegment of a piece's boundary: its ends (point ids), its input edge,
  // and whether the piece lies on one side only (1) or on both (0)
  struct Subsegment { std::size_t u, v, edge; int toggle; };

  // a piece's plane: 2D coordinates and the way back
  struct Frame
  {
    int axis = -1;       // x, y or z constant (0, 1, 2), or -1: a tilted plane
    double level = 0.;   // that constant
    Point_3 origin;      // tilted planes: an orthonormal frame
    Vector_3 e1, e2;
    bool flip = false;   // counterclockwise in 2D is clockwise for the piece
    int exact_axis = 0;  // the projection that checks orientations exactly
    CGAL::Orientation up = CGAL::POSITIVE; // the piece's orientation in that projection
  };

  static constexpr std::size_t none = std::size_t(-1);

  // Off the axis planes a triangle is refined only when it is
  // `tilted_size_factor` (default 1.5) times as wide as the size wanted there (the
  // input's own triangles near the median edge stay; with a factor 1,
  // modelA2 got three times the bubbles), and a
  // single triangle only when its angles are at least 20 degrees: splitting
  // a needle's long edge makes two needles, and on walls that are planes
  // only up to rounding, needles split so could not be recovered (modelA2).
  static constexpr double tilted_angle_bound = 20.;

public:
  // `refine_tilted`: whether pieces off the axis planes (and single
  // triangles of curved surfaces) get points for size too, where a triangle
  // is `tilted_size_factor` times as wide as the size wanted; `size_cap`:
  // the largest size wanted (0: the median input edge)
  Planar_pieces(const Model& input, double angle_bound, bool refine_tilted, double tilted_size_factor,
                double size_cap = 0.)
    : in_(input), np_(input.number_of_points()), nt_(input.number_of_triangles()),
      sin_bound_(std::sin((std::min)(angle_bound, 34.) * CGAL_PI / 180.)), refine_(angle_bound > 0.),
      refine_tilted_(refine_tilted), tilted_size_factor_(tilted_size_factor),
      tolerance_(coplanarity_tolerance(input))
  {
    build_edges();
    build_pieces();
    if(refine_) measure_edges();
    if(size_cap > 0.) size_cap_ = size_cap;
  }

  Planar_retriangulation_report run(Model& out)
  {
    Planar_retriangulation_report report;
    if(refine_)
    {
      // A refined piece whose triangulation fails its check is left out and
      // the refinement starts again (its neighbours may have points on the
      // edges they share with it); after a few such failures nothing is refined.
      std::size_t excluded = 0;
      for(int attempt = 0; attempt < 16; ++attempt)
      {
        std::size_t failed = refine_all();
        if(failed == none) failed = write(out, report);
        if(failed == none)
        {
          report.number_of_excluded_pieces = excluded;
          return report;
        }
        unrefine();
        excluded_[failed] = 1;
        ++excluded;
        mark_soft_edges();
      }
    }
    unrefine();
    write(out, report);
    return report;
  }

private:
  void unrefine()
  {
    extra_.clear();
    for(auto& l : edge_points_) l.clear();
    for(auto& l : inner_) l.clear();
  }

  // writes the model; the first piece with new points that failed its check, or `none`
  std::size_t write(Model& out, Planar_retriangulation_report& report) const
  {
    report = Planar_retriangulation_report();
    out = Model();
    out.set_file_name(in_.file_name());
    for(std::size_t r = 1; r < in_.regions().size(); ++r) out.add_region(in_.region(r).name);
    for(const auto& p : in_.patches()) out.add_patch(p.name, p.positive_region, p.negative_region);
    for(std::size_t i = 0; i < np_; ++i) out.add_point(in_.point(i), in_.point_source(i));
    for(const Point_3& p : extra_) out.add_point(p);
    report.number_of_points_added = extra_.size();

    std::vector<Triangle> tris;
    for(std::size_t p = 0; p < pieces_.size(); ++p)
    {
      const std::vector<std::size_t>& ts = pieces_[p];
      const std::size_t first = ts.front();
      const bool refined = !inner_[p].empty() || boundary_has_new_points(p);
      const bool is_piece = ts.size() > 1 || frames_[p].axis >= 0 || refined;
      if(is_piece) ++report.number_of_pieces;
      if(!is_piece || !triangulate(p, tris))
      {
        if(refined) return p;
        for(std::size_t t : ts)
          out.add_triangle(in_.triangle(t)[0], in_.triangle(t)[1], in_.triangle(t)[2], in_.patch_of_triangle(t),
                           in_.triangle_source(t));
        continue;
      }
      ++report.number_of_retriangulated_pieces;
      if(refined) ++report.number_of_refined_pieces;
      if(refined && frames_[p].axis < 0) ++report.number_of_refined_tilted_pieces;
      report.number_of_triangles_before += ts.size();
      report.number_of_triangles_after += tris.size();
      for(std::size_t t : ts)
      {
        const double a = angle(in_.triangle(t));
        report.min_angle_before = (std::min)(report.min_angle_before, a);
        if(a < 10.) ++report.number_of_small_angle_triangles_before;
      }
      for(const Triangle& t : tris)
      {
        const double a = angle(t);
        report.min_angle_after = (std::min)(report.min_angle_after, a);
        if(a < 10.) ++report.number_of_small_angle_triangles_after;
        // errors name the piece's first input triangle
        out.add_triangle(t[0], t[1], t[2], in_.patch_of_triangle(first), in_.triangle_source(first));
      }
    }
    return none;
  }

  const Point_3& point(std::size_t id) const { return id < np_ ? in_.point(id) : extra_[id - np_]; }
  double angle(const Triangle& t) const { return smallest_triangle_angle(point(t[0]), point(t[1]), point(t[2])); }

  static std::uint64_t pair_key(std::size_t a, std::size_t b)
  {
    if(a > b) std::swap(a, b);
    return (std::uint64_t(a) << 32) | std::uint64_t(b);
  }

  // ---- edges and pieces ------------------------------------------------------

  void build_edges()
  {
    std::unordered_map<std::uint64_t, std::size_t> edge_id;
    tri_edges_.resize(nt_);
    for(std::size_t t = 0; t < nt_; ++t)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t a = in_.triangle(t)[k], b = in_.triangle(t)[(k + 1) % 3];
        auto ins = edge_id.emplace(pair_key(a, b), edge_ends_.size());
        if(ins.second)
        {
          edge_ends_.push_back({{(std::min)(a, b), (std::max)(a, b)}});
          edge_tris_.emplace_back();
        }
        edge_tris_[ins.first->second].push_back(t);
        tri_edges_[t][k] = ins.first->second;
      }
    edge_points_.resize(edge_ends_.size());
  }

  // the input's shortest and median edge: bounds of the refinement, the same
  // for every attempt of run()
  void measure_edges()
  {
    std::vector<double> lengths;
    lengths.reserve(edge_ends_.size());
    for(const auto& e : edge_ends_)
      lengths.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(in_.point(e[0]), in_.point(e[1])))));
    min_split_length_ = lengths.empty() ? std::numeric_limits<double>::infinity()
                                        : *std::min_element(lengths.begin(), lengths.end());
    if(!lengths.empty())
    {
      std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
      size_cap_ = lengths[lengths.size() / 2];
    }
  }

  // whether triangle `t` runs from a to b (else from b to a)
  bool runs(std::size_t t, std::size_t a, std::size_t b) const
  {
    const auto& tri = in_.triangle(t);
    for(int k = 0; k < 3; ++k)
      if(tri[k] == a && tri[(k + 1) % 3] == b) return true;
    return false;
  }

  // an edge inside a piece: two triangles of one patch, coplanar, oriented alike
  bool is_free(std::size_t e) const
  {
    const std::vector<std::size_t>& ts = edge_tris_[e];
    if(ts.size() != 2) return false;
    const std::size_t t1 = ts[0], t2 = ts[1], a = edge_ends_[e][0], b = edge_ends_[e][1];
    if(in_.patch_of_triangle(t1) != in_.patch_of_triangle(t2) || runs(t1, a, b) == runs(t2, a, b)) return false;
    return are_nearly_coplanar(in_, t1, t2, tolerance_);
  }

  void build_pieces()
  {
    std::vector<std::size_t> parent = uf_singletons(nt_);
    free_.resize(edge_ends_.size());
    for(std::size_t e = 0; e < edge_ends_.size(); ++e)
    {
      free_[e] = is_free(e);
      if(free_[e]) uf_union(parent, edge_tris_[e][0], edge_tris_[e][1]);
    }
    // pieces in the order of their first triangle
    std::vector<std::size_t> piece_of_root(nt_, std::size_t(-1));
    piece_of_.resize(nt_);
    for(std::size_t t = 0; t < nt_; ++t)
    {
      std::size_t& p = piece_of_root[uf_find(parent, t)];
      if(p == std::size_t(-1)) { p = pieces_.size(); pieces_.emplace_back(); }
      pieces_[p].push_back(t);
      piece_of_[t] = p;
    }
    inner_.resize(pieces_.size());
    frames_.resize(pieces_.size());
    for(std::size_t p = 0; p < pieces_.size(); ++p) frames_[p] = frame(pieces_[p]);

    excluded_.assign(pieces_.size(), 0);
    well_shaped_.assign(pieces_.size(), 1);
    for(std::size_t p = 0; p < pieces_.size(); ++p)
      if(pieces_[p].size() == 1)
        well_shaped_[p] = angle(in_.triangle(pieces_[p].front())) >= tilted_angle_bound;
    mark_soft_edges();
  }

  // whether piece `p` gets new points
  bool refinable(std::size_t p) const
  {
    return refine_ && !excluded_[p] && (frames_[p].axis >= 0 || (refine_tilted_ && well_shaped_[p]));
  }

  // edges that may be split: every triangle on them is in a piece being refined
  void mark_soft_edges()
  {
    soft_.assign(edge_ends_.size(), 0);
    for(std::size_t e = 0; e < edge_ends_.size(); ++e)
    {
      if(free_[e]) continue;
      bool soft = true;
      for(std::size_t t : edge_tris_[e]) soft = soft && refinable(piece_of_[t]);
      soft_[e] = soft;
    }
  }

  Frame frame(const std::vector<std::size_t>& ts) const
  {
    Frame f;
    const auto& t0 = in_.triangle(ts[0]);
    const Point_3& o = in_.point(t0[0]);
    const Vector_3 n = CGAL::cross_product(in_.point(t0[1]) - o, in_.point(t0[2]) - o);
    for(int i = 1; i < 3; ++i)
      if(std::abs(CGAL::to_double(n[i])) > std::abs(CGAL::to_double(n[f.exact_axis]))) f.exact_axis = i;
    f.up = CGAL::orientation(project(o, f.exact_axis), project(in_.point(t0[1]), f.exact_axis),
                             project(in_.point(t0[2]), f.exact_axis));
    // an axis plane when every point has the same coordinate along the normal's axis
    bool axis_plane = n[(f.exact_axis + 1) % 3] == 0 && n[(f.exact_axis + 2) % 3] == 0;
    for(std::size_t t : ts)
      for(std::size_t v : in_.triangle(t))
        axis_plane = axis_plane && in_.point(v)[f.exact_axis] == o[f.exact_axis];
    if(axis_plane)
    {
      f.axis = f.exact_axis;
      f.level = CGAL::to_double(o[f.axis]);
      f.flip = f.up == CGAL::NEGATIVE;
      return f;
    }
    // a tilted plane: an orthonormal frame for the Delaunay criterion (the
    // projection would stretch it); counterclockwise in it is the piece's side
    f.origin = o;
    const Vector_3 d = in_.point(t0[1]) - o;
    f.e1 = d / std::sqrt(CGAL::to_double(d.squared_length()));
    f.e2 = CGAL::cross_product(n, f.e1);
    f.e2 = f.e2 / std::sqrt(CGAL::to_double(f.e2.squared_length()));
    return f;
  }

  static Point_2 project(const Point_3& p, int axis) { return Point_2(p[(axis + 1) % 3], p[(axis + 2) % 3]); }

  Point_2 to_2d(const Frame& f, const Point_3& p) const
  {
    if(f.axis >= 0) return project(p, f.axis);
    const Vector_3 d = p - f.origin;
    return Point_2(d * f.e1, d * f.e2);
  }

  // a point of the piece's plane from its 2D coordinates: exactly on an axis
  // plane, within rounding of a tilted one
  static Point_3 lift(const Frame& f, const Point_2& q)
  {
    if(f.axis < 0) return f.origin + CGAL::to_double(q.x()) * f.e1 + CGAL::to_double(q.y()) * f.e2;
    std::array<double, 3> c;
    c[std::size_t(f.axis)] = f.level;
    c[std::size_t((f.axis + 1) % 3)] = CGAL::to_double(q.x());
    c[std::size_t((f.axis + 2) % 3)] = CGAL::to_double(q.y());
    return Point_3(c[0], c[1], c[2]);
  }

  bool boundary_has_new_points(std::size_t p) const
  {
    for(std::size_t t : pieces_[p])
      for(std::size_t e : tri_edges_[t])
        if(!edge_points_[e].empty()) return true;
    return false;
  }

  // ---- one piece's triangulation ---------------------------------------------------

  // The constrained Delaunay triangulation of piece `p`'s points with its
  // boundary as constraints, faces inside marked 1; false if it cannot be
  // checked to be the piece's polygon.
  bool build(std::size_t p, CDT& cdt, std::vector<Subsegment>& subs) const
  {
    const Frame& f = frames_[p];
    subs.clear();
    std::vector<std::size_t> pts;
    std::map<std::size_t, int> boundary; // edge -> 1 if on the piece's boundary, 0 if inside it
    for(std::size_t t : pieces_[p])
    {
      pts.insert(pts.end(), in_.triangle(t).begin(), in_.triangle(t).end());
      for(std::size_t e : tri_edges_[t])
      {
        if(free_[e]) continue;
        auto ins = boundary.emplace(e, 1);
        if(!ins.second) ins.first->second = 0; // two triangles of the piece on it
      }
    }
    std::unordered_map<std::uint64_t, int> toggle;
    for(const auto& eb : boundary)
    {
      const std::size_t e = eb.first;
      std::vector<std::size_t> chain(1, edge_ends_[e][0]);
      for(const auto& tp : edge_points_[e]) chain.push_back(tp.second);
      chain.push_back(edge_ends_[e][1]);
      for(std::size_t k = 0; k + 1 < chain.size(); ++k)
      {
        subs.push_back(Subsegment{chain[k], chain[k + 1], e, eb.second});
        toggle[pair_key(chain[k], chain[k + 1])] = eb.second;
      }
      pts.insert(pts.end(), chain.begin() + 1, chain.end() - 1);
    }
    pts.insert(pts.end(), inner_[p].begin(), inner_[p].end());
    std::sort(pts.begin(), pts.end());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());

    std::unordered_map<std::size_t, typename CDT::Vertex_handle> vh;
    for(std::size_t id : pts)
    {
      const typename CDT::Vertex_handle v = cdt.insert(to_2d(f, point(id)));
      if(cdt.number_of_vertices() != vh.size() + 1) return false; // two points project to one
      v->info() = id;
      vh[id] = v;
    }
    try
    {
      for(const Subsegment& s : subs) cdt.insert_constraint(vh[s.u], vh[s.v]);
    }
    catch(...) { return false; } // constraints that cross
    if(cdt.number_of_vertices() != pts.size()) return false;

    // inside: across a boundary subsegment the side changes, across any other it does not
    for(auto fh = cdt.all_faces_begin(); fh != cdt.all_faces_end(); ++fh) fh->info() = -1;
    std::vector<typename CDT::Face_handle> stack(1, cdt.infinite_face());
    cdt.infinite_face()->info() = 0;
    while(!stack.empty())
    {
      const typename CDT::Face_handle fh = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i)
      {
        int side = fh->info();
        if(cdt.is_constrained(std::make_pair(fh, i)))
        {
          auto it = toggle.find(pair_key(fh->vertex(cdt.cw(i))->info(), fh->vertex(cdt.ccw(i))->info()));
          if(it == toggle.end()) return false; // a point on a constraint split it
          side ^= it->second;
        }
        const typename CDT::Face_handle g = fh->neighbor(i);
        if(g->info() == -1) { g->info() = side; stack.push_back(g); }
        else if(g->info() != side) return false;
      }
    }
    return true;
  }

  // piece `p`'s new triangles, oriented as the piece; false if the check fails
  bool triangulate(std::size_t p, std::vector<Triangle>& out) const
  {
    out.clear();
    CDT cdt;
    std::vector<Subsegment> subs;
    if(!build(p, cdt, subs)) return false;
    const Frame& f = frames_[p];
    double area_before = 0., area_after = 0.;
    auto area = [&](const Triangle& t) {
      return std::sqrt(CGAL::to_double(
               CGAL::cross_product(point(t[1]) - point(t[0]), point(t[2]) - point(t[0])).squared_length()));
    };
    for(std::size_t t : pieces_[p]) area_before += area(in_.triangle(t));
    for(auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh)
    {
      if(fh->info() != 1) continue;
      Triangle t = {{fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()}};
      if(f.flip) std::swap(t[1], t[2]);
      if(CGAL::orientation(project(point(t[0]), f.exact_axis), project(point(t[1]), f.exact_axis),
                           project(point(t[2]), f.exact_axis)) != f.up)
        return false;
      area_after += area(t);
      out.push_back(t);
    }
    return std::abs(area_after - area_before) <= 1e-9 * area_before;
  }

  // ---- refinement of axis-plane pieces ---------------------------------------------

  // refines every refinable piece until no edge between them is split any
  // more; the first piece whose triangulation failed its check, or `none`
  std::size_t refine_all()
  {
    // the angle rule's points, and those of the size rule: about one per
    // 0.43 cap^2 of refined area, graded towards the finer borders
    double refined_area = 0.;
    for(std::size_t p = 0; p < pieces_.size(); ++p)
      if(refinable(p))
        for(std::size_t t : pieces_[p])
        {
          const Triangle& tri = in_.triangle(t);
          refined_area += 0.5 * std::sqrt(CGAL::to_double(
                               CGAL::cross_product(point(tri[1]) - point(tri[0]), point(tri[2]) - point(tri[0])).squared_length()));
        }
    const double size_points = std::isfinite(size_cap_) && size_cap_ > 0. ? 2. * refined_area / (0.43 * size_cap_ * size_cap_) : 0.;
    budget_ = 2 * np_ + 1000 + std::size_t((std::min)(size_points, 1e7));
    for(int round = 0; round < 100; ++round)
    {
      bool split = false;
      for(std::size_t p = 0; p < pieces_.size(); ++p)
      {
        if(!refinable(p)) continue;
        int r = refine(p);
        if(r < 0) return p;
        split = split || r > 0;
      }
      if(!split) break;
    }
    return none;
  }

  // -1: the check failed; 1: an edge was split (its other pieces need another look); 0: done
  int refine(std::size_t p)
  {
    const Frame& f = frames_[p];
    int result = 0;
    for(;;)
    {
      CDT cdt;
      std::vector<Subsegment> subs;
      if(!build(p, cdt, subs)) return -1;
      const std::vector<Size_source> sources = size_sources(f, subs);
      std::set<std::array<std::size_t, 3> > given_up;
      bool rebuild = false;
      // bad faces a batch at a time, largest circumcircle first (a scan per
      // insertion would be quadratic on large pieces)
      struct Bad { double r2; std::array<std::size_t, 3> key; std::array<typename CDT::Vertex_handle, 3> v; };
      std::vector<Bad> batch;
      std::size_t next = 0;
      while(!rebuild)
      {
        if(extra_.size() >= budget_) return result;
        if(next == batch.size())
        {
          batch.clear();
          next = 0;
          for(auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh)
          {
            if(fh->info() != 1) continue;
            const Point_2& a = fh->vertex(0)->point();
            const Point_2& b = fh->vertex(1)->point();
            const Point_2& c = fh->vertex(2)->point();
            const double la = CGAL::to_double(CGAL::squared_distance(b, c)),
                         lb = CGAL::to_double(CGAL::squared_distance(c, a)),
                         lc = CGAL::to_double(CGAL::squared_distance(a, b));
            const double twice_area = std::abs(CGAL::to_double(CGAL::area(a, b, c))) * 2.;
            // the smallest angle is opposite the shortest side: sin = 2A / (product of the other two)
            const double shortest = (std::min)({la, lb, lc});
            const double others = shortest == la ? lb * lc : shortest == lb ? la * lc : la * lb;
            const double r2 = CGAL::to_double(CGAL::squared_radius(a, b, c));
            // the angle rule on axis planes only: on curved surfaces it would
            // chase the input's needles across every triangle around them
            const bool angle_ok = f.axis < 0 || twice_area >= sin_bound_ * std::sqrt(others);
            const double wide = f.axis < 0 ? tilted_size_factor_ : 1.;
            if(angle_ok && !(3. * r2 > CGAL::square(wide * target_size(sources, CGAL::circumcenter(a, b, c)))))
              continue;
            Bad bad{r2,
                    {{fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()}},
                    {{fh->vertex(0), fh->vertex(1), fh->vertex(2)}}};
            std::sort(bad.key.begin(), bad.key.end());
            if(!given_up.count(bad.key)) batch.push_back(bad);
          }
          if(batch.empty()) return result;
          std::sort(batch.begin(), batch.end(), [](const Bad& x, const Bad& y) {
            return x.r2 != y.r2 ? x.r2 > y.r2 : x.key < y.key;
          });
        }
        const Bad& bad = batch[next++];
        typename CDT::Face_handle worst;
        if(!cdt.is_face(bad.v[0], bad.v[1], bad.v[2], worst)) continue; // gone with an insertion
        const std::array<std::size_t, 3> worst_key = bad.key;
        const Point_2 c = CGAL::circumcenter(worst->vertex(0)->point(), worst->vertex(1)->point(), worst->vertex(2)->point());

        // a subsegment whose diametral circle holds it: split it if it may be, else give up the face
        const Subsegment* hit = nullptr;
        double hit_l2 = -1.;
        for(const Subsegment& s : subs)
        {
          const Point_2 u = to_2d(f, point(s.u)), v = to_2d(f, point(s.v));
          const double l2 = CGAL::to_double(CGAL::squared_distance(u, v));
          if(CGAL::to_double(CGAL::squared_distance(CGAL::midpoint(u, v), c)) < 0.25 * l2 && l2 > hit_l2)
          {
            hit = &s;
            hit_l2 = l2;
          }
        }
        if(hit)
        {
          if(soft_[hit->edge] && split(*hit)) { result = 1; rebuild = true; }
          else given_up.insert(worst_key);
          continue;
        }
        typename CDT::Locate_type lt;
        int li;
        const typename CDT::Face_handle at = cdt.locate(c, lt, li, worst);
        // a circumcentre may lie on an edge inside the piece: a right
        // triangle's, on the diagonal of a rectangle given as two triangles
        // (on a constrained edge it would have hit that subsegment above).
        // Only in an axis plane, where it is inserted exactly where it was
        // located; a tilted piece's lifted and rounded point may fall beside.
        const bool inside =
          at->info() == 1 &&
          (lt == CDT::FACE || (lt == CDT::EDGE && f.axis >= 0 && !cdt.is_constrained(std::make_pair(at, li)) &&
                               at->neighbor(li)->info() == 1));
        if(!inside) { given_up.insert(worst_key); continue; }
        const Point_3 q = lift(f, c);
        if(f.axis < 0 && !on_piece_plane(p, q)) { given_up.insert(worst_key); continue; }
        const std::size_t nv = cdt.number_of_vertices();
        const typename CDT::Vertex_handle v = cdt.insert(to_2d(f, q), at);
        if(cdt.number_of_vertices() != nv + 1) { given_up.insert(worst_key); continue; }
        v->info() = np_ + extra_.size();
        extra_.push_back(q);
        inner_[p].push_back(v->info());
        // the new faces fill the old ones' place: inside
        typename CDT::Face_circulator fc = cdt.incident_faces(v), done = fc;
        do { fc->info() = 1; } while(++fc != done);
      }
    }
  }

  // The edge length wanted on a piece: the spacing of the points on its
  // boundary and on the curves inside it (a quarter of the cap at least),
  // growing by half the distance from them, and at most the cap (the median
  // input edge, or the size asked for). Without it a wall or a bottom given as a few huge
  // triangles stays bare: the bubbles beside it have no neighbour on that
  // side, and its tetrahedra reach across the whole model.
  struct Size_source { double x, y, size; };

  std::vector<Size_source> size_sources(const Frame& f, const std::vector<Subsegment>& subs) const
  {
    std::map<std::size_t, std::pair<double, int> > spacing; // point -> sum of its subsegments' lengths, count
    for(const Subsegment& s : subs)
    {
      const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(point(s.u), point(s.v))));
      for(std::size_t id : {s.u, s.v})
      {
        auto& acc = spacing[id];
        acc.first += l;
        ++acc.second;
      }
    }
    std::vector<Size_source> out;
    out.reserve(spacing.size());
    for(const auto& sp : spacing)
    {
      // a quarter of the cap at least: the angle rule already grades the
      // triangles down to tiny input edges, rings of points for size too would
      // only multiply the points there
      const double h = (std::max)(sp.second.first / sp.second.second, 0.25 * size_cap_);
      if(!(h < size_cap_)) continue; // bounds nothing under the cap
      const Point_2 q = to_2d(f, point(sp.first));
      out.push_back(Size_source{CGAL::to_double(q.x()), CGAL::to_double(q.y()), h});
    }
    return out;
  }

  double target_size(const std::vector<Size_source>& sources, const Point_2& c) const
  {
    const double cx = CGAL::to_double(c.x()), cy = CGAL::to_double(c.y());
    double h = size_cap_;
    for(const Size_source& s : sources)
      h = (std::min)(h, s.size + 0.5 * std::sqrt(CGAL::square(cx - s.x) + CGAL::square(cy - s.y)));
    return h;
  }

  // whether `q` lies on the plane of piece `p` within the coplanarity tolerance
  bool on_piece_plane(std::size_t p, const Point_3& q) const
  {
    const auto& t = in_.triangle(pieces_[p].front());
    return is_nearly_coplanar(in_.point(t[0]), in_.point(t[1]), in_.point(t[2]), q, tolerance_);
  }

  // splits subsegment `s` at its midpoint if that lies on the edge (exactly,
  // or within the coplanarity tolerance off the axis planes) and on the
  // planes of the pieces around it; false if not
  bool split(const Subsegment& s)
  {
    const Point_3& a = point(s.u);
    const Point_3& b = point(s.v);
    if(CGAL::to_double(CGAL::squared_distance(a, b)) < 4. * min_split_length_ * min_split_length_) return false;
    const Point_3 m = CGAL::midpoint(a, b);
    const Point_3& e0 = in_.point(edge_ends_[s.edge][0]);
    const Point_3& e1 = in_.point(edge_ends_[s.edge][1]);
    if(!(CGAL::to_double((m - a) * (b - a)) > 0. && CGAL::to_double((m - b) * (a - b)) > 0.)) return false;
    bool tilted = false;
    for(std::size_t t : edge_tris_[s.edge]) tilted = tilted || frames_[piece_of_[t]].axis < 0;
    if(!tilted && !CGAL::collinear(e0, e1, m)) return false; // axis planes stay exact
    if(tilted)
    {
      // on the line as well as on the planes: a fault's free edge has one plane only
      if(!(CGAL::to_double(CGAL::squared_distance(m, typename GeomTraits::Line_3(e0, e1))) <= tolerance_ * tolerance_))
        return false;
      for(std::size_t t : edge_tris_[s.edge])
        if(!on_piece_plane(piece_of_[t], m)) return false;
    }
    const std::size_t id = np_ + extra_.size();
    extra_.push_back(m);
    const double t = CGAL::to_double((m - e0) * (e1 - e0));
    std::vector<std::pair<double, std::size_t> >& l = edge_points_[s.edge];
    l.insert(std::upper_bound(l.begin(), l.end(), std::make_pair(t, id)), std::make_pair(t, id));
    return true;
  }

  const Model& in_;
  const std::size_t np_, nt_;
  const double sin_bound_;
  const bool refine_;
  const bool refine_tilted_;
  const double tilted_size_factor_;
  const double tolerance_; // coplanar up to the rounding of the points (near_coplanarity.h)
  double min_split_length_ = 0.;
  double size_cap_ = std::numeric_limits<double>::infinity(); // the median input edge, or the size asked for
  std::size_t budget_ = 0;

  std::vector<std::array<std::size_t, 2> > edge_ends_;   // model point ids, first < second
  std::vector<std::vector<std::size_t> > edge_tris_;     // triangles of each edge
  std::vector<std::array<std::size_t, 3> > tri_edges_;   // edge k joins corners k and k+1
  std::vector<char> free_;                               // inside a piece
  std::vector<char> soft_;                               // may be split: only refinable pieces on it
  std::vector<char> well_shaped_;                        // not a single triangle under tilted_angle_bound
  std::vector<char> excluded_;                           // pieces whose refinement failed: not refined

  std::vector<std::vector<std::size_t> > pieces_;        // their triangles, in the input's order
  std::vector<std::size_t> piece_of_;                    // of each triangle
  std::vector<Frame> frames_;                            // of each piece

  std::vector<Point_3> extra_;                           // new points: ids np_, np_ + 1, ...
  std::vector<std::vector<std::pair<double, std::size_t> > > edge_points_; // new points on each edge, in order
  std::vector<std::vector<std::size_t> > inner_;         // new points inside each piece
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_PLANAR_PIECES_H
