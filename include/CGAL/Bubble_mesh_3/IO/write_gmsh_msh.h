// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_GMSH_MSH_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_GMSH_MSH_H

#include <CGAL/Bubble_mesh_3/IO/internal/mesh_arrays.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>

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

inline void write_gmsh_msh(std::ostream& os, const Mesh_arrays& m)
{
  const std::vector<int> regions = m.regions_present(), labels = m.labels_present();
  const std::size_t nt = m.tets.size(), nf = m.triangles.size(), np = m.points.size();

  // one entity per patch (dimension 2, tag = patch label) and per region
  // (dimension 3, tag = region), each in the physical group of the same tag
  std::map<int, std::vector<std::size_t> > tets_of = m.tets_by_region(), triangles_of = m.triangles_by_label();

  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  os << "$PhysicalNames\n" << labels.size() + regions.size() << '\n';
  Unique_names patch_names, region_names; // Gmsh looks groups up by name within a dimension
  for(int l : labels) os << "2 " << l << " \"" << patch_names(quotable(m.patch_name(l))) << "\"\n";
  for(int r : regions) os << "3 " << r << " \"" << region_names(quotable(m.region_name(r))) << "\"\n";
  os << "$EndPhysicalNames\n";

  // each node is classified on one entity: the lowest patch it lies on, else its lowest region
  std::vector<std::pair<int, int> > node_entity(np, std::make_pair(0, 0));
  for(int l : labels)
    for(std::size_t t : triangles_of[l])
      for(std::size_t v : m.triangles[t])
        if(node_entity[v].first == 0) node_entity[v] = std::make_pair(2, l);
  for(int r : regions)
    for(std::size_t t : tets_of[r])
      for(std::size_t v : m.tets[t])
        if(node_entity[v].first == 0) node_entity[v] = std::make_pair(3, r);
  std::map<std::pair<int, int>, std::vector<std::size_t> > nodes_of;
  for(std::size_t v = 0; v < np; ++v) nodes_of[node_entity[v]].push_back(v);

  // the patches bounding each region, signed: + when the triangle normals point out of it
  std::map<int, std::set<int> > bounding;
  for(std::size_t t = 0; t < nf; ++t)
  {
    const std::size_t pos = m.triangle_tets[t][0], neg = m.triangle_tets[t][1];
    const int rp = pos == Mesh_arrays::no_tet ? 0 : m.tet_regions[pos];
    const int rn = neg == Mesh_arrays::no_tet ? 0 : m.tet_regions[neg];
    if(rp == rn) continue; // a surface inside a region bounds nothing
    if(rp != 0) bounding[rp].insert(-m.triangle_labels[t]);
    if(rn != 0) bounding[rn].insert(m.triangle_labels[t]);
  }

  auto write_box = [&](const std::vector<std::size_t>& vertices) {
    const std::array<double, 6> b = m.bounding_box(vertices);
    for(double x : b) { os << ' '; write_double(os, x); }
  };
  auto element_vertices = [](const auto& elements, const std::vector<std::size_t>& ids) {
    std::vector<std::size_t> vs;
    for(std::size_t e : ids) vs.insert(vs.end(), elements[e].begin(), elements[e].end());
    return vs;
  };

  os << "$Entities\n0 0 " << labels.size() << ' ' << regions.size() << '\n';
  for(int l : labels)
  {
    os << l;
    write_box(element_vertices(m.triangles, triangles_of[l]));
    os << " 1 " << l << " 0\n";
  }
  for(int r : regions)
  {
    os << r;
    write_box(element_vertices(m.tets, tets_of[r]));
    os << " 1 " << r << ' ' << bounding[r].size();
    for(int s : bounding[r]) os << ' ' << s;
    os << '\n';
  }
  os << "$EndEntities\n";

  os << "$Nodes\n" << nodes_of.size() << ' ' << np << ' ' << (np == 0 ? 0 : 1) << ' ' << np << '\n';
  for(const auto& block : nodes_of)
  {
    os << block.first.first << ' ' << block.first.second << " 0 " << block.second.size() << '\n';
    for(std::size_t v : block.second) os << v + 1 << '\n';
    for(std::size_t v : block.second)
    {
      write_double(os, m.points[v][0]); os << ' ';
      write_double(os, m.points[v][1]); os << ' ';
      write_double(os, m.points[v][2]); os << '\n';
    }
  }
  os << "$EndNodes\n";

  // element tags: tetrahedron t is t+1, triangle t is nt+t+1 (type 4 = tet, 2 = triangle)
  os << "$Elements\n" << labels.size() + regions.size() << ' ' << nt + nf << ' ' << (nt + nf == 0 ? 0 : 1) << ' '
     << nt + nf << '\n';
  for(int r : regions)
  {
    os << "3 " << r << " 4 " << tets_of[r].size() << '\n';
    for(std::size_t t : tets_of[r])
      os << t + 1 << ' ' << m.tets[t][0] + 1 << ' ' << m.tets[t][1] + 1 << ' ' << m.tets[t][2] + 1 << ' '
         << m.tets[t][3] + 1 << '\n';
  }
  for(int l : labels)
  {
    os << "2 " << l << " 2 " << triangles_of[l].size() << '\n';
    for(std::size_t t : triangles_of[l])
      os << nt + t + 1 << ' ' << m.triangles[t][0] + 1 << ' ' << m.triangles[t][1] + 1 << ' '
         << m.triangles[t][2] + 1 << '\n';
  }
  os << "$EndElements\n";
}

inline void write_gmsh_msh_file(const std::string& filename, const Mesh_arrays& m)
{
  write_atomically(filename, [&](std::ostream& os) { write_gmsh_msh(os, m); });
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

writes the complex of `c3t3` to `filename` in Gmsh's ASCII `.msh` format
4.1. Each region `r` is a volume entity of tag `r` in the 3D physical group
`r` named after the region; each patch of index `k` is a surface entity of
tag `k+1` in the 2D physical group `k+1` named after the patch (names made
unique within a dimension by `_2`, `_3`, ...; `"` becomes `'`). A volume
entity lists the patches bounding it (sign `+` when the triangle normals
point out of it). Tetrahedra (type 4, positively oriented) have element tags
`1..T`, triangles (type 2, normal into the patch's positive region)
`T+1..T+F`; nodes are `1..N`, each classified on the lowest patch it lies on,
else on its lowest region.

The file is written to `filename.tmp` and renamed when complete.

\param filename the output file
\param c3t3 the mesh (cells in the complex are written, labelled by subdomain index)
\param model gives the region and patch names and the sides of each patch
\throws std::runtime_error naming the file if it cannot be written
*/
template <class C3T3, class GeomTraits>
void write_gmsh_msh(const std::string& filename, const C3T3& c3t3, const Geological_model_3<GeomTraits>& model)
{
  internal::write_gmsh_msh_file(filename, internal::extract_mesh_arrays(c3t3, model));
}

/// \ingroup PkgBubbleMesh3IO
/// same without a model: names are `region_<r>` and `patch_<k>`, and facet
/// normals point to the smaller region index (outward on the mesh boundary)
template <class C3T3>
void write_gmsh_msh(const std::string& filename, const C3T3& c3t3)
{
  internal::write_gmsh_msh_file(filename, internal::extract_mesh_arrays(c3t3, internal::Mesh_labels()));
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_GMSH_MSH_H
