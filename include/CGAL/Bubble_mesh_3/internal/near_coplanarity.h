// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_NEAR_COPLANARITY_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_NEAR_COPLANARITY_H

// Triangles of one plane whose points were rounded. A box wall that is not an
// axis plane (a model rotated to its survey's grid, say) is planar only up to
// the rounding of its points: exact predicates see adjacent wall triangles as
// bent by a few units in the last place. The surface recovery's Steiner points
// are rounded off their triangles by as much, so such walls behave like
// neither one plane nor two: the recovery splits their edges without end
// (a rotated copy of the bundled model failed after two minutes). Triangles
// bent by less than the tolerance below count as coplanar. It is a thousand
// rounding units of the largest coordinate: far above what rounding does to
// doubles, far below the bends of real surfaces, and below the rounding of
// single-precision coordinates (GOCAD's): their walls are bent enough for the
// recovery to see them as bent, and they mesh as such.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// the distance under which a point counts as lying on a triangle's plane
template <class GeomTraits>
double coplanarity_tolerance(const Geological_model_3<GeomTraits>& model)
{
  double largest = 0.;
  for(const auto& p : model.points())
    for(int i = 0; i < 3; ++i) largest = (std::max)(largest, std::abs(CGAL::to_double(p[i])));
  return 1024. * std::numeric_limits<double>::epsilon() * largest;
}

/// whether `x` lies on the plane of (p, q, r) exactly or within `tolerance`
template <class Point_3>
bool is_nearly_coplanar(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& x, double tolerance)
{
  if(CGAL::orientation(p, q, r, x) == CGAL::COPLANAR) return true;
  const auto n = CGAL::cross_product(q - p, r - p);
  const double length = std::sqrt(CGAL::to_double(n.squared_length()));
  return length > 0. && std::abs(CGAL::to_double((x - p) * n)) <= tolerance * length;
}

/*
Whether triangles `t1` and `t2` of `model` lie on one plane, exactly or within
`tolerance`. The plane the distances are measured from is the one of the
widest three of their corners: a needle's own plane is tilted by its points'
rounding over its short side, so measured from a needle the far corners of
its neighbour (a fan of needles on a turned wall, say) seem to be many times
the tolerance off a plane they lie on.
*/
template <class GeomTraits>
bool are_nearly_coplanar(const Geological_model_3<GeomTraits>& model, std::size_t t1, std::size_t t2,
                         double tolerance)
{
  const auto& a = model.triangle(t1);
  bool exact = true;
  for(std::size_t x : model.triangle(t2))
    exact = exact && CGAL::orientation(model.point(a[0]), model.point(a[1]), model.point(a[2]), model.point(x)) ==
                       CGAL::COPLANAR;
  if(exact) return true;

  std::array<std::size_t, 6> ids;
  std::size_t n = 0;
  for(const auto* tri : {&a, &model.triangle(t2)})
    for(std::size_t v : *tri)
      if(std::find(ids.begin(), ids.begin() + n, v) == ids.begin() + n) ids[n++] = v;
  // the widest triple: the largest cross product
  std::array<std::size_t, 3> best = {{0, 1, 2}};
  double best_l2 = -1.;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      for(std::size_t k = j + 1; k < n; ++k)
      {
        const auto& p = model.point(ids[i]);
        const double l2 = CGAL::to_double(
          CGAL::cross_product(model.point(ids[j]) - p, model.point(ids[k]) - p).squared_length());
        if(l2 > best_l2) { best_l2 = l2; best = {{i, j, k}}; }
      }
  for(std::size_t m = 0; m < n; ++m)
  {
    if(m == best[0] || m == best[1] || m == best[2]) continue;
    if(!is_nearly_coplanar(model.point(ids[best[0]]), model.point(ids[best[1]]), model.point(ids[best[2]]),
                           model.point(ids[m]), tolerance))
      return false;
  }
  return true;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_NEAR_COPLANARITY_H
