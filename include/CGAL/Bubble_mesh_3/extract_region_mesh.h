// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_EXTRACT_REGION_MESH_H
#define CGAL_BUBBLE_MESH_3_EXTRACT_REGION_MESH_H

#include <array>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

The tetrahedra of one region as an indexed mesh, with its boundary: the
complex facets of its cells that separate it from another region or the
outside, oriented outward, with their patch (`patch index - 1` of the
complex, i.e. the model's patch).
*/
template <class Point_3>
struct Region_mesh
{
  std::vector<Point_3> points;                          ///< the vertices of the region's tetrahedra
  std::vector<std::array<std::size_t, 4> > tetrahedra;  ///< positively oriented
  std::vector<std::array<std::size_t, 3> > boundary;    ///< outward normals (right-hand rule)
  std::vector<std::size_t> boundary_patches;            ///< the model's patch of each boundary triangle
};

/*!
\ingroup PkgBubbleMesh3Ref

Extracts the cells of `c3t3` with subdomain index `region`. Vertices are
numbered in the order the cells are visited, so the result is the same for
the same complex.

\tparam C3T3 a `Mesh_complex_3<K>` (any `CGAL::Mesh_complex_3_in_triangulation_3`
  with integer indices)
*/
template <class C3T3>
Region_mesh<typename C3T3::Triangulation::Geom_traits::Point_3>
extract_region_mesh(const C3T3& c3t3, int region)
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle   Vertex_handle;
  const Tr& tr = c3t3.triangulation();
  auto bare = tr.geom_traits().construct_point_3_object();

  Region_mesh<typename Tr::Geom_traits::Point_3> mesh;
  std::unordered_map<Vertex_handle, std::size_t> index;
  auto index_of = [&](Vertex_handle v) {
    auto ins = index.emplace(v, mesh.points.size());
    if(ins.second) mesh.points.push_back(bare(tr.point(v)));
    return ins.first->second;
  };
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    if(c3t3.subdomain_index(c) != region) continue;
    mesh.tetrahedra.push_back({{index_of(c->vertex(0)), index_of(c->vertex(1)), index_of(c->vertex(2)),
                                index_of(c->vertex(3))}});
    for(int i = 0; i < 4; ++i)
    {
      if(!c3t3.is_in_complex(c, i)) continue;
      if(c3t3.subdomain_index(c->neighbor(i)) == region) continue; // inside the region
      // vertex_triple_index order has the normal pointing into the cell: reverse it
      mesh.boundary.push_back({{index_of(c->vertex(Tr::vertex_triple_index(i, 0))),
                                index_of(c->vertex(Tr::vertex_triple_index(i, 2))),
                                index_of(c->vertex(Tr::vertex_triple_index(i, 1)))}});
      mesh.boundary_patches.push_back(std::size_t(c3t3.surface_patch_index(c, i) - 1));
    }
  }
  return mesh;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_EXTRACT_REGION_MESH_H
