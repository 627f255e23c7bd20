// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_LABEL_REGIONS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_LABEL_REGIONS_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/recover_surface.h>

#include <cstddef>
#include <string>
#include <algorithm>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/*
Puts the facets on input triangles into `c3t3` (patch index = patch + 1) and
gives every cell its region: the cells on either side of such a facet get the
patch's positive or negative region, the others the region of the cells they
share a facet with (flood fill). Cells of region 0 stay out of the complex.

The facets and their sides come from `Surface_recovery::surface_facets_on_triangle()`,
which deals with the flat cells that rounded Steiner points can make.

Throws Tetrahedralization_error when a cell is reached with two regions (two
regions touch where no input surface separates them) or when two input
triangles claim the same facet.
*/
template <class C3T3, class GeomTraits, class Recovery>
void label_regions(const Geological_model_3<GeomTraits>& model, const Recovery& recovery, C3T3& c3t3)
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Cell_handle     Cell_handle;
  typedef typename Tr::Facet           Facet;
  typedef typename GeomTraits::Point_3 Point_3;

  const Tr& tr = c3t3.triangulation();
  auto bare = tr.geom_traits().construct_point_3_object();
  // labels indexed by the cells' time stamps (unique among live cells); -1 = none yet
  std::size_t stamps = 0;
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) stamps = (std::max)(stamps, c->time_stamp() + 1);
  std::vector<int> label(stamps, -1);
  std::vector<Cell_handle> queue;

  auto where = [&](Cell_handle c) {
    double x = 0, y = 0, z = 0;
    int n = 0;
    for(int i = 0; i < 4; ++i)
    {
      if(tr.is_infinite(c->vertex(i))) continue;
      const Point_3 p = bare(tr.point(c, i));
      x += CGAL::to_double(p.x()); y += CGAL::to_double(p.y()); z += CGAL::to_double(p.z());
      ++n;
    }
    return Recovery::to_string(Point_3(x / n, y / n, z / n));
  };
  // `from_triangle` (or else `from_cell`) says where the region came from, for the message
  auto assign = [&](Cell_handle c, int region, std::size_t from_triangle, Cell_handle from_cell) {
    int& l = label[c->time_stamp()];
    if(l == -1) { l = region; queue.push_back(c); return; }
    if(l != region)
      throw Tetrahedralization_error(
        "the cell near " + where(c) + " lies in " + model.region_label(std::size_t(l)) +
        " and in " + model.region_label(std::size_t(region)) + " (reached from " +
        (from_triangle != std::size_t(-1) ? recovery.describe_triangle(from_triangle)
                                          : "the cell near " + where(from_cell)) +
        "): a surface between them is missing or the patches' regions are inconsistent");
  };

  // seeds: the facets of the recovered surface
  std::vector<typename Recovery::Surface_facet> facets;
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const std::size_t p = model.patch_of_triangle(t);
    const auto& patch = model.patch(p);
    if(!recovery.surface_facets_on_triangle(t, facets))
      throw Tetrahedralization_error("internal error: the flat cells on " + recovery.describe_triangle(t) +
                                     " cannot be put on one side");
    for(const auto& sf : facets)
    {
      const Facet& f = sf.facet;
      if(c3t3.is_in_complex(f))
        throw Tetrahedralization_error("two input triangles share the facet near " + where(f.first) + ": " +
                                       recovery.describe_triangle(t) + " overlaps another triangle");
      c3t3.add_to_complex(f, int(p) + 1);
      const Facet m = tr.mirror_facet(f);
      assign(f.first, int(sf.first_is_positive ? patch.positive_region : patch.negative_region), t, f.first);
      assign(m.first, int(sf.first_is_positive ? patch.negative_region : patch.positive_region), t, m.first);
    }
  }

  // flood fill across the facets that are on no input triangle
  for(std::size_t q = 0; q < queue.size(); ++q)
  {
    const Cell_handle c = queue[q];
    const int region = label[c->time_stamp()];
    for(int i = 0; i < 4; ++i)
    {
      if(c3t3.is_in_complex(c, i)) continue;
      assign(c->neighbor(i), region, std::size_t(-1), c);
    }
  }

  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
  {
    const int l = label[c->time_stamp()];
    if(l == -1)
      throw Tetrahedralization_error("internal error: the cell near " + where(c) + " was not reached by the labelling");
    if(l != 0) c3t3.add_to_complex(c, l);
  }
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
    if(tr.is_infinite(c) && label[c->time_stamp()] > 0)
      throw Tetrahedralization_error("the outside of the model is labelled " +
                                     model.region_label(std::size_t(label[c->time_stamp()])) +
                                     ": the model's outer boundary is not closed or wrongly oriented");
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_LABEL_REGIONS_H
