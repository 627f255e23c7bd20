// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_VTU_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_VTU_H

#include <CGAL/Bubble_mesh_3/IO/internal/mesh_arrays.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>

#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

// VTK's XML ASCII form of a vtkStringArray: the bytes of each string as
// numbers, each string ended by 0.
inline void write_vtu_string_array(std::ostream& os, const std::string& name, const std::vector<std::string>& values)
{
  os << "      <Array type=\"String\" Name=\"" << name << "\" NumberOfTuples=\"" << values.size()
     << "\" format=\"ascii\">\n       ";
  for(const std::string& s : values)
  {
    for(char ch : s) os << ' ' << int(static_cast<unsigned char>(ch));
    os << " 0";
  }
  os << "\n      </Array>\n";
}

inline void write_vtu(std::ostream& os, const Mesh_arrays& m)
{
  const std::size_t nt = m.tets.size(), nf = m.triangles.size();
  const std::vector<int> regions = m.regions_present(), labels = m.labels_present();

  // names indexed by the values of the "region" and "patch" arrays
  std::vector<std::string> region_names(regions.empty() ? 1 : regions.back() + 1);
  for(std::size_t r = 0; r < region_names.size(); ++r) region_names[r] = r == 0 ? "outside" : m.region_name(int(r));
  std::vector<std::string> patch_names(labels.empty() ? 1 : labels.back() + 1);
  for(std::size_t l = 0; l < patch_names.size(); ++l) patch_names[l] = l == 0 ? "none" : m.patch_name(int(l));

  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
     << "  <UnstructuredGrid>\n    <FieldData>\n";
  write_vtu_string_array(os, "region_names", region_names);
  write_vtu_string_array(os, "patch_names", patch_names);
  os << "    </FieldData>\n";
  os << "    <Piece NumberOfPoints=\"" << m.points.size() << "\" NumberOfCells=\"" << nt + nf << "\">\n";
  os << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for(const auto& p : m.points)
  {
    os << "         ";
    for(int d = 0; d < 3; ++d) { os << ' '; write_double(os, p[d]); }
    os << '\n';
  }
  os << "        </DataArray>\n      </Points>\n      <Cells>\n";
  os << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for(const auto& t : m.tets) os << "          " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  for(const auto& t : m.triangles) os << "          " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  os << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for(std::size_t i = 1; i <= nt; ++i) os << "          " << 4 * i << '\n';
  for(std::size_t i = 1; i <= nf; ++i) os << "          " << 4 * nt + 3 * i << '\n';
  os << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  // VTK_TETRA = 10, VTK_TRIANGLE = 5
  for(std::size_t i = 0; i < nt; ++i) os << "          10\n";
  for(std::size_t i = 0; i < nf; ++i) os << "          5\n";
  os << "        </DataArray>\n      </Cells>\n      <CellData Scalars=\"region\">\n";
  os << "        <DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n";
  for(int r : m.tet_regions) os << "          " << r << '\n';
  for(std::size_t i = 0; i < nf; ++i) os << "          -1\n";
  os << "        </DataArray>\n        <DataArray type=\"Int32\" Name=\"patch\" format=\"ascii\">\n";
  for(std::size_t i = 0; i < nt; ++i) os << "          -1\n";
  for(int l : m.triangle_labels) os << "          " << l << '\n';
  os << "        </DataArray>\n      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

inline void write_vtu_file(const std::string& filename, const Mesh_arrays& m)
{
  write_atomically(filename, [&](std::ostream& os) { write_vtu(os, m); });
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

writes the complex of `c3t3` to `filename` as one VTK XML unstructured grid
(ASCII `.vtu`, opens in ParaView): first the tetrahedra (`VTK_TETRA`,
positively oriented), then the complex facets (`VTK_TRIANGLE`, each once,
normal pointing into the patch's positive region). Cell data: `region`
(the region index for tetrahedra, -1 for triangles) and `patch` (patch
index + 1 for triangles, -1 for tetrahedra). Field data: string arrays
`region_names` (entry `r` names region `r`, entry 0 is `outside`) and
`patch_names` (entry `l` names the patch with `patch` value `l`). Point
numbers are 0-based, as in VTK.

The file is written to `filename.tmp` and renamed when complete.

\param filename the output file
\param c3t3 the mesh (cells in the complex are written, labelled by subdomain index)
\param model gives the region and patch names and the sides of each patch
\throws std::runtime_error naming the file if it cannot be written
*/
template <class C3T3, class GeomTraits>
void write_vtu(const std::string& filename, const C3T3& c3t3, const Geological_model_3<GeomTraits>& model)
{
  internal::write_vtu_file(filename, internal::extract_mesh_arrays(c3t3, model));
}

/// \ingroup PkgBubbleMesh3IO
/// same without a model: names are `region_<r>` and `patch_<k>`, and facet
/// normals point to the smaller region index (outward on the mesh boundary)
template <class C3T3>
void write_vtu(const std::string& filename, const C3T3& c3t3)
{
  internal::write_vtu_file(filename, internal::extract_mesh_arrays(c3t3, internal::Mesh_labels()));
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_VTU_H
