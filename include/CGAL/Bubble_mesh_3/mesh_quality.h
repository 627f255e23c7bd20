// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_MESH_QUALITY_H
#define CGAL_BUBBLE_MESH_3_MESH_QUALITY_H

#include <CGAL/Bubble_mesh_3/Quality_report.h>

#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Bubble_mesh_3/internal/union_find.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

A tetrahedral mesh as plain arrays, with a region label per tetrahedron: what
the quality report reads, what the file readers of `IO/read_tet_mesh.h` return,
and what `to_labeled_tetrahedral_mesh()` makes of a C3T3.

Boundary triangles are optional. When given they are the mesh facets on the
input surfaces (or on any labelled surface of a file); `input_min_angles`, when
not empty, gives for each of them the smallest angle (degrees) of the input
triangle it lies on (NaN where unknown), which the report uses to tell
tetrahedra that the input forces to be bad.
*/
struct Labeled_tetrahedral_mesh_3
{
  std::vector<std::array<double, 3> > points;                  ///< coordinates
  std::vector<std::array<std::size_t, 4> > tetrahedra;         ///< 0-based point indices
  std::vector<int> regions;                                    ///< one label per tetrahedron
  std::vector<std::array<std::size_t, 3> > boundary_triangles; ///< optional, 0-based
  std::vector<int> boundary_patches;    ///< one per boundary triangle, or empty (all 0)
  std::vector<double> input_min_angles; ///< one per boundary triangle, or empty (unknown)
  std::map<int, std::string> region_names; ///< optional names of region labels
};

/*!
\ingroup PkgBubbleMesh3Ref

Shape measures of one tetrahedron `(p0, p1, p2, p3)`. Angles are in degrees.
*/
struct Tetrahedron_quality
{
  /// dihedral angle at edge (0,1), (0,2), (0,3), (1,2), (1,3), (2,3): the angle
  /// between the two faces that share the edge, measured inside the tetrahedron
  std::array<double, 6> dihedral_angles;
  /// the three angles of each face, faces opposite p0, p1, p2, p3 in turn
  std::array<double, 12> face_angles;
  /// longest edge over shortest altitude (the altitude onto the largest face):
  /// sqrt(3/2) = 1.2247 for the regular tetrahedron, `+infinity` for a flat one
  double aspect_ratio;
  /// signed volume, positive when `CGAL::orientation(p0, p1, p2, p3) == POSITIVE`
  double volume;
  double min_dihedral_angle;  ///< smallest of `dihedral_angles`
  double max_dihedral_angle;  ///< largest of `dihedral_angles`
};

namespace internal {
// edge (i,j) of a tetrahedron and its two other vertices (k,l), in the order of
// `Tetrahedron_quality::dihedral_angles`
inline constexpr int tetrahedron_edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                                {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

computes the shape measures of the tetrahedron `(p0, p1, p2, p3)` in double precision.
`Point` is any type whose coordinates are read with `p[0]`, `p[1]`, `p[2]` and
`CGAL::to_double()` (CGAL points of any kernel, `std::array<double,3>`).
*/
template <class Point>
Tetrahedron_quality tetrahedron_quality(const Point& p0, const Point& p1,
                                        const Point& p2, const Point& p3)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Point_3 P;
  typedef K::Vector_3 V;
  auto to_p = [](const Point& p) {
    return P(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]));
  };
  const std::array<P, 4> p = {{to_p(p0), to_p(p1), to_p(p2), to_p(p3)}};

  Tetrahedron_quality q;
  const auto& edge = internal::tetrahedron_edges;
  double longest_squared = 0.;
  for(int e = 0; e < 6; ++e)
  {
    const int* v = edge[e];
    // CGAL's atan2 form stays accurate near 0 and 180 degrees, where slivers live;
    // its sign is orientation, not shape
    q.dihedral_angles[e] =
      std::abs(CGAL::approximate_dihedral_angle(p[v[0]], p[v[1]], p[v[2]], p[v[3]]));
    longest_squared = (std::max)(longest_squared, CGAL::squared_distance(p[v[0]], p[v[1]]));
  }
  q.min_dihedral_angle = *std::min_element(q.dihedral_angles.begin(), q.dihedral_angles.end());
  q.max_dihedral_angle = *std::max_element(q.dihedral_angles.begin(), q.dihedral_angles.end());

  double largest_area = 0.;
  static const int face[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for(int f = 0; f < 4; ++f)
  {
    const int* t = face[f];
    for(int k = 0; k < 3; ++k)
    {
      const P& o = p[t[k]];
      q.face_angles[3 * f + k] =
        CGAL::approximate_angle(V(o, p[t[(k + 1) % 3]]), V(o, p[t[(k + 2) % 3]]));
    }
    const V n = CGAL::cross_product(V(p[t[0]], p[t[1]]), V(p[t[0]], p[t[2]]));
    largest_area = (std::max)(largest_area, 0.5 * std::sqrt(n.squared_length()));
  }

  q.volume = CGAL::determinant(V(p[0], p[1]), V(p[0], p[2]), V(p[0], p[3])) / 6.;
  // shortest altitude = 3 V / largest face area
  const double volume = std::abs(q.volume);
  q.aspect_ratio = volume > 0.
                     ? std::sqrt(longest_squared) * largest_area / (3. * volume)
                     : std::numeric_limits<double>::infinity();
  return q;
}

namespace internal_np {
enum number_of_worst_tetrahedra_t { number_of_worst_tetrahedra };
enum number_of_steiner_points_t { number_of_steiner_points };
enum number_of_input_triangles_t { number_of_input_triangles };
enum number_of_input_triangles_kept_whole_t { number_of_input_triangles_kept_whole };
enum facet_input_min_angle_t { facet_input_min_angle };
enum surface_angle_source_t { surface_angle_source };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgBubbleMesh3Ref
/// `compute_mesh_quality()`: how many of the worst tetrahedra to list (default 20)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_worst_tetrahedra)
/// \ingroup PkgBubbleMesh3Ref
/// `compute_mesh_quality()`: Steiner points the mesher inserted, copied into the report
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_steiner_points)
/// \ingroup PkgBubbleMesh3Ref
/// `compute_mesh_quality()`: input surface triangles, copied into the report
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_input_triangles)
/// \ingroup PkgBubbleMesh3Ref
/// `compute_mesh_quality()`: input triangles that are one mesh facet (not split), copied into the report
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_input_triangles_kept_whole)
/// \ingroup PkgBubbleMesh3Ref
/// `compute_mesh_quality()`: what the surface angles are, for `Mesh_quality_report::surface_angle_source`
/// (say so when `facet_input_min_angle` gives something other than the input triangles' angles)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::string, surface_angle_source)

/// \ingroup PkgBubbleMesh3Ref
/// `to_labeled_tetrahedral_mesh()`: a callable `double(const C3T3::Facet&)` giving the
/// smallest angle (degrees) of the input triangle a complex facet lies on, NaN if unknown
template <class F>
Named_function_parameters<F, internal_np::facet_input_min_angle_t> facet_input_min_angle(const F& f)
{
  return Named_function_parameters<F, internal_np::facet_input_min_angle_t>(f);
}
template <class F, class T, class Tag, class Base>
Named_function_parameters<F, internal_np::facet_input_min_angle_t, Named_function_parameters<T, Tag, Base> >
facet_input_min_angle(const F& f, const Named_function_parameters<T, Tag, Base>& np)
{
  return Named_function_parameters<F, internal_np::facet_input_min_angle_t,
                                   Named_function_parameters<T, Tag, Base> >(f, np);
}

} // namespace parameters

namespace internal {

// a label as an int: integral indices as they are; other index types (pairs,
// variants) cannot be ordered as one number, so they all become label 1
template <class Index>
int label_as_int(const Index& i)
{
  if constexpr(std::is_arithmetic<Index>::value || std::is_enum<Index>::value)
    return static_cast<int>(i);
  else
    return 1;
}

inline double smallest_triangle_angle(const std::array<double, 3>& a,
                                      const std::array<double, 3>& b,
                                      const std::array<double, 3>& c)
{
  typedef CGAL::Simple_cartesian<double>::Point_3 P;
  typedef CGAL::Simple_cartesian<double>::Vector_3 V;
  const P pa(a[0], a[1], a[2]), pb(b[0], b[1], b[2]), pc(c[0], c[1], c[2]);
  return (std::min)({CGAL::approximate_angle(V(pa, pb), V(pa, pc)),
                     CGAL::approximate_angle(V(pb, pc), V(pb, pa)),
                     CGAL::approximate_angle(V(pc, pa), V(pc, pb))});
}

// accumulates one region's numbers tet by tet; the merged model is the merge
// of the regions (so its sums do not depend on how a file orders the regions)
struct Region_accumulator
{
  Region_quality q;
  std::vector<double> aspect_ratios;
  double dihedral_sum = 0., smallest_dihedral_sum = 0.;
  std::array<std::size_t, 4> under = {{0, 0, 0, 0}};
  std::size_t above_10 = 0, above_40 = 0, under_10_unexplained = 0, under_10_at_sharp_contact = 0;
  std::size_t under_10_not_touching = 0; // of the unexplained, no vertex on a small surface angle either

  void add(const Tetrahedron_quality& t, bool unexplained_under_10)
  {
    ++q.number_of_tetrahedra;
    q.volume += std::abs(t.volume);
    if(t.volume == 0.) ++q.number_of_degenerate_tetrahedra;
    if(t.volume < 0.) ++q.number_of_negatively_oriented_tetrahedra;
    for(double a : t.dihedral_angles)
    {
      dihedral_sum += a;
      q.dihedral_angle_histogram.add(a);
    }
    q.min_dihedral_angle = std::fmin(q.min_dihedral_angle, t.min_dihedral_angle);
    q.max_dihedral_angle = std::fmax(q.max_dihedral_angle, t.max_dihedral_angle);
    smallest_dihedral_sum += t.min_dihedral_angle;
    for(std::size_t k = 0; k < 4; ++k)
      if(t.min_dihedral_angle < Region_quality::dihedral_thresholds[k]) ++under[k];
    if(unexplained_under_10) ++under_10_unexplained;
    for(double a : t.face_angles)
    {
      q.face_angle_histogram.add(a);
      q.min_face_angle = std::fmin(q.min_face_angle, a);
      q.max_face_angle = std::fmax(q.max_face_angle, a);
    }
    aspect_ratios.push_back(t.aspect_ratio);
    q.aspect_ratio_histogram.add(t.aspect_ratio);
    if(t.aspect_ratio > 10.) ++above_10;
    if(t.aspect_ratio > 40.) ++above_40;
  }

  void merge(const Region_accumulator& o)
  {
    q.number_of_tetrahedra += o.q.number_of_tetrahedra;
    q.volume += o.q.volume;
    q.number_of_degenerate_tetrahedra += o.q.number_of_degenerate_tetrahedra;
    q.number_of_negatively_oriented_tetrahedra += o.q.number_of_negatively_oriented_tetrahedra;
    q.min_dihedral_angle = std::fmin(q.min_dihedral_angle, o.q.min_dihedral_angle);
    q.max_dihedral_angle = std::fmax(q.max_dihedral_angle, o.q.max_dihedral_angle);
    q.min_face_angle = std::fmin(q.min_face_angle, o.q.min_face_angle);
    q.max_face_angle = std::fmax(q.max_face_angle, o.q.max_face_angle);
    q.dihedral_angle_histogram.merge(o.q.dihedral_angle_histogram);
    q.face_angle_histogram.merge(o.q.face_angle_histogram);
    q.aspect_ratio_histogram.merge(o.q.aspect_ratio_histogram);
    aspect_ratios.insert(aspect_ratios.end(), o.aspect_ratios.begin(), o.aspect_ratios.end());
    dihedral_sum += o.dihedral_sum;
    smallest_dihedral_sum += o.smallest_dihedral_sum;
    for(std::size_t k = 0; k < 4; ++k) under[k] += o.under[k];
    above_10 += o.above_10;
    above_40 += o.above_40;
    under_10_unexplained += o.under_10_unexplained;
    under_10_at_sharp_contact += o.under_10_at_sharp_contact;
    under_10_not_touching += o.under_10_not_touching;
  }

  Region_quality finish(std::size_t number_of_vertices, bool surfaces_known)
  {
    const std::size_t n = q.number_of_tetrahedra;
    q.number_of_vertices = number_of_vertices;
    if(n > 0)
    {
      const double dn = double(n);
      q.mean_dihedral_angle = dihedral_sum / (6. * dn);
      q.mean_smallest_dihedral_angle = smallest_dihedral_sum / dn;
      for(std::size_t k = 0; k < 4; ++k) q.share_smallest_dihedral_under[k] = double(under[k]) / dn;
      if(surfaces_known)
      {
        q.share_under_10_not_at_small_surface_angle = double(under_10_unexplained) / dn;
        q.share_under_10_at_sharp_contact = double(under_10_at_sharp_contact) / dn;
        q.share_under_10_not_touching_small_surface_angle = double(under_10_not_touching) / dn;
      }
      q.min_aspect_ratio = *std::min_element(aspect_ratios.begin(), aspect_ratios.end());
      q.max_aspect_ratio = *std::max_element(aspect_ratios.begin(), aspect_ratios.end());
      // median: the middle value, or the mean of the two middle values
      const auto middle = aspect_ratios.begin() + std::ptrdiff_t(n / 2);
      std::nth_element(aspect_ratios.begin(), middle, aspect_ratios.end());
      q.median_aspect_ratio = *middle;
      if(n % 2 == 0) q.median_aspect_ratio = 0.5 * (q.median_aspect_ratio + *std::max_element(aspect_ratios.begin(), middle));
      q.share_aspect_ratio_above_10 = double(above_10) / dn;
      q.share_aspect_ratio_above_40 = double(above_40) / dn;
    }
    q.aspect_ratio_histogram.normalize();
    q.face_angle_histogram.normalize();
    q.dihedral_angle_histogram.normalize();
    return q;
  }
};

// boundary triangles by edge: which patches, and the smallest surface angle, touch an edge
class Surface_edge_index
{
public:
  typedef std::pair<std::size_t, std::size_t> Edge;

  explicit Surface_edge_index(const Labeled_tetrahedral_mesh_3& m)
  {
    CGAL_precondition(m.boundary_patches.empty() || m.boundary_patches.size() == m.boundary_triangles.size());
    CGAL_precondition(m.input_min_angles.empty() || m.input_min_angles.size() == m.boundary_triangles.size());
    const std::size_t nb = m.boundary_triangles.size();
    vertex_min_angles_.assign(m.points.size(), std::nan(""));
    for(std::size_t i = 0; i < nb; ++i)
    {
      const std::array<std::size_t, 3>& t = m.boundary_triangles[i];
      double angle = m.input_min_angles.empty() ? std::nan("") : m.input_min_angles[i];
      if(m.input_min_angles.empty())
        angle = smallest_triangle_angle(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
      const int patch = m.boundary_patches.empty() ? 0 : m.boundary_patches[i];
      for(int k = 0; k < 3; ++k)
      {
        entries_.push_back(std::make_tuple(edge(t[k], t[(k + 1) % 3]), patch, angle));
        vertex_min_angles_[t[k]] = std::fmin(vertex_min_angles_[t[k]], angle);
      }
      std::array<std::size_t, 3> s = t;
      std::sort(s.begin(), s.end());
      faces_.push_back(s);
    }
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) {
                return std::make_pair(std::get<0>(a), std::get<1>(a)) <
                       std::make_pair(std::get<0>(b), std::get<1>(b));
              });
    std::sort(faces_.begin(), faces_.end());
  }

  static Edge edge(std::size_t a, std::size_t b) { return a < b ? Edge(a, b) : Edge(b, a); }

  bool empty() const { return faces_.empty(); }

  // smallest surface angle over the triangles sharing an edge with `tet` (NaN:
  // none, or unknown), and their patches when `patches` is given
  double touching_min_angle(const std::array<std::size_t, 4>& tet, std::vector<int>* patches = nullptr) const
  {
    double r = std::nan("");
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
      {
        const Edge e = edge(tet[i], tet[j]);
        for(auto it = first_entry(e); it != entries_.end() && std::get<0>(*it) == e; ++it)
        {
          r = std::fmin(r, std::get<2>(*it));
          if(patches) patches->push_back(std::get<1>(*it));
        }
      }
    if(patches)
    {
      std::sort(patches->begin(), patches->end());
      patches->erase(std::unique(patches->begin(), patches->end()), patches->end());
    }
    return r;
  }

  // smallest surface angle over the triangles with a vertex of `tet` (NaN: none, or unknown)
  double vertex_touching_min_angle(const std::array<std::size_t, 4>& tet) const
  {
    double r = std::nan("");
    for(std::size_t v : tet) r = std::fmin(r, vertex_min_angles_[v]);
    return r;
  }

  bool is_edge(const Edge& e) const
  {
    const auto it = first_entry(e);
    return it != entries_.end() && std::get<0>(*it) == e;
  }

  bool is_face(std::size_t a, std::size_t b, std::size_t c) const
  {
    std::array<std::size_t, 3> s = {{a, b, c}};
    std::sort(s.begin(), s.end());
    return std::binary_search(faces_.begin(), faces_.end(), s);
  }

  int boundary_faces(const std::array<std::size_t, 4>& tet) const
  {
    int n = 0;
    for(int f = 0; f < 4; ++f)
    {
      std::array<std::size_t, 3> s = {{tet[(f + 1) % 4], tet[(f + 2) % 4], tet[(f + 3) % 4]}};
      std::sort(s.begin(), s.end());
      if(std::binary_search(faces_.begin(), faces_.end(), s)) ++n;
    }
    return n;
  }

private:
  typedef std::tuple<Edge, int, double> Entry;

  // the first entry of edge `e`, or the one after where it would be
  typename std::vector<Entry>::const_iterator first_entry(const Edge& e) const
  {
    return std::lower_bound(entries_.begin(), entries_.end(), e,
                            [](const Entry& a, const Edge& x) { return std::get<0>(a) < x; });
  }

  std::vector<Entry> entries_;
  std::vector<std::array<std::size_t, 3> > faces_;
  std::vector<double> vertex_min_angles_; // by point: smallest surface angle of its triangles, NaN if none
};

// The angles of each region between the surfaces at the boundary edges. Around
// a boundary edge, the tets of a region that follow one another across facets
// that are not boundary triangles form a sector; its angle is the sum of their
// dihedral angles at the edge (a pinch-out gives a few degrees, a plane 180).
// Kept per vertex and region: the smallest angle of the sectors at the
// boundary edges through the vertex.
class Contact_sectors
{
public:
  explicit Contact_sectors(const Labeled_tetrahedral_mesh_3& m) : on_boundary_(m.points.size(), false)
  {
    CGAL_precondition(m.points.size() <= (std::numeric_limits<std::uint32_t>::max)());
    for(const std::array<std::size_t, 3>& t : m.boundary_triangles)
      for(std::size_t v : t) on_boundary_[v] = true;
  }

  // a tet of `region` with dihedral angle `angle` at its edge (a, b), c and d
  // its other vertices, tets added in a fixed order (the sums follow it); only
  // edges on a boundary triangle are kept
  void add(const Surface_edge_index& surfaces, int region, std::size_t a, std::size_t b, std::size_t c,
           std::size_t d, double angle)
  {
    if(!on_boundary_[a] || !on_boundary_[b]) return;
    const Surface_edge_index::Edge e = Surface_edge_index::edge(a, b);
    if(!surfaces.is_edge(e)) return;
    around_.push_back(Around{{{std::uint32_t(e.first), std::uint32_t(e.second)}}, std::uint32_t(c), std::uint32_t(d),
                             region, angle});
  }

  // the sectors, once every tet was added
  void finish(const Surface_edge_index& surfaces)
  {
    std::stable_sort(around_.begin(), around_.end(), [](const Around& x, const Around& y) {
      return std::make_pair(x.edge, x.region) < std::make_pair(y.edge, y.region);
    });
    std::vector<double> sum;
    for(std::size_t first = 0; first < around_.size();)
    {
      std::size_t last = first + 1;
      while(last < around_.size() && around_[last].edge == around_[first].edge &&
            around_[last].region == around_[first].region)
        ++last;
      // tets sharing a facet through the edge that is no boundary triangle are one sector
      const std::size_t k = last - first;
      std::vector<std::size_t> parent = uf_singletons(k);
      const std::array<std::uint32_t, 2>& e = around_[first].edge;
      for(std::size_t i = 0; i < k; ++i)
        for(std::size_t j = i + 1; j < k; ++j)
        {
          const Around &x = around_[first + i], &y = around_[first + j];
          for(std::size_t v : {x.c, x.d})
            if((v == y.c || v == y.d) && !surfaces.is_face(e[0], e[1], v)) uf_union(parent, i, j);
        }
      sum.assign(k, 0.);
      for(std::size_t i = 0; i < k; ++i) sum[uf_find(parent, i)] += around_[first + i].angle;
      for(std::size_t i = 0; i < k; ++i)
        if(parent[i] == i) // once per sector
        {
          for(std::size_t v : e) smallest_.push_back(std::make_tuple(v, around_[first].region, sum[i]));
          if(sum[i] < sharp_angle) add_wedge(surfaces, first, k, parent, i);
        }
      first = last;
    }
    around_.clear();
    around_.shrink_to_fit();
    // the smallest per (vertex, region), first after the sort
    std::sort(smallest_.begin(), smallest_.end());
    smallest_.erase(std::unique(smallest_.begin(), smallest_.end(),
                                [](const Entry& x, const Entry& y) {
                                  return std::get<0>(x) == std::get<0>(y) && std::get<1>(x) == std::get<1>(y);
                                }),
                    smallest_.end());
  }

  // smallest sector angle of `region` at the boundary edges through `v`; NaN if none
  double smallest_at(std::size_t v, int region) const
  {
    auto it = std::lower_bound(smallest_.begin(), smallest_.end(), std::make_tuple(v, region, -1.));
    return it != smallest_.end() && std::get<0>(*it) == v && std::get<1>(*it) == region ? std::get<2>(*it)
                                                                                          : std::nan("");
  }

  double smallest_at(const std::array<std::size_t, 4>& tet, int region) const
  {
    double r = std::nan("");
    for(std::size_t v : tet) r = std::fmin(r, smallest_at(v, region));
    return r;
  }

  // Whether `tet` of `region` lies inside the sector of the sharp contact
  // nearest to its centroid where that sector is thinner (the centroid's
  // distances to its two walls added) than the tet's longest edge: in a wedge
  // of angle theta that is every tet within L / theta of the contact line, and
  // no tet of size L fits across there.
  bool in_thin_wedge(const std::vector<std::array<double, 3> >& points, const std::array<std::size_t, 4>& tet,
                     int region)
  {
    const auto found = wedges_.find(region);
    if(found == wedges_.end()) return false;
    Wedge_search& ws = found->second;
    if(!ws.tree)
    {
      for(const Wedge& w : ws.wedges) ws.segments.push_back(Segment(point(points, w.edge[0]), point(points, w.edge[1])));
      ws.tree.reset(new Tree(ws.segments.begin(), ws.segments.end()));
      ws.tree->accelerate_distance_queries();
    }
    Vector c(0., 0., 0.);
    double longest = 0.;
    for(int i = 0; i < 4; ++i)
    {
      c = c + (point(points, tet[i]) - CGAL::ORIGIN) / 4.;
      for(int j = i + 1; j < 4; ++j)
        longest = (std::max)(longest, std::sqrt(CGAL::squared_distance(point(points, tet[i]), point(points, tet[j]))));
    }
    const Point centroid = CGAL::ORIGIN + c;
    const Wedge& w = ws.wedges[std::size_t(ws.tree->closest_point_and_primitive(centroid).second - ws.segments.begin())];
    const Point a = point(points, w.edge[0]), b = point(points, w.edge[1]);
    const Point w1 = point(points, w.w1), w2 = point(points, w.w2);
    // the centroid's distance to the wall through (a, b, from), towards the other wall `to`
    auto inside = [&](const Point& from, const Point& to) {
      Vector n = CGAL::cross_product(b - a, from - a);
      const double len = std::sqrt(n.squared_length());
      if(!(len > 0.)) return std::nan("");
      if((to - a) * n < 0.) n = -n;
      return ((centroid - a) * n) / len;
    };
    const double s1 = inside(w1, w2), s2 = inside(w2, w1);
    return s1 >= 0. && s2 >= 0. && s1 + s2 < longest;
  }

  /// sectors under this many degrees are sharp contacts
  static constexpr double sharp_angle = 10.;

private:
  struct Around
  {
    std::array<std::uint32_t, 2> edge; // sorted
    std::uint32_t c, d;                // the tet's other vertices
    int region;
    double angle;                      // its dihedral angle at the edge
  };
  typedef std::tuple<std::size_t, int, double> Entry;
  typedef CGAL::Simple_cartesian<double> SK;
  typedef SK::Point_3 Point;
  typedef SK::Vector_3 Vector;
  typedef SK::Segment_3 Segment;
  typedef std::vector<Segment>::const_iterator Segment_iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<SK, CGAL::AABB_segment_primitive<SK, Segment_iterator> > > Tree;
  // a sharp sector: its edge and the third vertices of its two walls
  struct Wedge
  {
    std::array<std::uint32_t, 2> edge;
    std::uint32_t w1, w2;
  };
  // a region's sharp sectors, searched (built on the first query) by their edges
  struct Wedge_search
  {
    std::vector<Wedge> wedges;
    std::vector<Segment> segments;
    std::unique_ptr<Tree> tree;
  };

  static Point point(const std::vector<std::array<double, 3> >& points, std::size_t v)
  {
    return Point(points[v][0], points[v][1], points[v][2]);
  }

  // the sector of root `root` among the k entries from `first`: kept when two
  // boundary triangles through its edge bound it
  void add_wedge(const Surface_edge_index& surfaces, std::size_t first, std::size_t k,
                 std::vector<std::size_t>& parent, std::size_t root)
  {
    const std::array<std::uint32_t, 2>& e = around_[first].edge;
    std::vector<std::uint32_t> walls;
    for(std::size_t j = 0; j < k; ++j)
      if(uf_find(parent, j) == root)
        for(std::uint32_t v : {around_[first + j].c, around_[first + j].d})
          if(surfaces.is_face(e[0], e[1], v) && std::find(walls.begin(), walls.end(), v) == walls.end())
            walls.push_back(v);
    if(walls.size() == 2) wedges_[around_[first].region].wedges.push_back(Wedge{e, walls[0], walls[1]});
  }

  std::vector<bool> on_boundary_;
  std::vector<Around> around_;
  std::vector<Entry> smallest_;
  std::map<int, Wedge_search> wedges_;
};

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

computes the quality report of a labelled tetrahedral mesh: per region (in
increasing label order) and for the merged model, the counts, volume, dihedral,
face-angle and aspect-ratio statistics and histograms of `Region_quality`, and
the worst tetrahedra by smallest dihedral angle (ties: lower index first).

Definitions (per tetrahedron, see `tetrahedron_quality()`): 6 dihedral angles,
12 face angles (so an interior triangle counts once per tetrahedron it bounds),
aspect ratio = longest edge / shortest altitude (regular tetrahedron:
sqrt(3/2) = 1.2247; the paper's 0.81 is the reciprocal normalisation, not used here).

A tetrahedron "touches" a surface triangle when they share at least an edge
(a contact sector between two surfaces is bounded by such edges). The surface
angle of a boundary triangle is `mesh.input_min_angles[i]` when given, else the
triangle's own smallest angle.
A tetrahedron under 10 degrees that touches no surface angle under 10 is
further counted "at a sharp contact" when one of its vertices lies on a
boundary edge where its region's angle between the surfaces is under 10
degrees (a pinch-out), or when it lies inside that angle where the wedge
between the two surfaces is thinner than its longest edge: see
`Region_quality::share_under_10_at_sharp_contact`. Touching at a vertex
only is counted apart: `Region_quality::share_under_10_not_touching_small_surface_angle`
leaves out the tetrahedra with a vertex on a surface angle under 10.

\pre every index of `mesh.tetrahedra` and `mesh.boundary_triangles` is smaller than `mesh.points.size()`,
`mesh.regions.size() == mesh.tetrahedra.size()`

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_worst_tetrahedra}
    \cgalParamDescription{how many worst tetrahedra to list}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{20}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_steiner_points}
    \cgalParamDescription{copied into the report}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{unknown (not printed)}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_input_triangles}
    \cgalParamDescription{copied into the report}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{unknown (not printed)}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_input_triangles_kept_whole}
    \cgalParamDescription{copied into the report}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{unknown (not printed)}
  \cgalParamNEnd
  \cgalParamNBegin{surface_angle_source}
    \cgalParamDescription{what `mesh.input_min_angles` holds, copied into the report when the mesh has
      boundary triangles}
    \cgalParamType{`std::string`}
    \cgalParamDefault{`"input triangles"` when `mesh.input_min_angles` is given, else `"boundary facets"`}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_quality_report compute_mesh_quality(const Labeled_tetrahedral_mesh_3& mesh,
                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;

  CGAL_precondition(mesh.regions.size() == mesh.tetrahedra.size());
  const std::size_t n = mesh.tetrahedra.size();

  Mesh_quality_report r;
  r.number_of_points = mesh.points.size();
  r.number_of_boundary_triangles = mesh.boundary_triangles.size();
  if(!mesh.boundary_triangles.empty())
    r.surface_angle_source =
      choose_parameter(get_parameter(np, internal_np::surface_angle_source),
                       std::string(mesh.input_min_angles.empty() ? "boundary facets" : "input triangles"));
  if(!is_default_parameter<NamedParameters, internal_np::number_of_steiner_points_t>::value)
    r.number_of_steiner_points = choose_parameter(get_parameter(np, internal_np::number_of_steiner_points), std::size_t(0));
  if(!is_default_parameter<NamedParameters, internal_np::number_of_input_triangles_t>::value)
    r.number_of_input_triangles = choose_parameter(get_parameter(np, internal_np::number_of_input_triangles), std::size_t(0));
  if(!is_default_parameter<NamedParameters, internal_np::number_of_input_triangles_kept_whole_t>::value)
    r.number_of_input_triangles_kept_whole =
      choose_parameter(get_parameter(np, internal_np::number_of_input_triangles_kept_whole), std::size_t(0));
  const std::size_t number_of_worst =
    choose_parameter(get_parameter(np, internal_np::number_of_worst_tetrahedra), std::size_t(20));

  const internal::Surface_edge_index surfaces(mesh);
  const bool surfaces_known = !surfaces.empty();
  internal::Contact_sectors sectors(mesh);
  std::vector<std::size_t> unexplained_under_10; // by the surface angles

  std::map<int, internal::Region_accumulator> per_region;
  // what the worst-tet list needs of each tet, kept small for meshes of millions
  struct Kept { double min_dihedral, max_dihedral, aspect_ratio, volume; };
  std::vector<Kept> tq(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::array<std::size_t, 4>& t = mesh.tetrahedra[i];
    for(std::size_t v : t) CGAL_precondition(v < mesh.points.size());
    const Tetrahedron_quality q =
      tetrahedron_quality(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]);
    tq[i] = Kept{q.min_dihedral_angle, q.max_dihedral_angle, q.aspect_ratio, std::abs(q.volume)};
    bool unexplained = false;
    if(q.min_dihedral_angle < 10. && surfaces_known)
    {
      const double a = surfaces.touching_min_angle(t);
      unexplained = !(a < 10.); // NaN (touches nothing) counts as unexplained
      if(unexplained) unexplained_under_10.push_back(i);
    }
    per_region[mesh.regions[i]].add(q, unexplained);
    if(surfaces_known)
    {
      const auto& edge = internal::tetrahedron_edges;
      for(int e = 0; e < 6; ++e)
        sectors.add(surfaces, mesh.regions[i], t[edge[e][0]], t[edge[e][1]], t[edge[e][2]], t[edge[e][3]],
                    q.dihedral_angles[e]);
    }
  }
  sectors.finish(surfaces);
  for(std::size_t i : unexplained_under_10)
  {
    internal::Region_accumulator& acc = per_region[mesh.regions[i]];
    if(sectors.smallest_at(mesh.tetrahedra[i], mesh.regions[i]) < internal::Contact_sectors::sharp_angle ||
       sectors.in_thin_wedge(mesh.points, mesh.tetrahedra[i], mesh.regions[i]))
      ++acc.under_10_at_sharp_contact;
    if(!(surfaces.vertex_touching_min_angle(mesh.tetrahedra[i]) < 10.)) ++acc.under_10_not_touching;
  }

  // distinct vertices: tets grouped by region, a stamp per point
  std::map<int, std::size_t> slot;
  for(const auto& rq : per_region) slot.emplace(rq.first, slot.size());
  std::vector<std::size_t> first(slot.size() + 1, 0), by_region(n);
  for(std::size_t i = 0; i < n; ++i) ++first[slot[mesh.regions[i]] + 1];
  for(std::size_t k = 1; k < first.size(); ++k) first[k] += first[k - 1];
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for(std::size_t i = 0; i < n; ++i) by_region[next[slot[mesh.regions[i]]]++] = i;
  }
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  std::vector<std::size_t> stamp(mesh.points.size(), none);
  std::vector<std::size_t> region_vertices(slot.size(), 0);
  std::size_t all_vertices = 0;
  for(std::size_t k = 0; k < slot.size(); ++k)
    for(std::size_t j = first[k]; j < first[k + 1]; ++j)
      for(std::size_t v : mesh.tetrahedra[by_region[j]])
        if(stamp[v] != k)
        {
          if(stamp[v] == none) ++all_vertices;
          stamp[v] = k;
          ++region_vertices[k];
        }

  internal::Region_accumulator all;
  for(auto& rq : per_region)
  {
    all.merge(rq.second);
    r.regions.push_back(rq.second.finish(region_vertices[slot[rq.first]], surfaces_known));
    r.regions.back().region = rq.first;
    auto name = mesh.region_names.find(rq.first);
    if(name != mesh.region_names.end()) r.regions.back().name = name->second;
  }
  r.all = all.finish(all_vertices, surfaces_known);

  // worst first; the index breaks ties so that the list is deterministic
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i) order[i] = i;
  const std::size_t k = (std::min)(number_of_worst, n);
  std::partial_sort(order.begin(), order.begin() + k, order.end(),
                    [&](std::size_t a, std::size_t b) {
                      return std::make_pair(tq[a].min_dihedral, a) < std::make_pair(tq[b].min_dihedral, b);
                    });
  for(std::size_t j = 0; j < k; ++j)
  {
    const std::size_t i = order[j];
    const std::array<std::size_t, 4>& t = mesh.tetrahedra[i];
    Worst_tetrahedron w;
    w.index = i;
    w.region = mesh.regions[i];
    w.vertices = t;
    for(int c = 0; c < 3; ++c)
      w.centroid[c] = 0.25 * (mesh.points[t[0]][c] + mesh.points[t[1]][c] +
                              mesh.points[t[2]][c] + mesh.points[t[3]][c]);
    w.min_dihedral_angle = tq[i].min_dihedral;
    w.max_dihedral_angle = tq[i].max_dihedral;
    w.aspect_ratio = tq[i].aspect_ratio;
    w.volume = tq[i].volume;
    w.boundary_faces = surfaces.boundary_faces(t);
    w.touching_surface_min_angle = surfaces.touching_min_angle(t, &w.touching_patches);
    w.contact_min_angle = sectors.smallest_at(t, w.region);
    r.worst_tetrahedra.push_back(w);
  }
  return r;
}

/*!
\ingroup PkgBubbleMesh3Ref

converts the cells and facets of a complex (`CGAL::Mesh_complex_3_in_triangulation_3`
or any type with the same cell and facet iterators) into a `Labeled_tetrahedral_mesh_3`:
each cell in the complex becomes a tetrahedron with region `subdomain_index(c)`,
each facet in the complex a boundary triangle with patch `surface_patch_index(f)`.
Points are numbered in the order the cells and then the facets first meet them.
Integral indices are kept as they are; other index types become label 1.

\cgalNamedParamsBegin
  \cgalParamNBegin{facet_input_min_angle}
    \cgalParamDescription{a callable `double(const C3T3::Facet&)`: the smallest angle (degrees)
      of the input triangle a complex facet lies on, NaN if unknown}
    \cgalParamType{a callable}
    \cgalParamDefault{none: the report then uses each facet's own smallest angle}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class C3T3, class NamedParameters = CGAL::parameters::Default_named_parameters>
Labeled_tetrahedral_mesh_3 to_labeled_tetrahedral_mesh(const C3T3& c3t3,
                                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename C3T3::Triangulation::Vertex_handle Vertex_handle;
  typedef typename C3T3::Facet Facet;
  Labeled_tetrahedral_mesh_3 m;
  std::map<Vertex_handle, std::size_t> index;
  auto number = [&](Vertex_handle v) {
    auto ins = index.insert(std::make_pair(v, m.points.size()));
    if(ins.second)
      m.points.push_back({{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()),
                           CGAL::to_double(v->point().z())}});
    return ins.first->second;
  };
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    m.tetrahedra.push_back({{number(c->vertex(0)), number(c->vertex(1)),
                             number(c->vertex(2)), number(c->vertex(3))}});
    m.regions.push_back(internal::label_as_int(c3t3.subdomain_index(c)));
  }

  constexpr bool has_angles =
    !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::facet_input_min_angle_t>::value;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    const Facet& facet = *f;
    std::array<std::size_t, 3> t;
    for(int k = 0, j = 0; k < 4; ++k)
      if(k != facet.second) t[j++] = number(facet.first->vertex(k));
    m.boundary_triangles.push_back(t);
    m.boundary_patches.push_back(internal::label_as_int(c3t3.surface_patch_index(facet)));
    if constexpr(has_angles)
      m.input_min_angles.push_back(CGAL::parameters::get_parameter(np, internal_np::facet_input_min_angle)(facet));
  }
  return m;
}

/*!
\ingroup PkgBubbleMesh3Ref

computes the quality report of a complex: `compute_mesh_quality(to_labeled_tetrahedral_mesh(c3t3, np), np)`.
*/
template <class C3T3, class NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_quality_report compute_c3t3_quality(const C3T3& c3t3,
                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  return compute_mesh_quality(to_labeled_tetrahedral_mesh(c3t3, np), np);
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_MESH_QUALITY_H
