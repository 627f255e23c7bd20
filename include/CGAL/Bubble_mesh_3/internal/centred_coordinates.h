// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_CENTRED_COORDINATES_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_CENTRED_COORDINATES_H

// Points as doubles relative to the centre of the model's bounding box, and
// the signed volumes summed over them. Real models sit far from the origin
// (UTM metres): relative to the centre a volume sum loses no digits.

#include <CGAL/Bbox_3.h>
#include <CGAL/number_utils.h>

#include <array>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

typedef std::array<double, 3> Centred_point;

// the centre of the bounding box of a model's points (the origin if it has none)
template <class Model>
Centred_point box_centre(const Model& model)
{
  if(model.number_of_points() == 0) return Centred_point{{0., 0., 0.}};
  const Bbox_3 box = bbox_3(model.points().begin(), model.points().end());
  return Centred_point{{0.5 * (box.xmin() + box.xmax()), 0.5 * (box.ymin() + box.ymax()),
                        0.5 * (box.zmin() + box.zmax())}};
}

template <class Point_3>
Centred_point centred(const Point_3& p, const Centred_point& centre)
{
  return Centred_point{{CGAL::to_double(p.x()) - centre[0], CGAL::to_double(p.y()) - centre[1],
                        CGAL::to_double(p.z()) - centre[2]}};
}

// det[a b c]: six times the signed volume of the tetrahedron (centre, a, b, c),
// positive when (a, b, c) turns counterclockwise seen from the centre's side
inline double triple_product(const Centred_point& a, const Centred_point& b, const Centred_point& c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

inline double signed_volume(const Centred_point& a, const Centred_point& b, const Centred_point& c)
{
  return triple_product(a, b, c) / 6.;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_CENTRED_COORDINATES_H
