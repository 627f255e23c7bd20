// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_VERTEX_ANGLE_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_VERTEX_ANGLE_H

// The angle at a vertex and a triangle's smallest angle, in degrees, for the
// model summary, the measures of a model and the surface re-meshing. atan2(|u x v|, u.v) stays accurate
// for angles of a thousandth of a degree, where acos of the cosine does not.

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// a point's coordinates as doubles
template <class Point>
std::array<double, 3> coordinates(const Point& p)
{
  return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

/// the angle q-o-r at `o`, in degrees
inline double angle_degrees(const std::array<double, 3>& o, const std::array<double, 3>& q,
                            const std::array<double, 3>& r)
{
  const double u[3] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]}, v[3] = {r[0] - o[0], r[1] - o[1], r[2] - o[2]};
  const double c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) *
         180. / 3.14159265358979323846;
}

/// the same for kernel points
template <class Point>
double angle_degrees(const Point& o, const Point& q, const Point& r)
{
  return angle_degrees(coordinates(o), coordinates(q), coordinates(r));
}

/// the smallest angle of a triangle, in degrees
template <class Point>
double min_angle_degrees(const Point& a, const Point& b, const Point& c)
{
  const std::array<double, 3> pa = coordinates(a), pb = coordinates(b), pc = coordinates(c);
  return (std::min)({angle_degrees(pa, pb, pc), angle_degrees(pb, pc, pa), angle_degrees(pc, pa, pb)});
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_VERTEX_ANGLE_H
