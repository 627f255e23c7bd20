// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_READ_GEOLOGICAL_MODEL_H
#define CGAL_BUBBLE_MESH_3_IO_READ_GEOLOGICAL_MODEL_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/IO/reader_parameters.h>
#include <CGAL/Bubble_mesh_3/IO/read_gocad_model3d.h>
#include <CGAL/Bubble_mesh_3/IO/read_gocad_tsurf.h>
#include <CGAL/Bubble_mesh_3/IO/read_multibody_obj.h>
#include <CGAL/Bubble_mesh_3/IO/read_single_body.h>

#include <cctype>
#include <string>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {

/*!
\ingroup PkgBubbleMesh3IO

Reads the geological model in `filename`, choosing the reader by the file's
extension (case-insensitive): `.ml` `read_gocad_model3d()`, `.ts`
`read_gocad_tsurf()`, `.obj` `read_multibody_obj()`, `.off`, `.ply` and
`.stl` `read_single_body()` (one body). The named parameters
are passed on (`merge_tolerance` for all, `region_assignment` and
`region_assignment_file` for `.ts`).

\throws Geological_model_error for an unknown extension (naming it and the
known ones), a file that cannot be opened, or invalid contents.
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void read_geological_model(const std::string& filename, Geological_model_3<GeomTraits>& model,
                           const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  const std::string ext = internal::file_extension(filename);
  if(ext == "ml") read_gocad_model3d(filename, model, np);
  else if(ext == "ts") read_gocad_tsurf(filename, model, np);
  else if(ext == "obj") read_multibody_obj(filename, model, np);
  else if(ext == "off" || ext == "ply" || ext == "stl") read_single_body(filename, model, np);
  else
    throw Geological_model_error("cannot read '" + filename + "': " +
                                 (ext.empty() ? std::string("no file extension") : "unknown extension '." + ext + "'") +
                                 " (known: .ml GOCAD Model3d, .ts GOCAD TSurf, .obj multi-body OBJ; .off, .ply, .stl one body)");
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_READ_GEOLOGICAL_MODEL_H
