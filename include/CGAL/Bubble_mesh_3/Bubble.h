// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_BUBBLE_H
#define CGAL_BUBBLE_MESH_3_BUBBLE_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/// index value meaning "none"
constexpr std::size_t no_index = (std::numeric_limits<std::size_t>::max)();

/*!
\ingroup PkgBubbleMesh3Ref

A bubble: a ball whose centre becomes a mesh vertex.

Surface bubbles sit on the model's points and never move (`is_fixed`,
`surface_point` is the model point index, `region` is `no_index` since a
surface point may bound several regions). Interior bubbles belong to exactly
one region and move during relaxation.
*/
template <class GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel>
struct Bubble
{
  /// point type of the traits
  typedef typename GeomTraits::Point_3 Point_3;

  Point_3 center;                       ///< centre, a mesh vertex in the end
  double radius = 0.;                   ///< radius, from the sizing field
  std::size_t region = no_index;        ///< region of an interior bubble
  std::size_t surface_point = no_index; ///< model point of a surface bubble
  bool is_fixed = false;                ///< surface bubbles never move

  /// a bubble at the origin with radius 0
  Bubble() {}
  /// a bubble with all its fields given
  Bubble(const Point_3& c, double r, std::size_t reg, std::size_t sp, bool fixed)
    : center(c), radius(r), region(reg), surface_point(sp), is_fixed(fixed) {}
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_BUBBLE_H
