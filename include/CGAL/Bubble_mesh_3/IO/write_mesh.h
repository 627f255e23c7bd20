// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_MESH_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_MESH_H

#include <CGAL/Bubble_mesh_3/IO/internal/mesh_arrays.h>
#include <CGAL/Bubble_mesh_3/IO/write_abaqus_inp.h>
#include <CGAL/Bubble_mesh_3/IO/write_flac3d_f3grid.h>
#include <CGAL/Bubble_mesh_3/IO/write_gmsh_msh.h>
#include <CGAL/Bubble_mesh_3/IO/write_medit.h>
#include <CGAL/Bubble_mesh_3/IO/write_tetgen.h>
#include <CGAL/Bubble_mesh_3/IO/write_vtu.h>

#include <cctype>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {

/// \ingroup PkgBubbleMesh3IO
/// the file name extensions `write_mesh()` knows, with their formats, for messages and help texts
inline const char* mesh_file_extensions()
{
  return ".mesh (Medit), .vtu (VTK XML), .msh (Gmsh 4.1), .node (TetGen .node/.ele/.face), "
         ".inp (Abaqus/CalculiX), .f3grid (FLAC3D)";
}

namespace internal {

inline std::string mesh_file_extension(const std::string& filename);
inline bool is_mesh_file_extension(const std::string& ext);

} // namespace internal

/// \ingroup PkgBubbleMesh3IO
/// throws a `std::runtime_error` naming `filename` and listing the known
/// extensions unless `write_mesh()` knows its extension: a program can check
/// its output names before it meshes
inline void check_mesh_file_name(const std::string& filename)
{
  const std::string ext = internal::mesh_file_extension(filename);
  if(!internal::is_mesh_file_extension(ext))
    throw std::runtime_error("cannot write the mesh to '" + filename + "': " +
                             (ext.empty() ? std::string("the name has no extension")
                                          : "unknown extension '" + ext + "'") +
                             "; known extensions: " + mesh_file_extensions());
}

namespace internal {

/// the lower-case extension of `filename` with its dot, or "" if it has none
inline std::string mesh_file_extension(const std::string& filename)
{
  const std::string::size_type dot = filename.rfind('.');
  const std::string::size_type slash = filename.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::string();
  std::string ext = filename.substr(dot);
  for(char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

inline bool is_mesh_file_extension(const std::string& ext)
{
  return ext == ".mesh" || ext == ".vtu" || ext == ".msh" || ext == ".node" || ext == ".inp" || ext == ".f3grid";
}

inline void write_mesh_file(const std::string& filename, const Mesh_arrays& m)
{
  const std::string ext = mesh_file_extension(filename);
  if(ext == ".mesh") write_medit_file(filename, m);
  else if(ext == ".vtu") write_vtu_file(filename, m);
  else if(ext == ".msh") write_gmsh_msh_file(filename, m);
  else if(ext == ".node") write_tetgen_files(filename, m);
  else if(ext == ".inp") write_abaqus_inp_file(filename, m);
  else if(ext == ".f3grid") write_flac3d_f3grid_file(filename, m);
  else check_mesh_file_name(filename);
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

writes the complex of `c3t3` to `filename` in the format its extension
names (case does not matter): `.mesh` `write_medit()`, `.vtu`
`write_vtu()`, `.msh` `write_gmsh_msh()`, `.node` `write_tetgen()` (also
writes `.ele` and `.face` beside it), `.inp` `write_abaqus_inp()`,
`.f3grid` `write_flac3d_f3grid()`. All keep the region of each
tetrahedron, the patch of each facet, and the region and patch names taken
from `model`.

\tparam C3T3 a `Mesh_complex_3_in_triangulation_3` whose subdomain index is
        the region (>= 1) and whose surface patch index is the patch index + 1
\throws std::runtime_error naming the file for an unknown extension (the
        message lists the known ones) or a file that cannot be written
*/
template <class C3T3, class GeomTraits>
void write_mesh(const std::string& filename, const C3T3& c3t3, const Geological_model_3<GeomTraits>& model)
{
  check_mesh_file_name(filename);
  internal::write_mesh_file(filename, internal::extract_mesh_arrays(c3t3, model));
}

/// \ingroup PkgBubbleMesh3IO
/// same without a model: names are `region_<r>` and `patch_<k>`, and facet
/// normals point to the smaller region index (outward on the mesh boundary)
template <class C3T3>
void write_mesh(const std::string& filename, const C3T3& c3t3)
{
  check_mesh_file_name(filename);
  internal::write_mesh_file(filename, internal::extract_mesh_arrays(c3t3, internal::Mesh_labels()));
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_MESH_H
