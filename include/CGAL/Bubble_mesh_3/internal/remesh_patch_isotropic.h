// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_PATCH_ISOTROPIC_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_PATCH_ISOTROPIC_H

// The comparison method: CGAL's isotropic remeshing of one patch, started
// from the size-refined chart triangulations, curve edges constrained and
// protected (so the curve points shared with the neighbouring patches stay),
// then every free vertex projected onto the input patch. CGAL 5.5 takes one
// target length per call, so a patch gets the median of its sizing field
// (raised if needed to 3/4 of its longest curve edge: protected edges must
// not exceed 4/3 of the target).

#include <CGAL/Bubble_mesh_3/internal/remesh_charts.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_triangle_tree.h>

#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

// `triangles` of one patch over `points` are replaced; points that are not
// fixed are appended anew (the old ones of this patch are left unused).
// Returns false if the patch is not a manifold surface mesh (left as it was).
template <class GeomTraits, class SizeFunction>
bool isotropic_remesh_patch(std::vector<typename GeomTraits::Point_3>& points,
                            std::vector<std::array<std::size_t, 3> >& triangles, const std::vector<char>& fixed,
                            const Edge_set& constrained, const Remesh_triangle_tree<GeomTraits>& patch_tree,
                            const SizeFunction& size, unsigned int iterations, double& target_used)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Face_index Face_index;
  typedef typename Mesh::Edge_index Edge_index;

  Mesh mesh;
  std::map<std::size_t, Vertex_index> vmap;
  auto global = mesh.template add_property_map<Vertex_index, std::size_t>("v:global", std::size_t(-1)).first;
  std::vector<double> sizes;
  for(const auto& t : triangles)
    for(std::size_t v : t)
      if(!vmap.count(v))
      {
        const Vertex_index vi = mesh.add_vertex(points[v]);
        vmap[v] = vi;
        global[vi] = v;
        sizes.push_back(size(points[v]));
      }
  for(const auto& t : triangles)
    if(mesh.add_face(vmap[t[0]], vmap[t[1]], vmap[t[2]]) == Mesh::null_face()) return false;

  auto ecm = mesh.template add_property_map<Edge_index, bool>("e:constrained", false).first;
  double longest = 0.;
  for(Edge_index e : mesh.edges())
  {
    const std::size_t a = global[mesh.source(mesh.halfedge(e))], b = global[mesh.target(mesh.halfedge(e))];
    if(constrained.count(edge_key(a, b)) || mesh.is_border(e))
    {
      ecm[e] = true;
      longest = (std::max)(longest, std::sqrt(CGAL::to_double(CGAL::squared_distance(points[a], points[b]))));
    }
  }
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  double target = sizes.empty() ? 1. : sizes[sizes.size() / 2];
  if(longest > 4. / 3. * target) target = 0.76 * longest;
  target_used = target;

  std::vector<Face_index> faces(mesh.faces().begin(), mesh.faces().end());
  CGAL::Polygon_mesh_processing::isotropic_remeshing(
    faces, target, mesh,
    CGAL::parameters::edge_is_constrained_map(ecm).protect_constraints(true).number_of_iterations(iterations));

  triangles.clear();
  for(Vertex_index v : mesh.vertices())
  {
    if(global[v] != std::size_t(-1) && fixed[global[v]]) continue;
    points.push_back(patch_tree.closest_point(mesh.point(v)));
    global[v] = points.size() - 1;
  }
  for(Face_index f : mesh.faces())
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[k++] = global[v];
    triangles.push_back(t);
  }
  return true;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_PATCH_ISOTROPIC_H
