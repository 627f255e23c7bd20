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

/// whether the corners of triangle `t2` of `model` lie on the plane of triangle `t1`, exactly or within `tolerance`
template <class GeomTraits>
bool are_nearly_coplanar(const Geological_model_3<GeomTraits>& model, std::size_t t1, std::size_t t2,
                         double tolerance)
{
  const auto& a = model.triangle(t1);
  for(std::size_t x : model.triangle(t2))
    if(!is_nearly_coplanar(model.point(a[0]), model.point(a[1]), model.point(a[2]), model.point(x), tolerance))
      return false;
  return true;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_NEAR_COPLANARITY_H
