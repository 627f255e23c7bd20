// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_TETGEN_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_TETGEN_H

#include <CGAL/Bubble_mesh_3/IO/internal/mesh_arrays.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>

#include <ostream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

inline void write_tetgen_node(std::ostream& os, const Mesh_arrays& m)
{
  os << "# Bubble_mesh_3 mesh nodes, numbered from 1\n" << m.points.size() << " 3 0 0\n";
  for(std::size_t v = 0; v < m.points.size(); ++v)
  {
    os << v + 1;
    for(int d = 0; d < 3; ++d) { os << ' '; write_double(os, m.points[v][d]); }
    os << '\n';
  }
}

inline void write_tetgen_ele(std::ostream& os, const Mesh_arrays& m)
{
  os << "# Bubble_mesh_3 tetrahedra; the attribute is the region:\n";
  for(int r : m.regions_present()) os << "#   " << r << " \"" << quotable(m.region_name(r)) << "\"\n";
  os << m.tets.size() << " 4 1\n";
  for(std::size_t t = 0; t < m.tets.size(); ++t)
    os << t + 1 << ' ' << m.tets[t][0] + 1 << ' ' << m.tets[t][1] + 1 << ' ' << m.tets[t][2] + 1 << ' '
       << m.tets[t][3] + 1 << ' ' << m.tet_regions[t] << '\n';
}

inline void write_tetgen_face(std::ostream& os, const Mesh_arrays& m)
{
  os << "# Bubble_mesh_3 surface triangles; the boundary marker is the patch index + 1:\n";
  for(int l : m.labels_present()) os << "#   " << l << " \"" << quotable(m.patch_name(l)) << "\"\n";
  os << m.triangles.size() << " 1\n";
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
    os << t + 1 << ' ' << m.triangles[t][0] + 1 << ' ' << m.triangles[t][1] + 1 << ' ' << m.triangles[t][2] + 1
       << ' ' << m.triangle_labels[t] << '\n';
}

inline void write_tetgen_files(const std::string& filename, const Mesh_arrays& m)
{
  const std::string::size_type dot = filename.rfind('.');
  const std::string::size_type slash = filename.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash) || filename.substr(dot) != ".node")
    throw std::runtime_error("cannot write TetGen files '" + filename + "': the name must end in .node");
  const std::string base = filename.substr(0, dot);
  // the .node file, the one asked for, comes last: when it is there, so are the others
  try
  {
    write_atomically(base + ".ele", [&](std::ostream& os) { write_tetgen_ele(os, m); });
    write_atomically(base + ".face", [&](std::ostream& os) { write_tetgen_face(os, m); });
  }
  catch(const std::exception& e)
  {
    throw std::runtime_error("cannot write TetGen files '" + filename + "': " + e.what());
  }
  write_atomically(filename, [&](std::ostream& os) { write_tetgen_node(os, m); });
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

writes the complex of `c3t3` as TetGen files: `filename` (which must end in
`.node`) and, beside it, the `.ele` and `.face` files of the same base name.
Numbers start at 1 in all three. `.node`: the vertices, no attributes, no
markers. `.ele`: the tetrahedra (positively oriented, as TetGen writes them)
with one attribute, the region index. `.face`: each complex facet once,
normal pointing into the patch's positive region, with boundary marker =
patch index + 1. The region and patch names are in `#` comments at the top
of `.ele` and `.face`.

Each file is written to a `.tmp` name and renamed when complete; `.node` is
renamed last.

\param filename the output file
\param c3t3 the mesh (cells in the complex are written, labelled by subdomain index)
\param model gives the region and patch names and the sides of each patch
\throws std::runtime_error naming the file if one cannot be written
*/
template <class C3T3, class GeomTraits>
void write_tetgen(const std::string& filename, const C3T3& c3t3, const Geological_model_3<GeomTraits>& model)
{
  internal::write_tetgen_files(filename, internal::extract_mesh_arrays(c3t3, model));
}

/// \ingroup PkgBubbleMesh3IO
/// same without a model: names are `region_<r>` and `patch_<k>`, and facet
/// normals point to the smaller region index (outward on the mesh boundary)
template <class C3T3>
void write_tetgen(const std::string& filename, const C3T3& c3t3)
{
  internal::write_tetgen_files(filename, internal::extract_mesh_arrays(c3t3, internal::Mesh_labels()));
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_TETGEN_H
