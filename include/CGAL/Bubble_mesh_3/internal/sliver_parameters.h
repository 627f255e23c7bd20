// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_SLIVER_PARAMETERS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_SLIVER_PARAMETERS_H

// Named parameters of `remove_slivers()`. They chain with CGAL's own:
// `parameters::sliver_bound(15).random_seed(3)`, or, after a CGAL chain, the
// two-argument form `parameters::sliver_bound(15, CGAL::parameters::random_seed(3))`.
// CGAL tags reused: `random_seed`, `number_of_iterations` (perturbation passes),
// `maximum_running_time` (the time budget), `verbose`.
// Mesh_3's `CGAL::parameters::sliver_bound` is a Boost.Parameter keyword of
// `exude_mesh_3()`; the function below lives in `CGAL::Bubble_mesh_3::parameters`
// and does not collide with it.

#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal_np {
enum sliver_bound_t { sliver_bound };
enum perturb_interior_vertices_t { perturb_interior_vertices };
enum exude_slivers_t { exude_slivers };
enum polish_interior_t { polish_interior };
enum number_of_smoothing_passes_t { number_of_smoothing_passes };
enum insert_interior_vertices_t { insert_interior_vertices };
enum flip_slivers_t { flip_slivers };
enum collapse_steiner_points_t { collapse_steiner_points };
enum perturbation_radius_factor_t { perturbation_radius_factor };
enum number_of_perturbation_directions_t { number_of_perturbation_directions };
} // namespace internal_np

namespace parameters {

using CGAL::parameters::default_values;
using CGAL::parameters::random_seed;
using CGAL::parameters::number_of_iterations;
using CGAL::parameters::maximum_running_time;
using CGAL::parameters::verbose;

/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: a tetrahedron whose smallest dihedral angle (degrees) is under this is a sliver
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, sliver_bound)
/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: whether interior vertices of slivers are moved (default `true`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, perturb_interior_vertices)
/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: whether CGAL's `exude_mesh_3()` runs after the perturbation (default `false`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, exude_slivers)
/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: whether CGAL's `tetrahedral_isotropic_remeshing()` polishes the interior at the end (default `false`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, polish_interior)
/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: passes of the smoothing of all interior vertices after the perturbation (default 0: none)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_smoothing_passes)
/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: whether slivers left are replaced by the star of a new interior vertex at the end
/// (default: the value of `perturb_interior_vertices`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, insert_interior_vertices)
/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: whether slivers left are flipped away (2-3 flips and edge removals) before and
/// after the insertion (default: the value of `perturb_interior_vertices`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, flip_slivers)
/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: whether Steiner points of the recovery are collapsed onto a neighbour on the same
/// input triangles where that improves the cells, before the flips (default: the value of `flip_slivers`;
/// needs `surface_vertex_supports`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, collapse_steiner_points)
/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: largest move of a vertex, as a fraction of its shortest incident edge
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, perturbation_radius_factor)
/// \ingroup PkgBubbleMesh3Ref
/// `remove_slivers()`: random directions tried per vertex and pass, besides the directions away from its slivers
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(unsigned int, number_of_perturbation_directions)

} // namespace parameters
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_SLIVER_PARAMETERS_H
