// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_MEASURES_H
#define CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_MEASURES_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/centred_coordinates.h>
#include <CGAL/Bubble_mesh_3/internal/union_find.h>
#include <CGAL/Bubble_mesh_3/internal/vertex_angle.h>
#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

Signed volume enclosed by each region's boundary, by the divergence theorem
over the triangles of the patches that have the region on exactly one side.
Entry `r` is the volume of region `r`; entry 0 is the volume enclosed by the
model's outer boundary (the patches that touch the outside), positive when
the model is oriented as `Geological_model_3` documents.

The sum is taken relative to the centre of the bounding box, so that models
far from the origin (real coordinates in metres) lose no digits.
*/
template <class GeomTraits>
std::vector<double> region_volumes(const Geological_model_3<GeomTraits>& model)
{
  std::vector<double> vol(model.number_of_regions() + 1, 0.);
  const internal::Centred_point o = internal::box_centre(model);
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& patch = model.patch(model.patch_of_triangle(t));
    if(patch.is_inside_region()) continue;
    const auto& tri = model.triangle(t);
    // positive when the normal (right-hand rule) points away from the centre's side
    const double v = internal::signed_volume(internal::centred(model.point(tri[0]), o),
                                             internal::centred(model.point(tri[1]), o),
                                             internal::centred(model.point(tri[2]), o));
    // the negative region sees the normal pointing out of it
    vol[patch.negative_region] += v;
    vol[patch.positive_region] -= v;
  }
  // region 0 collected the outer boundary with the sign of the outside: flip it
  vol[0] = -vol[0];
  return vol;
}

/*!
\ingroup PkgBubbleMesh3Ref

How sharply a region's surfaces meet: at each input edge, the angle of the
region between two consecutive triangles around the edge (its dihedral angle
there, in degrees; 180 on a flat surface, 90 at the corner of a box). Under
about 10 degrees no conforming mesh has good tetrahedra at the edge: a layer
pinching out between two horizons, a fault meeting a horizon at a low angle,
or a surface folded back on itself.
*/
struct Region_contact_angles
{
  /// the smallest angle of the region at an edge of two of its triangles (NaN: no such edge)
  double min_angle = std::numeric_limits<double>::quiet_NaN();
  /// the midpoint of that edge
  std::array<double, 3> min_angle_point{{0., 0., 0.}};
  /// the patches of the two triangles there (the same patch: a fold)
  std::pair<std::size_t, std::size_t> min_angle_patches{0, 0};
  /// edges where the region's angle is under the bound, and their total length
  std::size_t number_of_sharp_edges = 0;
  double sharp_edge_length = 0.; ///< total length of those edges
};

/*!
\ingroup PkgBubbleMesh3Ref

The `Region_contact_angles` of every region (entry `r` for region `r`, entry
0 unused), edges counted as sharp when the region's angle there is under
`bound` degrees. Around each edge the triangles are sorted by angle; the
region between two consecutive ones is the one their orientations and
patches put there (a sector on which they disagree, in an invalid model, is
skipped, and so is an edge with a triangle of zero area). A surface inside a
region (a fault) splits the region's angle at its edges; its free edges
(a fault's tip) have the whole turn, 360 degrees.
*/
template <class GeomTraits>
std::vector<Region_contact_angles> region_contact_angles(const Geological_model_3<GeomTraits>& model,
                                                         double bound = 10.)
{
  std::vector<Region_contact_angles> out(model.number_of_regions() + 1);
  struct Side { std::size_t a, b, triangle, third; bool forward; };
  std::vector<Side> sides;
  sides.reserve(3 * model.number_of_triangles());
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& v = model.triangle(t);
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t p = v[k], q = v[(k + 1) % 3];
      sides.push_back(Side{(std::min)(p, q), (std::max)(p, q), t, v[(k + 2) % 3], p < q});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return std::make_pair(std::make_pair(x.a, x.b), x.triangle) < std::make_pair(std::make_pair(y.a, y.b), y.triangle);
  });
  auto coords = [&](std::size_t i) { return internal::coordinates(model.point(i)); };
  const double pi = 3.14159265358979323846;
  std::vector<std::pair<double, std::size_t> > around; // (angle around the edge, side)
  std::vector<std::size_t> counted;                     // regions with a sharp sector at the edge
  for(std::size_t first = 0; first < sides.size();)
  {
    std::size_t last = first + 1;
    while(last < sides.size() && sides[last].a == sides[first].a && sides[last].b == sides[first].b) ++last;
    const std::array<double, 3> pa = coords(sides[first].a), pb = coords(sides[first].b);
    double d[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    around.clear();
    double e1[3] = {0., 0., 0.}, e2[3] = {0., 0., 0.};
    bool degenerate = !(len > 0.);
    if(!degenerate)
      for(double& c : d) c /= len;
    for(std::size_t i = first; i < last && !degenerate; ++i)
    {
      // the third corner's direction from the edge, across it
      const std::array<double, 3> pw = coords(sides[i].third);
      double q[3] = {pw[0] - pa[0], pw[1] - pa[1], pw[2] - pa[2]};
      const double along = q[0] * d[0] + q[1] * d[1] + q[2] * d[2];
      for(int c = 0; c < 3; ++c) q[c] -= along * d[c];
      const double ql = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
      if(!(ql > 1e-12 * len)) { degenerate = true; break; }
      if(i == first)
      {
        for(int c = 0; c < 3; ++c) e1[c] = q[c] / ql;
        e2[0] = d[1] * e1[2] - d[2] * e1[1];
        e2[1] = d[2] * e1[0] - d[0] * e1[2];
        e2[2] = d[0] * e1[1] - d[1] * e1[0];
      }
      double angle = std::atan2(q[0] * e2[0] + q[1] * e2[1] + q[2] * e2[2], q[0] * e1[0] + q[1] * e1[1] + q[2] * e1[2]);
      if(angle < 0.) angle += 2. * pi;
      around.emplace_back(angle, i);
    }
    if(!degenerate)
    {
      std::sort(around.begin(), around.end());
      counted.clear();
      const std::size_t m = around.size();
      for(std::size_t k = 0; k < m; ++k)
      {
        const Side& lo = sides[around[k].second];
        const Side& hi = sides[around[(k + 1) % m].second];
        const double sector =
          (m == 1 ? 2. * pi : around[(k + 1) % m].first - around[k].first + (k + 1 == m ? 2. * pi : 0.)) * 180. / pi;
        // a triangle whose corners run along the edge from a to b has its normal, so its
        // positive region, towards increasing angles (d x q)
        const auto& plo = model.patch(model.patch_of_triangle(lo.triangle));
        const auto& phi = model.patch(model.patch_of_triangle(hi.triangle));
        const std::size_t from_lo = lo.forward ? plo.positive_region : plo.negative_region;
        const std::size_t from_hi = hi.forward ? phi.negative_region : phi.positive_region;
        if(from_lo != from_hi || from_lo == 0 || from_lo >= out.size()) continue;
        Region_contact_angles& r = out[from_lo];
        if(m > 1 && !(sector >= r.min_angle))
        {
          r.min_angle = sector;
          r.min_angle_point = {{0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])}};
          r.min_angle_patches = std::make_pair(model.patch_of_triangle(lo.triangle), model.patch_of_triangle(hi.triangle));
        }
        if(m > 1 && sector < bound && std::find(counted.begin(), counted.end(), from_lo) == counted.end())
        {
          counted.push_back(from_lo);
          ++r.number_of_sharp_edges;
          r.sharp_edge_length += len;
        }
      }
    }
    first = last;
  }
  return out;
}

/*!
\ingroup PkgBubbleMesh3Ref

How sharply a patch's outline turns: at each point of its border, the angle
the patch spans there between two of its border edges (the sum of its
triangles' angles at the point, in degrees; 180 along a straight border, 90
at the corner of a rectangle). Under about 10 degrees two border curves of
the patch meet at a small angle, as where a fault strip between two horizon
cut lines ends: triangles there are thin however the surface is meshed.
*/
struct Patch_corner_angles
{
  /// the smallest angle of the patch at a point of its border (NaN: no border)
  double min_angle = std::numeric_limits<double>::quiet_NaN();
  /// that point's index in the model, and its coordinates
  std::size_t min_angle_vertex = 0;
  std::array<double, 3> min_angle_point{{0., 0., 0.}}; ///< the coordinates of that point
  /// border points where the patch's angle is under the bound
  std::size_t number_of_sharp_corners = 0;
  /// those points (model point indices) and the patch's angle at each, in point order
  std::vector<std::pair<std::size_t, double> > sharp_corners;
};

/*!
\ingroup PkgBubbleMesh3Ref

The `Patch_corner_angles` of every patch (entry `p` for patch `p`), corners
counted as sharp when the patch's angle there is under `bound` degrees. An
edge is on a patch's border where the patch has other than two triangles on
it or another patch also uses it (a curve); around a point, the patch's
triangles joined by edges off its border make one sector, and a sector that
reaches the border at the point is a corner.
*/
template <class GeomTraits>
std::vector<Patch_corner_angles> patch_corner_angles(const Geological_model_3<GeomTraits>& model, double bound = 10.)
{
  typedef std::array<std::size_t, 3> Key; // (edge's smaller point, larger point, patch)
  std::vector<Key> uses;
  uses.reserve(3 * model.number_of_triangles());
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& v = model.triangle(t);
    for(int k = 0; k < 3; ++k)
      uses.push_back(Key{{(std::min)(v[k], v[(k + 1) % 3]), (std::max)(v[k], v[(k + 1) % 3]), model.patch_of_triangle(t)}});
  }
  std::sort(uses.begin(), uses.end());
  std::vector<Key> border; // sorted
  for(std::size_t first = 0; first < uses.size();)
  {
    std::size_t last = first + 1;
    while(last < uses.size() && uses[last][0] == uses[first][0] && uses[last][1] == uses[first][1]) ++last;
    const bool shared = uses[first][2] != uses[last - 1][2];
    for(std::size_t i = first; i < last;)
    {
      std::size_t j = i + 1;
      while(j < last && uses[j][2] == uses[i][2]) ++j;
      if(shared || j - i != 2) border.push_back(uses[i]);
      i = j;
    }
    first = last;
  }
  auto on_border = [&](std::size_t a, std::size_t b, std::size_t p) {
    return std::binary_search(border.begin(), border.end(), Key{{(std::min)(a, b), (std::max)(a, b), p}});
  };
  auto coords = [&](std::size_t i) { return internal::coordinates(model.point(i)); };
  // (patch, point, triangle) for every corner of every triangle
  std::vector<Key> corners;
  corners.reserve(3 * model.number_of_triangles());
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    for(std::size_t v : model.triangle(t)) corners.push_back(Key{{model.patch_of_triangle(t), v, t}});
  std::sort(corners.begin(), corners.end());
  std::vector<Patch_corner_angles> out(model.number_of_patches());
  std::vector<double> sum;
  std::vector<char> reaches;
  for(std::size_t first = 0; first < corners.size();)
  {
    std::size_t last = first + 1;
    while(last < corners.size() && corners[last][0] == corners[first][0] && corners[last][1] == corners[first][1]) ++last;
    const std::size_t p = corners[first][0], v = corners[first][1], m = last - first;
    std::vector<std::size_t> parent = internal::uf_singletons(m);
    // the other two points of each triangle, as seen from v
    auto others = [&](std::size_t i) {
      const auto& tri = model.triangle(corners[first + i][2]);
      const int k = int(std::find(tri.begin(), tri.end(), v) - tri.begin());
      return std::make_pair(tri[(k + 1) % 3], tri[(k + 2) % 3]);
    };
    for(std::size_t i = 0; i < m; ++i)
      for(std::size_t j = i + 1; j < m; ++j)
      {
        const auto a = others(i), b = others(j);
        for(std::size_t w : {a.first, a.second})
          if((w == b.first || w == b.second) && !on_border(v, w, p)) internal::uf_union(parent, i, j);
      }
    sum.assign(m, 0.);
    reaches.assign(m, 0);
    const std::array<double, 3> o = coords(v);
    for(std::size_t i = 0; i < m; ++i)
    {
      const auto w = others(i);
      const std::size_t root = internal::uf_find(parent, i);
      sum[root] += internal::angle_degrees(o, coords(w.first), coords(w.second));
      if(on_border(v, w.first, p) || on_border(v, w.second, p)) reaches[root] = 1;
    }
    Patch_corner_angles& a = out[p];
    for(std::size_t i = 0; i < m; ++i)
    {
      if(internal::uf_find(parent, i) != i || !reaches[i]) continue;
      if(!(sum[i] >= a.min_angle))
      {
        a.min_angle = sum[i];
        a.min_angle_vertex = v;
        a.min_angle_point = o;
      }
      if(sum[i] < bound)
      {
        ++a.number_of_sharp_corners;
        a.sharp_corners.emplace_back(v, sum[i]);
      }
    }
    first = last;
  }
  return out;
}

/// the bounding box of the model's points
template <class GeomTraits>
Bbox_3 bbox(const Geological_model_3<GeomTraits>& model)
{
  return bbox_3(model.points().begin(), model.points().end());
}

/// the length of the diagonal of the model's bounding box (`bbox()`)
template <class GeomTraits>
double bbox_diagonal(const Geological_model_3<GeomTraits>& model)
{
  const Bbox_3 box = bbox(model);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_MEASURES_H
