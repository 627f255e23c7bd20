// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// An independent inside test for the dynamics' checks (test_dynamics,
// bench_relaxation): CGAL::Side_of_triangle_mesh on each region's closed
// boundary, surfaces inside a region left out. The dynamics use their own
// ray parity, so this one checks them.

#ifndef CGAL_BUBBLE_MESH_3_TEST_REGION_SIDES_H
#define CGAL_BUBBLE_MESH_3_TEST_REGION_SIDES_H

#include <CGAL/Bubble_mesh_3/Bubble.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

template <class K>
struct Region_sides
{
  typedef CGAL::Surface_mesh<typename K::Point_3> Mesh;
  std::vector<std::unique_ptr<Mesh> > meshes;
  std::vector<std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, K> > > side;

  explicit Region_sides(const CGAL::Bubble_mesh_3::Geological_model_3<K>& m)
    : meshes(m.number_of_regions() + 1), side(m.number_of_regions() + 1)
  {
    for(std::size_t r = 1; r <= m.number_of_regions(); ++r)
    {
      std::vector<std::array<std::size_t, 3> > faces;
      for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
      {
        const auto& patch = m.patch(m.patch_of_triangle(t));
        if(patch.is_inside_region() || (patch.positive_region != r && patch.negative_region != r)) continue;
        std::array<std::size_t, 3> f = m.triangle(t);
        if(patch.positive_region == r) std::swap(f[1], f[2]); // outward
        faces.push_back(f);
      }
      meshes[r].reset(new Mesh);
      CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(m.points(), faces, *meshes[r]);
      side[r].reset(new CGAL::Side_of_triangle_mesh<Mesh, K>(*meshes[r]));
    }
  }

  /// strictly inside the bubble's region
  bool inside(const CGAL::Bubble_mesh_3::Bubble<K>& b) const
  {
    return (*side[b.region])(b.center) == CGAL::ON_BOUNDED_SIDE;
  }
};

#endif // CGAL_BUBBLE_MESH_3_TEST_REGION_SIDES_H
