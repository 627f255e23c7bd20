// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_REMESHING_PARAMETERS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_REMESHING_PARAMETERS_H

// Named parameters of the surface re-meshing stage (model features, sizing
// field, `remesh_surfaces()`). They chain with CGAL's own parameters:
// `parameters::edge_length(50.).number_of_iterations(30)`, or, to append after
// a CGAL chain, the two-argument form
// `parameters::edge_length(50., CGAL::parameters::verbose(true))`.
// CGAL tags reused: `number_of_iterations` (bubble relaxation steps per round),
// `verbose` (progress on std::cerr).

#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/// \ingroup PkgBubbleMesh3Ref
/// How `remesh_surfaces()` re-triangulates each patch once its curves are resampled.
enum class Surface_remeshing_method
{
  /// surface bubbles relaxed on the patch under the cubic force law,
  /// connected by a constrained Delaunay triangulation and cleaned with
  /// edge flips and point insertions in 3D (default)
  BUBBLES,
  /// CGAL's `Polygon_mesh_processing::isotropic_remeshing()` with the
  /// curve edges protected, started from the same initial triangulation
  ISOTROPIC
};

namespace internal_np {
enum feature_angle_t { feature_angle };
enum edge_length_t { edge_length };
enum relative_edge_length_t { relative_edge_length };
enum region_size_factors_t { region_size_factors };
enum patch_size_factors_t { patch_size_factors };
enum elements_across_thickness_t { elements_across_thickness };
enum minimum_edge_length_t { minimum_edge_length };
enum size_grading_t { size_grading };
enum refine_ribbons_t { refine_ribbons };
enum curvature_angle_t { curvature_angle };
enum curve_distance_t { curve_distance };
enum surface_distance_t { surface_distance };
enum chart_angle_t { chart_angle };
enum minimum_triangle_angle_t { minimum_triangle_angle };
enum surface_remeshing_method_t { surface_remeshing_method };
enum number_of_population_steps_t { number_of_population_steps };
enum sizing_field_output_t { sizing_field_output };
enum keep_region_volumes_t { keep_region_volumes };
} // namespace internal_np

namespace parameters {

using CGAL::parameters::default_values;
using CGAL::parameters::number_of_iterations;
using CGAL::parameters::verbose;

/// \ingroup PkgBubbleMesh3Ref
/// angle in degrees above which a turn of a contact curve makes a corner and
/// the dihedral between two adjacent triangles of one patch makes a feature
/// curve (default 30)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, feature_angle)
/// \ingroup PkgBubbleMesh3Ref
/// target edge length of the re-meshed surfaces, in model units (default:
/// the median input edge length); overrides `relative_edge_length`
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, edge_length)
/// \ingroup PkgBubbleMesh3Ref
/// target edge length as a fraction of the bounding-box diagonal
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, relative_edge_length)
/// \ingroup PkgBubbleMesh3Ref
/// size factor per region (index 0 = outside, ignored); a patch takes the
/// smaller factor of its two regions (default: all 1)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::vector<double>, region_size_factors)
/// \ingroup PkgBubbleMesh3Ref
/// size factor per patch, multiplied with the region factor (default: all 1)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::vector<double>, patch_size_factors)
/// \ingroup PkgBubbleMesh3Ref
/// number of edges wanted across the local thickness (distance to the
/// nearest non-adjacent surface), e.g. across a thin layer (default
/// `Remeshing_sizing_field::default_elements_across_thickness`, 1.63)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, elements_across_thickness)
/// \ingroup PkgBubbleMesh3Ref
/// floor of the thickness rule, in model units (default: a tenth of the
/// smallest patch size)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, minimum_edge_length)
/// \ingroup PkgBubbleMesh3Ref
/// largest ratio between the sizes of neighbouring edges (default 1.5): the
/// size grows by at most `size_grading - 1` per unit of distance
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, size_grading)
/// \ingroup PkgBubbleMesh3Ref
/// largest turn, in degrees, of the input surface along one re-meshed edge
/// where a patch is curved (default 22.5: 16 edges around a circle; 0: off)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, curvature_angle)
/// \ingroup PkgBubbleMesh3Ref
/// sizes a ribbon (a patch between two curves that meet at a corner under 10
/// degrees, such as a fault strip between two horizon cut lines) by its width,
/// down to a twentieth of `minimum_edge_length`, instead of spanning it with
/// needles (default `false`: many more elements near long ribbons)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, refine_ribbons)
/// \ingroup PkgBubbleMesh3Ref
/// largest distance between a re-meshed contact curve and the input
/// polyline, as a fraction of the bounding-box diagonal (default 5e-7)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, curve_distance)
/// \ingroup PkgBubbleMesh3Ref
/// distance between a new triangle and the input surface, as a fraction of
/// the local target edge length, above which the triangle is refined (down
/// to a quarter of the local size; default 1e-3)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, surface_distance)
/// \ingroup PkgBubbleMesh3Ref
/// largest angle in degrees between the normals of a patch and the plane it
/// is flattened onto for triangulation; patches that bend more are cut into
/// several charts (default 50)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, chart_angle)
/// \ingroup PkgBubbleMesh3Ref
/// smallest triangle angle in degrees the re-meshing aims at (default 25)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, minimum_triangle_angle)
/// \ingroup PkgBubbleMesh3Ref
/// the patch triangulation method (default `Surface_remeshing_method::BUBBLES`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(Surface_remeshing_method, surface_remeshing_method)
/// \ingroup PkgBubbleMesh3Ref
/// rounds of bubble relaxation and population control on each patch (default 3)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_population_steps)
/// \ingroup PkgBubbleMesh3Ref
/// slides the free points of the re-meshed patches along the input surface
/// until every region encloses its input volume again, and re-meshes the
/// surfaces of convex, coarsely faceted bodies, which slides cannot balance,
/// with their creases kept (default `false`: each region differs by the
/// chords' error, about 1e-4 of its volume on curved horizons)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, keep_region_volumes)

/// \ingroup PkgBubbleMesh3Ref
/// receives the sizing field `remesh_surfaces()` used in the end, with the
/// size constraints of the curve points it had to keep (a pointer to a
/// `Remeshing_sizing_field` of the same traits; default: none)
template <class SizingField>
CGAL::Named_function_parameters<SizingField*, internal_np::sizing_field_output_t> sizing_field_output(SizingField* f)
{
  return CGAL::Named_function_parameters<SizingField*, internal_np::sizing_field_output_t>(f);
}
/// \ingroup PkgBubbleMesh3Ref
/// the same, appended to an existing chain
template <class SizingField, class T, class Tag, class Base>
CGAL::Named_function_parameters<SizingField*, internal_np::sizing_field_output_t,
                                CGAL::Named_function_parameters<T, Tag, Base> >
sizing_field_output(SizingField* f, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return CGAL::Named_function_parameters<SizingField*, internal_np::sizing_field_output_t,
                                         CGAL::Named_function_parameters<T, Tag, Base> >(f, np);
}

} // namespace parameters
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_REMESHING_PARAMETERS_H
