// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_MEDIT_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_MEDIT_H

#include <CGAL/Bubble_mesh_3/IO/internal/mesh_arrays.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>

#include <ostream>
#include <string>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

inline void write_medit(std::ostream& os, const Mesh_arrays& m)
{
  // version 2: double precision coordinates
  os << "MeshVersionFormatted 2\nDimension 3\n";
  os << "Vertices\n" << m.points.size() << '\n';
  for(const auto& p : m.points)
  {
    write_double(os, p[0]); os << ' ';
    write_double(os, p[1]); os << ' ';
    write_double(os, p[2]); os << " 0\n";
  }
  os << "Triangles\n" << m.triangles.size() << '\n';
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
    os << m.triangles[t][0] + 1 << ' ' << m.triangles[t][1] + 1 << ' ' << m.triangles[t][2] + 1 << ' '
       << m.triangle_labels[t] << '\n';
  os << "Tetrahedra\n" << m.tets.size() << '\n';
  for(std::size_t t = 0; t < m.tets.size(); ++t)
    os << m.tets[t][0] + 1 << ' ' << m.tets[t][1] + 1 << ' ' << m.tets[t][2] + 1 << ' ' << m.tets[t][3] + 1 << ' '
       << m.tet_regions[t] << '\n';
  os << "End\n";
  // Medit has no names: they follow End as comments, where readers (CGAL's,
  // Gmsh's) have stopped, so that a name can never be taken for a keyword.
  for(int r : m.regions_present())
    os << "# region " << r << " \"" << quotable(m.region_name(r)) << "\"\n";
  for(int l : m.labels_present())
    os << "# patch " << l - 1 << " ref " << l << " \"" << quotable(m.patch_name(l)) << "\"\n";
}

inline void write_medit_file(const std::string& filename, const Mesh_arrays& m)
{
  write_atomically(filename, [&](std::ostream& os) { write_medit(os, m); });
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

writes the cells and facets in the complex of `c3t3` to `filename` in Medit's
ASCII `.mesh` format (`MeshVersionFormatted 2`, double precision):
`Vertices` (reference 0), `Triangles` with reference = patch index + 1, each
complex facet once, its normal pointing into the patch's positive region,
and `Tetrahedra` with reference = region index, positively oriented.
Vertex numbers are 1-based. Region and patch names follow `End` as `#`
comment lines. `CGAL::IO::read_MEDIT()` reads the file back.

The file is written to `filename.tmp` and renamed when complete.

\tparam C3T3 a `Mesh_complex_3_in_triangulation_3` with integral subdomain
        and surface patch indices (region, patch index + 1)
\param filename the output file
\param c3t3 the mesh (cells in the complex are written, labelled by subdomain index)
\param model gives the region and patch names and the sides of each patch
\throws std::runtime_error naming the file if it cannot be written
*/
template <class C3T3, class GeomTraits>
void write_medit(const std::string& filename, const C3T3& c3t3, const Geological_model_3<GeomTraits>& model)
{
  internal::write_medit_file(filename, internal::extract_mesh_arrays(c3t3, model));
}

/// \ingroup PkgBubbleMesh3IO
/// same without a model: names are `region_<r>` and `patch_<k>`, and facet
/// normals point to the smaller region index (outward on the mesh boundary)
template <class C3T3>
void write_medit(const std::string& filename, const C3T3& c3t3)
{
  internal::write_medit_file(filename, internal::extract_mesh_arrays(c3t3, internal::Mesh_labels()));
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_MEDIT_H
