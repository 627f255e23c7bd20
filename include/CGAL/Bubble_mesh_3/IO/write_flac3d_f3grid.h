// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_FLAC3D_F3GRID_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_FLAC3D_F3GRID_H

#include <CGAL/Bubble_mesh_3/IO/internal/mesh_arrays.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>

#include <ostream>
#include <string>
#include <vector>

// Sources for the format: Itasca's "Itasca Grid Format" page and the
// `zone import` command of the FLAC3D 7 / 3DEC 7 manuals (docs.itascacg.com):
// `*` starts a comment line, blank lines are ignored, `G id x y z` defines a
// gridpoint and `Z type id g...` a zone; ids are positive and need not be
// consecutive. For what those pages do not show (the `F T3` face lines, zone
// and face ids counted apart, the group lines `ZGROUP "name" SLOT 1` followed
// by lines of ids, the first four gridpoints of a `T4` right-handed, i.e.
// positively oriented) the source is meshio's FLAC3D reader and writer. We
// could not check the file against FLAC3D itself.

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

inline void write_flac3d_group(std::ostream& os, const char* keyword, const std::string& name,
                               const std::vector<std::size_t>& ids)
{
  os << keyword << " \"" << name << "\" SLOT 1\n";
  for(std::size_t i = 0; i < ids.size(); ++i) os << ids[i] + 1 << ((i + 1) % 10 == 0 || i + 1 == ids.size() ? "\n" : " ");
}

inline void write_flac3d_f3grid(std::ostream& os, const Mesh_arrays& m)
{
  os << "* FLAC3D grid written by Bubble_mesh_3: " << m.points.size() << " gridpoints, " << m.tets.size()
     << " zones, " << m.triangles.size() << " faces\n";
  os << "* zone group = region, face group = patch, all in slot 1\n* GRIDPOINTS\n";
  for(std::size_t v = 0; v < m.points.size(); ++v)
  {
    os << "G " << v + 1;
    for(int d = 0; d < 3; ++d) { os << ' '; write_double(os, m.points[v][d]); }
    os << '\n';
  }
  os << "* ZONES\n";
  for(std::size_t t = 0; t < m.tets.size(); ++t)
    os << "Z T4 " << t + 1 << ' ' << m.tets[t][0] + 1 << ' ' << m.tets[t][1] + 1 << ' ' << m.tets[t][2] + 1 << ' '
       << m.tets[t][3] + 1 << '\n';
  os << "* ZONE GROUPS\n";
  Unique_names region_names, patch_names; // a repeated name would merge two groups
  for(const auto& region : m.tets_by_region())
    write_flac3d_group(os, "ZGROUP", region_names(quotable(m.region_name(region.first))), region.second);
  os << "* FACES\n";
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
    os << "F T3 " << t + 1 << ' ' << m.triangles[t][0] + 1 << ' ' << m.triangles[t][1] + 1 << ' '
       << m.triangles[t][2] + 1 << '\n';
  os << "* FACE GROUPS\n";
  for(const auto& patch : m.triangles_by_label())
    write_flac3d_group(os, "FGROUP", patch_names(quotable(m.patch_name(patch.first))), patch.second);
}

inline void write_flac3d_f3grid_file(const std::string& filename, const Mesh_arrays& m)
{
  write_atomically(filename, [&](std::ostream& os) { write_flac3d_f3grid(os, m); });
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

writes the complex of `c3t3` to `filename` as a FLAC3D ASCII grid
(`.f3grid`, FLAC3D 6 and later, `zone import`): gridpoints `G` numbered from
1, tetrahedral zones `Z T4` (zone `t` is the `t`-th tetrahedron, as in the
other formats, positively oriented, i.e. right-handed), one zone group per
region named after it (`ZGROUP "name" SLOT 1`), the complex facets as faces
`F T3` (normal pointing into the patch's positive region) and one face group
per patch (`FGROUP "name" SLOT 1`). `"` in names becomes `'`; a repeated name
gets `_2`, `_3`, ....

The file is written to `filename.tmp` and renamed when complete.

\param filename the output file
\param c3t3 the mesh (cells in the complex are written, labelled by subdomain index)
\param model gives the region and patch names and the sides of each patch
\throws std::runtime_error naming the file if it cannot be written
*/
template <class C3T3, class GeomTraits>
void write_flac3d_f3grid(const std::string& filename, const C3T3& c3t3,
                         const Geological_model_3<GeomTraits>& model)
{
  internal::write_flac3d_f3grid_file(filename, internal::extract_mesh_arrays(c3t3, model));
}

/// \ingroup PkgBubbleMesh3IO
/// same without a model: names are `region_<r>` and `patch_<k>`, and facet
/// normals point to the smaller region index (outward on the mesh boundary)
template <class C3T3>
void write_flac3d_f3grid(const std::string& filename, const C3T3& c3t3)
{
  internal::write_flac3d_f3grid_file(filename, internal::extract_mesh_arrays(c3t3, internal::Mesh_labels()));
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_FLAC3D_F3GRID_H
