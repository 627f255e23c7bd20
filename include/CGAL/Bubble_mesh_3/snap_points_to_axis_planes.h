// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_SNAP_POINTS_TO_AXIS_PLANES_H
#define CGAL_BUBBLE_MESH_3_SNAP_POINTS_TO_AXIS_PLANES_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/near_coplanarity.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <set>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal {

// per patch and axis (x, y, z), the coordinates that all three points of one
// of the patch's triangles share: the patch's axis planes
template <class GeomTraits>
std::vector<std::array<std::set<typename GeomTraits::FT>, 3> >
patch_axis_planes(const Geological_model_3<GeomTraits>& model)
{
  std::vector<std::array<std::set<typename GeomTraits::FT>, 3> > planes(model.number_of_patches());
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& tri = model.triangle(t);
    for(int k = 0; k < 3; ++k)
      if(model.point(tri[0])[k] == model.point(tri[1])[k] && model.point(tri[0])[k] == model.point(tri[2])[k])
        planes[model.patch_of_triangle(t)][k].insert(model.point(tri[0])[k]);
  }
  return planes;
}

// the plane of `planes` (not empty) nearest to `c`: the first at or above it,
// or the one below if that is nearer
template <class FT>
typename std::set<FT>::const_iterator nearest_axis_plane(const std::set<FT>& planes, const FT& c)
{
  auto it = planes.lower_bound(c);
  if(it == planes.end() || (it != planes.begin() && c - *std::prev(it) < *it - c)) --it;
  return it;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

What `snap_points_to_axis_planes()` did.
*/
struct Axis_plane_snap_report
{
  std::size_t number_of_points = 0; ///< points given an axis plane's coordinate
  double largest_move = 0.;         ///< the largest change of a coordinate
};

/*!
\ingroup PkgBubbleMesh3Ref

Gives back their axis plane to the points of a box wall that modelling
software wrote a hair off it. Where a horizon or a fault meets a wall
\f$ y = 0 \f$, the exported cut points often read \f$ y = 10^{-11} \f$: the wall
is then no plane, and the surface recovery, which keeps axis planes exactly
planar, cannot rebuild its triangles (a Gmsh-made graben failed so, with 15
of 1,166 wall points off by at most 3.5e-11; snapped, it meshed).

An axis plane of a patch is a value \f$ c \f$ that all three points of one of
its triangles have as their \f$ x \f$, \f$ y \f$ or \f$ z \f$. A triangle of
the patch whose three points lie within the coplanarity tolerance of that
plane (a thousand rounding units of the largest coordinate, the tolerance
under which the rest of the pipeline counts triangles as coplanar) has the
coordinate of its points set to \f$ c \f$ exactly (the nearest such plane if
there are several). A move that would make a triangle degenerate is not made.

\returns how many points moved, and by how much at most.
*/
template <class GeomTraits>
Axis_plane_snap_report snap_points_to_axis_planes(Geological_model_3<GeomTraits>& model)
{
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_3 Point_3;
  Axis_plane_snap_report report;
  const std::size_t nt = model.number_of_triangles();
  const std::vector<std::array<std::set<FT>, 3> > levels = internal::patch_axis_planes(model);
  const double tolerance = internal::coplanarity_tolerance(model);

  // the coordinate each point is to take, per axis (a point of several walls
  // takes the nearest plane offered)
  std::vector<std::array<const FT*, 3> > target(model.number_of_points(), {{nullptr, nullptr, nullptr}});
  for(std::size_t t = 0; t < nt; ++t)
  {
    const auto& tri = model.triangle(t);
    for(int k = 0; k < 3; ++k)
    {
      const std::set<FT>& planes = levels[model.patch_of_triangle(t)][k];
      if(planes.empty()) continue;
      const FT& c = model.point(tri[0])[k];
      const auto it = internal::nearest_axis_plane(planes, c);
      bool near = true;
      for(std::size_t v : tri) near = near && std::abs(CGAL::to_double(model.point(v)[k] - *it)) <= tolerance;
      if(!near) continue;
      for(std::size_t v : tri)
      {
        const FT& x = model.point(v)[k];
        const FT*& to = target[v][std::size_t(k)];
        if(x != *it && (to == nullptr || CGAL::abs(*it - x) < CGAL::abs(*to - x))) to = &*it;
      }
    }
  }

  std::vector<Point_3> snapped(model.points());
  std::vector<char> moved(snapped.size(), 0);
  for(std::size_t v = 0; v < snapped.size(); ++v)
  {
    std::array<FT, 3> c{{snapped[v].x(), snapped[v].y(), snapped[v].z()}};
    for(std::size_t k = 0; k < 3; ++k)
      if(target[v][k] != nullptr) { c[k] = *target[v][k]; moved[v] = 1; }
    if(moved[v]) snapped[v] = Point_3(c[0], c[1], c[2]);
  }
  // a triangle made degenerate keeps its points where they were
  for(bool again = true; again;)
  {
    again = false;
    for(std::size_t t = 0; t < nt; ++t)
    {
      const auto& tri = model.triangle(t);
      if(!(moved[tri[0]] || moved[tri[1]] || moved[tri[2]])) continue;
      if(!CGAL::collinear(snapped[tri[0]], snapped[tri[1]], snapped[tri[2]])) continue;
      for(std::size_t v : tri)
        if(moved[v]) { snapped[v] = model.point(v); moved[v] = 0; again = true; }
    }
  }
  for(std::size_t v = 0; v < snapped.size(); ++v)
  {
    if(!moved[v]) continue;
    ++report.number_of_points;
    for(int k = 0; k < 3; ++k)
      report.largest_move = (std::max)(report.largest_move, std::abs(CGAL::to_double(snapped[v][k] - model.point(v)[k])));
    model.set_point(v, snapped[v]);
  }
  return report;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_SNAP_POINTS_TO_AXIS_PLANES_H
