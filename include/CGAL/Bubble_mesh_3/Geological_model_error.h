// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_ERROR_H
#define CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

Thrown by the readers and by `validate_geological_model()` when the input is
not a valid geological model. The message says what is wrong and where:
file and line where they apply, region or patch name, triangle or vertex
index, coordinates.
*/
class Geological_model_error : public std::runtime_error
{
public:
  /// an error with its message (what and where)
  explicit Geological_model_error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_ERROR_H
