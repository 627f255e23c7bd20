// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_OUTER_WALL_GUARDS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_OUTER_WALL_GUARDS_H

// Guard points beyond the model's tilted outer walls. An outer wall lies on
// the convex hull, where no point faces it from outside: the triangulation's
// facets on that side are those of the hull of the wall's points, which for a
// plane known only up to rounding (a wall turned off the axes) is a random
// triangulation set by the rounding, not the Delaunay one the inside sees.
// The flat cells between the two then reach the inside and the outside at
// once, and the recovery cannot put them on a side (CloudSpin and modelA2
// turned by 30 degrees failed so). Mirror images of the interior points that
// face such a wall give the outside the same view as the inside; they lie
// outside the model, so they leave with the other outside points once the
// regions are labelled. Axis-plane walls need none: their points are exact.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// mirror images of the `interior` points whose nearest input triangle lies
/// on a tilted outer wall (a plane group of two or more triangles, off the
/// axis planes, with the model's outside on one side), taken across that
/// triangle's plane, when the image's nearest triangle is on the same wall
template <class GeomTraits, class Recovery>
std::vector<typename GeomTraits::Point_3> outer_wall_guards(const Geological_model_3<GeomTraits>& model,
                                                            const Recovery& recovery,
                                                            const std::vector<typename GeomTraits::Point_3>& interior)
{
  typedef typename GeomTraits::Point_3    Point_3;
  typedef typename GeomTraits::Vector_3   Vector_3;
  typedef typename GeomTraits::Triangle_3 Triangle_3;
  std::vector<Point_3> guards;

  const std::size_t nt = model.number_of_triangles();
  std::vector<std::size_t> group_size(nt, 0);
  for(std::size_t t = 0; t < nt; ++t) ++group_size[recovery.plane_group(t)];
  std::vector<char> wall(nt, 0);
  bool any = false;
  for(std::size_t t = 0; t < nt; ++t)
  {
    const std::size_t g = recovery.plane_group(t);
    const Vector_3& n = recovery.group_normal(g);
    const int nonzero = (n.x() != 0) + (n.y() != 0) + (n.z() != 0);
    wall[t] = recovery.group_outside(g) != 0 && group_size[g] > 1 && nonzero > 1;
    any = any || wall[t];
  }
  if(!any || interior.empty()) return guards;

  std::vector<Triangle_3> triangles;
  triangles.reserve(nt);
  for(std::size_t t = 0; t < nt; ++t)
  {
    const auto& tri = model.triangle(t);
    triangles.emplace_back(model.point(tri[0]), model.point(tri[1]), model.point(tri[2]));
  }
  typedef typename std::vector<Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<GeomTraits, Iterator> Primitive;
  typedef CGAL::AABB_traits<GeomTraits, Primitive> Traits;
  CGAL::AABB_tree<Traits> tree(triangles.cbegin(), triangles.cend());
  tree.accelerate_distance_queries();
  auto nearest = [&](const Point_3& p) {
    return std::size_t(tree.closest_point_and_primitive(p).second - triangles.cbegin());
  };

  for(const Point_3& p : interior)
  {
    const std::size_t t = nearest(p);
    if(!wall[t]) continue;
    const auto& tri = model.triangle(t);
    const Vector_3 n = recovery.triangle_normal(t);
    const double l2 = CGAL::to_double(n.squared_length());
    const double d = CGAL::to_double((p - model.point(tri[0])) * n) / l2;
    if(d == 0.) continue;
    const Point_3 m = p - 2. * d * n;
    if(recovery.plane_group(nearest(m)) != recovery.plane_group(t)) continue;
    guards.push_back(m);
  }
  return guards;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_OUTER_WALL_GUARDS_H
