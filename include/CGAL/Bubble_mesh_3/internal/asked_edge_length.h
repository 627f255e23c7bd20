// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_ASKED_EDGE_LENGTH_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_ASKED_EDGE_LENGTH_H

// The edge length a user asked for with the named parameters `edge_length`
// (model units) or `relative_edge_length` (of the bounding-box diagonal),
// read the same way by the surface re-meshing and by the refinement of
// planar pieces.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/internal/remeshing_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <optional>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

// `edge_length` if given, else `relative_edge_length` times the diagonal if
// given, else nothing (the caller's default)
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
std::optional<double> asked_edge_length(const Geological_model_3<GeomTraits>& model, const CGAL_NP_CLASS& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  if(!is_default_parameter<CGAL_NP_CLASS, internal_np::edge_length_t>::value)
    return choose_parameter(get_parameter(np, internal_np::edge_length), 0.);
  if(!is_default_parameter<CGAL_NP_CLASS, internal_np::relative_edge_length_t>::value)
    return choose_parameter(get_parameter(np, internal_np::relative_edge_length), 0.) * Bubble_mesh_3::bbox_diagonal(model);
  return std::nullopt;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_ASKED_EDGE_LENGTH_H
