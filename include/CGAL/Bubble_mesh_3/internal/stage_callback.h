// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_STAGE_CALLBACK_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_STAGE_CALLBACK_H

// The `stage_callback` named parameter: the stages (and the long steps inside
// them) tell it when they start, so that a program can print a progress line.

#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <functional>
#include <string>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal_np {
enum stage_callback_t { stage_callback };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgBubbleMesh3Ref
/// the type of the `stage_callback` parameter
typedef std::function<void(const std::string&)> Stage_callback;
/// \ingroup PkgBubbleMesh3Ref
/// `make_bubble_mesh_3()` calls `f(stage_name)` when a stage starts (for a progress line), and
/// `tetrahedralize_bubbles()` and `remove_slivers()` when each of their steps starts
/// (`"tetrahedralization: recovering the surfaces"`, `"sliver removal: moving bubbles"`, ...)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(Stage_callback, stage_callback)

} // namespace parameters

namespace internal {

// announce(step) calls the callback of `np`, if any, with "stage: step"
template <class NamedParameters>
std::function<void(const char*)> step_announcer(const NamedParameters& np, const std::string& stage)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const parameters::Stage_callback callback =
    choose_parameter(get_parameter(np, internal_np::stage_callback), parameters::Stage_callback());
  return [callback, stage](const char* step) {
    if(callback) callback(stage + ": " + step);
  };
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_STAGE_CALLBACK_H
