// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_CORNER_FORCED_FACET_ANGLE_H
#define CGAL_BUBBLE_MESH_3_CORNER_FORCED_FACET_ANGLE_H

#include <CGAL/Bubble_mesh_3/mesh_quality.h>
#include <CGAL/Bubble_mesh_3/remesh_surfaces.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

The surface angle of a facet of a mesh made on re-meshed surfaces, for the
named parameter `facet_input_min_angle` of `compute_c3t3_quality()`: the
facet's own smallest angle, or, when the facet is one of the re-meshed
triangles that an input corner forces thin
(`Surface_remeshing_report::corner_forced_triangles`), the smaller of that and
the corner's own angle.

A corner of a patch under the angle bound (a fault lens's tip, a layer pinching
out on a wall) makes every triangle spanning its wedge thin; the re-meshing's
slide may lift such a triangle over 10 degrees while the corner is under it,
and the tetrahedra against it are then thin because of the input's corner,
which the quality report should tell from the ones the mesher made. Facets are matched to the triangles by
their corners' coordinates, which the tetrahedralization keeps; a facet cut by
a Steiner point keeps its own angle.

`C3T3` is a `CGAL::Mesh_complex_3_in_triangulation_3` (or a type with the same
facet and point types).
*/
template <class C3T3>
class Corner_forced_facet_angle
{
public:
  /// the facets of `report`'s corner-forced triangles
  explicit Corner_forced_facet_angle(const Surface_remeshing_report& report)
  {
    for(const auto& t : report.corner_forced_triangles)
    {
      Key key = t.points;
      std::sort(key.begin(), key.end());
      auto ins = corner_angles_.insert(std::make_pair(key, t.corner_angle));
      if(!ins.second) ins.first->second = (std::min)(ins.first->second, t.corner_angle);
    }
  }

  /// the surface angle of `f` in degrees
  double operator()(const typename C3T3::Facet& f) const
  {
    Key key;
    for(int k = 0, j = 0; k < 4; ++k)
      if(k != f.second)
      {
        const auto& p = f.first->vertex(k)->point();
        key[std::size_t(j++)] = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
      }
    const double own = internal::smallest_triangle_angle(key[0], key[1], key[2]);
    if(corner_angles_.empty()) return own;
    std::sort(key.begin(), key.end());
    const auto it = corner_angles_.find(key);
    return it == corner_angles_.end() ? own : (std::min)(own, it->second);
  }

private:
  typedef std::array<std::array<double, 3>, 3> Key;
  std::map<Key, double> corner_angles_;
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_CORNER_FORCED_FACET_ANGLE_H
