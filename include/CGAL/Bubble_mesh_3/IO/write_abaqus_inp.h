// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_ABAQUS_INP_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_ABAQUS_INP_H

#include <CGAL/Bubble_mesh_3/IO/internal/mesh_arrays.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>

#include <cctype>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

// Abaqus names: letters, digits and '_', starting with a letter, at most 80
// characters, unique regardless of case (Abaqus and CalculiX upper-case them).
class Abaqus_names
{
public:
  Abaqus_names() : unique_(true, 80) {}

  /// the Abaqus name for `name`; `prefix_` goes before a name that does not start with a letter
  std::string operator()(const std::string& name, const std::string& prefix)
  {
    std::string s = replace_non_word_characters(name);
    if(s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) s = prefix + "_" + s;
    return derived(s, "");
  }

  /// a name made of an Abaqus name and a suffix, shortened to leave room for a "_N"
  std::string derived(const std::string& name, const std::string& suffix)
  {
    return unique_(name.substr(0, 76 - suffix.size()) + suffix);
  }

private:
  Unique_names unique_;
};

// C3D4 face numbers: S1 = 1-2-3, S2 = 1-4-2, S3 = 2-4-3, S4 = 3-4-1, i.e.
// the face opposite node 4, 3, 1, 2.
inline int abaqus_c3d4_face(const std::array<std::size_t, 4>& tet, const std::array<std::size_t, 3>& tri)
{
  static const int face_opposite[4] = {3, 4, 2, 1};
  for(int i = 0; i < 4; ++i)
    if(tet[i] != tri[0] && tet[i] != tri[1] && tet[i] != tri[2]) return face_opposite[i];
  return 0;
}

// writes `ids` as the data lines of a set, at most 16 per line
inline void write_abaqus_id_lines(std::ostream& os, const std::vector<std::size_t>& ids)
{
  for(std::size_t i = 0; i < ids.size(); ++i)
    os << ids[i] << ((i + 1) % 16 == 0 || i + 1 == ids.size() ? "\n" : ", ");
}

inline void write_abaqus_inp(std::ostream& os, const Mesh_arrays& m)
{
  const std::vector<int> regions = m.regions_present(), labels = m.labels_present();
  Abaqus_names names;
  std::map<int, std::string> elset;
  for(int r : regions) elset[r] = names(m.region_name(r), "R");

  // per patch: the faces seen from its positive side (or its only side), and
  // for a patch with tets on both sides also from its negative side
  struct Patch_sets
  {
    std::vector<std::pair<std::size_t, int> > faces, negative_faces;
    std::set<std::size_t> nodes;
    std::string surface, negative_surface, nset;
  };
  std::map<int, Patch_sets> patches;
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    Patch_sets& p = patches[m.triangle_labels[t]];
    const std::size_t pos = m.triangle_tets[t][0], neg = m.triangle_tets[t][1];
    const std::size_t one = pos != Mesh_arrays::no_tet ? pos : neg;
    if(one != Mesh_arrays::no_tet) p.faces.emplace_back(one + 1, abaqus_c3d4_face(m.tets[one], m.triangles[t]));
    if(pos != Mesh_arrays::no_tet && neg != Mesh_arrays::no_tet)
      p.negative_faces.emplace_back(neg + 1, abaqus_c3d4_face(m.tets[neg], m.triangles[t]));
    p.nodes.insert(m.triangles[t].begin(), m.triangles[t].end());
  }
  for(int l : labels)
  {
    Patch_sets& p = patches[l];
    p.surface = names(m.patch_name(l), "S");
    if(!p.negative_faces.empty()) p.negative_surface = names.derived(p.surface, "_NEG");
    p.nset = names.derived(p.surface, "_NODES");
  }

  os << "*HEADING\nBubble_mesh_3 tetrahedral mesh: " << m.points.size() << " nodes, " << m.tets.size()
     << " C3D4 elements in " << regions.size() << " regions, " << m.triangles.size() << " faces in "
     << labels.size() << " patches\n";
  os << "** No *MATERIAL or *SOLID SECTION: add one *SOLID SECTION per region ELSET.\n";
  for(int r : regions)
    os << "** region " << r << " \"" << quotable(m.region_name(r)) << "\": ELSET=" << elset[r] << '\n';
  for(int l : labels)
  {
    const Patch_sets& p = patches[l];
    os << "** patch " << l - 1 << " \"" << quotable(m.patch_name(l)) << "\": SURFACE=" << p.surface;
    if(!p.negative_surface.empty())
      os << " (faces of the elements on its positive side), SURFACE=" << p.negative_surface << " (negative side)";
    os << ", NSET=" << p.nset << '\n';
  }

  os << "*NODE\n";
  for(std::size_t v = 0; v < m.points.size(); ++v)
  {
    os << v + 1;
    for(int d = 0; d < 3; ++d) { os << ", "; write_double(os, m.points[v][d]); }
    os << '\n';
  }
  // element numbers are the tet numbers of the other formats, grouped by region
  for(const auto& region : m.tets_by_region())
  {
    os << "*ELEMENT, TYPE=C3D4, ELSET=" << elset[region.first] << '\n';
    for(std::size_t t : region.second)
      os << t + 1 << ", " << m.tets[t][0] + 1 << ", " << m.tets[t][1] + 1 << ", " << m.tets[t][2] + 1 << ", "
           << m.tets[t][3] + 1 << '\n';
  }
  for(int l : labels)
  {
    const Patch_sets& p = patches[l];
    for(int side = 0; side < 2; ++side)
    {
      const auto& faces = side == 0 ? p.faces : p.negative_faces;
      if(faces.empty()) continue;
      os << "*SURFACE, TYPE=ELEMENT, NAME=" << (side == 0 ? p.surface : p.negative_surface) << '\n';
      for(const auto& f : faces) os << f.first << ", S" << f.second << '\n';
    }
    os << "*NSET, NSET=" << p.nset << '\n';
    std::vector<std::size_t> ids;
    for(std::size_t v : p.nodes) ids.push_back(v + 1);
    write_abaqus_id_lines(os, ids);
  }
}

inline void write_abaqus_inp_file(const std::string& filename, const Mesh_arrays& m)
{
  write_atomically(filename, [&](std::ostream& os) { write_abaqus_inp(os, m); });
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

writes the complex of `c3t3` to `filename` as an Abaqus input file (`.inp`,
also read by CalculiX): `*NODE` (numbered from 1), one `*ELEMENT,
TYPE=C3D4, ELSET=<region>` block per region (element `t` is the `t`-th
tetrahedron, as in the other formats; positively oriented), and per patch a
`*SURFACE, TYPE=ELEMENT` of element-face pairs (`S1`..`S4` in C3D4 face
numbering: S1 = 1-2-3, S2 = 1-4-2, S3 = 2-4-3, S4 = 3-4-1) plus an `*NSET`
of its nodes:
- `<patch>`: the faces of the elements on the patch's positive side, or on
  its only meshed side (the boundary of the mesh);
- `<patch>_NEG`: for a patch with elements on both sides (interfaces,
  surfaces inside a region), the faces of the elements on its negative side;
- `<patch>_NODES`: the node set.

Names are the region and patch names made Abaqus names: characters other
than letters, digits and `_` become `_`, a name not starting with a letter
gets `R_` (region) or `S_` (patch) before it, at most 80 characters, unique
regardless of case (`_2`, `_3`, ... appended). A comment at the top maps
each region and patch to its names. No `*MATERIAL` or `*SOLID SECTION` is
written: users add one section per region `ELSET`.

The file is written to `filename.tmp` and renamed when complete.

\param filename the output file
\param c3t3 the mesh (cells in the complex are written, labelled by subdomain index)
\param model gives the region and patch names and the sides of each patch
\throws std::runtime_error naming the file if it cannot be written
*/
template <class C3T3, class GeomTraits>
void write_abaqus_inp(const std::string& filename, const C3T3& c3t3, const Geological_model_3<GeomTraits>& model)
{
  internal::write_abaqus_inp_file(filename, internal::extract_mesh_arrays(c3t3, model));
}

/// \ingroup PkgBubbleMesh3IO
/// same without a model: names are `region_<r>` and `patch_<k>`, and a
/// facet's positive side is that of the smaller region index
template <class C3T3>
void write_abaqus_inp(const std::string& filename, const C3T3& c3t3)
{
  internal::write_abaqus_inp_file(filename, internal::extract_mesh_arrays(c3t3, internal::Mesh_labels()));
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_ABAQUS_INP_H
