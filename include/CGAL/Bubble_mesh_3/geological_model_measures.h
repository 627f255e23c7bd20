// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_MEASURES_H
#define CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_MEASURES_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bbox_3.h>

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
  if(model.number_of_points() == 0) return vol;
  const Bbox_3 box = bbox_3(model.points().begin(), model.points().end());
  const double ox = 0.5 * (box.xmin() + box.xmax());
  const double oy = 0.5 * (box.ymin() + box.ymax());
  const double oz = 0.5 * (box.zmin() + box.zmax());

  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& patch = model.patch(model.patch_of_triangle(t));
    if(patch.is_inside_region()) continue;
    const auto& tri = model.triangle(t);
    const auto& a = model.point(tri[0]);
    const auto& b = model.point(tri[1]);
    const auto& c = model.point(tri[2]);
    const double ax = CGAL::to_double(a.x()) - ox, ay = CGAL::to_double(a.y()) - oy, az = CGAL::to_double(a.z()) - oz;
    const double bx = CGAL::to_double(b.x()) - ox, by = CGAL::to_double(b.y()) - oy, bz = CGAL::to_double(b.z()) - oz;
    const double cx = CGAL::to_double(c.x()) - ox, cy = CGAL::to_double(c.y()) - oy, cz = CGAL::to_double(c.z()) - oz;
    // signed volume of the tetrahedron (origin, a, b, c): positive when the
    // normal (right-hand rule) points away from the origin side
    const double v = (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6.;
    // the negative region sees the normal pointing out of it
    vol[patch.negative_region] += v;
    vol[patch.positive_region] -= v;
  }
  // region 0 collected the outer boundary with the sign of the outside: flip it
  vol[0] = -vol[0];
  return vol;
}

/// the bounding box of the model's points
template <class GeomTraits>
Bbox_3 bbox(const Geological_model_3<GeomTraits>& model)
{
  return bbox_3(model.points().begin(), model.points().end());
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_MEASURES_H
