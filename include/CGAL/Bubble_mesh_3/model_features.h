// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_MODEL_FEATURES_H
#define CGAL_BUBBLE_MESH_3_MODEL_FEATURES_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/remeshing_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

The features of a geological model that a surface re-meshing must keep: its
corners (0-cells), its curves (1-cells) and its patches (2-cells), as
`detect_model_features()` finds them. Indices refer to the points, triangles
and patches of the model the features were detected on.
*/
struct Model_features
{
  /// what makes the edges of a curve features
  enum class Curve_kind
  {
    CONTACT,    ///< two or more patches meet along it (an interface line)
    FREE,       ///< the free border of one patch, e.g. the tip of a fault ending inside a region
    SHARP,      ///< two triangles of one patch meeting at a dihedral above the feature angle
    NON_MANIFOLD ///< three or more triangles of one patch (a patch touching itself)
  };

  /// a polyline of feature edges with no corner inside it
  struct Curve
  {
    /// input point indices in order; for a closed curve `points.front() == points.back()`
    std::vector<std::size_t> points;
    /// the patches with triangles on the curve, each once, sorted
    std::vector<std::size_t> patches;
    /// number of triangles on each edge of the curve (the same for all its edges)
    std::size_t number_of_incident_triangles = 0;
    Curve_kind kind = Curve_kind::CONTACT; ///< why it is a feature
    bool is_closed = false;                ///< a loop without a corner
  };

  /// input point indices of the corners, sorted
  std::vector<std::size_t> corners;
  /// the curves, in a deterministic order (by their first point, then second)
  std::vector<Curve> curves;
  /// the triangles of each patch
  std::vector<std::vector<std::size_t> > patch_triangles;
  /// the curves that touch each patch (bounding it or lying inside it)
  std::vector<std::vector<std::size_t> > patch_curves;
  /// the feature angle used, in degrees
  double feature_angle = 30.;

  /// `true` if input point `i` is a corner
  bool is_corner(std::size_t i) const { return std::binary_search(corners.begin(), corners.end(), i); }
};

namespace internal {

struct Edge_key_hash
{
  std::size_t operator()(const std::pair<std::size_t, std::size_t>& e) const
  {
    return std::hash<std::size_t>()(e.first * 1000003u) ^ std::hash<std::size_t>()(e.second);
  }
};

typedef std::unordered_map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>, Edge_key_hash>
  Edge_triangles_map;

inline std::pair<std::size_t, std::size_t> edge_key(std::size_t a, std::size_t b)
{
  return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

// the triangles on each (undirected) edge of the model
template <class GeomTraits>
Edge_triangles_map edge_triangles(const Geological_model_3<GeomTraits>& model)
{
  Edge_triangles_map map;
  map.reserve(2 * model.number_of_triangles());
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& tri = model.triangle(t);
    for(int k = 0; k < 3; ++k) map[edge_key(tri[k], tri[(k + 1) % 3])].push_back(t);
  }
  return map;
}

template <class Vector>
double angle_between_degrees(const Vector& a, const Vector& b)
{
  const double la = std::sqrt(CGAL::to_double(a.squared_length()));
  const double lb = std::sqrt(CGAL::to_double(b.squared_length()));
  if(la == 0. || lb == 0.) return 0.;
  const double c = (std::max)(-1., (std::min)(1., CGAL::to_double(a * b) / (la * lb)));
  return std::acos(c) * 180. / 3.14159265358979323846;
}

template <class GeomTraits>
Model_features detect_model_features(const Geological_model_3<GeomTraits>& model, double angle,
                                     const std::vector<double>& crease_angles);

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Finds the corners, curves and patches of a validated geological model.

An edge is a feature edge when the triangles on it are not exactly two
triangles of the same patch (patches meet there, or it is the free border of
a surface inside a region - a fault tip), or when they are two triangles of
one patch whose normals make an angle above `feature_angle` (a sharp crease;
a sliver along the edge, whose height is under 5% of the edge length, makes
no crease: the normal of such a needle says little about the surface).
Feature edges chain into curves; a curve ends at a corner: a point with
other than two feature edges (three or more patch borders meet there, or a
curve ends), a point where the set of patches along the curve changes, or a
point where the curve turns by more than `feature_angle`. A loop without any
corner is one closed curve.

\param model a geological model that `validate_geological_model()` accepts
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{feature_angle}
    \cgalParamDescription{angle above which a curve turn makes a corner and a dihedral makes a feature edge}
    \cgalParamType{`double` (degrees)}
    \cgalParamDefault{30}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
Model_features detect_model_features(const Geological_model_3<GeomTraits>& model,
                                     const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return internal::detect_model_features(model, choose_parameter(get_parameter(np, internal_np::feature_angle), 30.),
                                         std::vector<double>());
}

namespace internal {

// detect_model_features() with, for each patch p with crease_angles[p] > 0,
// that angle instead of `angle` for the creases inside p (the faceted
// patches remesh_surfaces() keeps whole; an empty vector: none)
template <class GeomTraits>
Model_features detect_model_features(const Geological_model_3<GeomTraits>& model, double angle,
                                     const std::vector<double>& crease_angles)
{
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef std::pair<std::size_t, std::size_t> Edge;

  Model_features features;
  features.feature_angle = angle;

  features.patch_triangles.assign(model.number_of_patches(), std::vector<std::size_t>());
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    features.patch_triangles[model.patch_of_triangle(t)].push_back(t);

  const internal::Edge_triangles_map et = internal::edge_triangles(model);

  auto normal = [&](std::size_t t) {
    const auto& tri = model.triangle(t);
    return Vector_3(CGAL::cross_product(model.point(tri[1]) - model.point(tri[0]),
                                        model.point(tri[2]) - model.point(tri[0])));
  };

  // Feature edges, each with the signature of its triangles (patch of each, sorted):
  // a curve keeps one signature along its length.
  // A sliver along the edge (height under 5% of the edge length) has a
  // normal that says little about the surface: it makes no crease.
  auto is_sliver_along = [&](std::size_t t, const Edge& e) {
    const double l2 = CGAL::to_double(CGAL::squared_distance(model.point(e.first), model.point(e.second)));
    const double area2 = CGAL::to_double(normal(t).squared_length()); // (2 area)^2
    return area2 < 0.0025 * l2 * l2; // height = 2 area / l < 0.05 l
  };
  std::vector<Edge> feature_edges;
  for(const auto& e : et)
  {
    const std::vector<std::size_t>& ts = e.second;
    bool feature = true;
    if(ts.size() == 2 && model.patch_of_triangle(ts[0]) == model.patch_of_triangle(ts[1]))
    {
      const std::size_t p = model.patch_of_triangle(ts[0]);
      const double crease = (p < crease_angles.size() && crease_angles[p] > 0.) ? crease_angles[p] : angle;
      feature = !is_sliver_along(ts[0], e.first) && !is_sliver_along(ts[1], e.first) &&
                internal::angle_between_degrees(normal(ts[0]), normal(ts[1])) > crease;
    }
    if(feature) feature_edges.push_back(e.first);
  }
  std::sort(feature_edges.begin(), feature_edges.end()); // hash order is not deterministic

  auto signature = [&](const Edge& e) {
    std::vector<std::size_t> s;
    for(std::size_t t : et.at(e)) s.push_back(model.patch_of_triangle(t));
    std::sort(s.begin(), s.end());
    return s;
  };

  std::vector<std::vector<std::size_t> > adjacent(model.number_of_points());
  for(const Edge& e : feature_edges)
  {
    adjacent[e.first].push_back(e.second);
    adjacent[e.second].push_back(e.first);
  }

  std::vector<char> corner(model.number_of_points(), 0);
  for(std::size_t v = 0; v < adjacent.size(); ++v)
  {
    if(adjacent[v].empty()) continue;
    if(adjacent[v].size() != 2) { corner[v] = 1; continue; }
    const std::size_t a = adjacent[v][0], b = adjacent[v][1];
    if(signature(internal::edge_key(v, a)) != signature(internal::edge_key(v, b))) { corner[v] = 1; continue; }
    const Vector_3 in = model.point(v) - model.point(a), out = model.point(b) - model.point(v);
    if(internal::angle_between_degrees(in, out) > angle) corner[v] = 1;
  }

  // Walk the curves: first from every corner (in index order), then the loops left.
  std::unordered_map<Edge, char, internal::Edge_key_hash> used;
  used.reserve(2 * feature_edges.size());
  auto walk = [&](std::size_t start, std::size_t next) {
    Model_features::Curve c;
    c.points.push_back(start);
    std::size_t prev = start, cur = next;
    used[internal::edge_key(prev, cur)] = 1;
    for(;;)
    {
      c.points.push_back(cur);
      if(corner[cur] || cur == start) break;
      const std::size_t nx = (adjacent[cur][0] == prev) ? adjacent[cur][1] : adjacent[cur][0];
      prev = cur;
      cur = nx;
      used[internal::edge_key(prev, cur)] = 1;
    }
    c.is_closed = (c.points.front() == c.points.back()) && !corner[start];
    const std::vector<std::size_t>& ts = et.at(internal::edge_key(c.points[0], c.points[1]));
    c.number_of_incident_triangles = ts.size();
    for(std::size_t t : ts) c.patches.push_back(model.patch_of_triangle(t));
    std::sort(c.patches.begin(), c.patches.end());
    c.patches.erase(std::unique(c.patches.begin(), c.patches.end()), c.patches.end());
    if(c.patches.size() > 1) c.kind = Model_features::Curve_kind::CONTACT;
    else if(ts.size() == 1) c.kind = Model_features::Curve_kind::FREE;
    else if(ts.size() == 2) c.kind = Model_features::Curve_kind::SHARP;
    else c.kind = Model_features::Curve_kind::NON_MANIFOLD;
    features.curves.push_back(c);
  };
  for(std::size_t v = 0; v < adjacent.size(); ++v)
  {
    if(!corner[v]) continue;
    std::vector<std::size_t> nbs = adjacent[v];
    std::sort(nbs.begin(), nbs.end());
    for(std::size_t w : nbs)
      if(!used.count(internal::edge_key(v, w))) walk(v, w);
  }
  for(std::size_t v = 0; v < adjacent.size(); ++v)
  {
    std::vector<std::size_t> nbs = adjacent[v];
    std::sort(nbs.begin(), nbs.end());
    for(std::size_t w : nbs)
      if(!used.count(internal::edge_key(v, w))) walk(v, w); // v is the smallest point of its loop
  }

  for(std::size_t v = 0; v < corner.size(); ++v)
    if(corner[v]) features.corners.push_back(v);

  features.patch_curves.assign(model.number_of_patches(), std::vector<std::size_t>());
  for(std::size_t c = 0; c < features.curves.size(); ++c)
    for(std::size_t p : features.curves[c].patches) features.patch_curves[p].push_back(c);
  return features;
}

} // namespace internal

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_MODEL_FEATURES_H
