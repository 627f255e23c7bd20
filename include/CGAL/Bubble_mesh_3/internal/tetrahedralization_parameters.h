// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_TETRAHEDRALIZATION_PARAMETERS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_TETRAHEDRALIZATION_PARAMETERS_H

// Named parameters of `tetrahedralize_bubbles()`. CGAL's own tags that it
// reads as well: `CGAL::parameters::verbose`.

#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <cstddef>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal_np {
enum drop_encroaching_points_t { drop_encroaching_points };
enum drop_ball_ratio_bound_t { drop_ball_ratio_bound };
enum maximum_number_of_steiner_points_t { maximum_number_of_steiner_points };
enum minimum_split_length_t { minimum_split_length };
} // namespace internal_np

namespace parameters {

/// whether interior points inside the diametral ball of an input edge, or the
/// equatorial ball of a well-shaped input triangle, that holds no other model
/// point, are dropped before recovery (default `true`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, drop_encroaching_points)
/// a triangle's equatorial ball drops points only when its radius is at most
/// this times the triangle's shortest edge (default `1`: smallest angle >= 30 degrees)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, drop_ball_ratio_bound)
/// recovery stops with an error beyond this many Steiner points (default: see `tetrahedralize_bubbles()`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, maximum_number_of_steiner_points)
/// recovery stops with an error rather than split an input edge into pieces
/// shorter than this fraction of the bounding-box diagonal (default `1e-9`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, minimum_split_length)

} // namespace parameters
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_TETRAHEDRALIZATION_PARAMETERS_H
