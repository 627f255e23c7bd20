// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_INTERNAL_CHECK_TRIANGLES_H
#define CGAL_BUBBLE_MESH_3_IO_INTERNAL_CHECK_TRIANGLES_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/IO/internal/Line_reader.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

// After merging, a triangle with two corners on one point has no normal and
// no side: readers refuse it with its line and coordinates.
template <class GeomTraits>
void check_triangles_not_degenerate(const Geological_model_3<GeomTraits>& m)
{
  for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
  {
    const auto& tri = m.triangle(t);
    for(int i = 0; i < 3; ++i)
      if(tri[i] == tri[(i + 1) % 3])
      {
        const auto& p = m.point(tri[i]);
        throw Geological_model_error(m.where(m.triangle_source(t)) + "triangle " + std::to_string(t) + " of " +
                                     m.patch_label(m.patch_of_triangle(t)) +
                                     " is degenerate: two of its corners are the same point " +
                                     point_text(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
      }
  }
}

} // namespace internal
} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_INTERNAL_CHECK_TRIANGLES_H
