// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_PLACE_SURFACE_BUBBLES_H
#define CGAL_BUBBLE_MESH_3_PLACE_SURFACE_BUBBLES_H

#include <CGAL/Bubble_mesh_3/Bubble.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/placement_parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

The points of the model that lie on the boundary of region `r` or on a
surface inside `r`: the vertices of the triangles of every patch that has
`r` on one side or on both. Sorted, without repetition.
*/
template <class GeomTraits>
std::vector<std::size_t> region_surface_points(const Geological_model_3<GeomTraits>& model, std::size_t r)
{
  std::vector<std::size_t> pts;
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& patch = model.patch(model.patch_of_triangle(t));
    if(patch.positive_region != r && patch.negative_region != r) continue;
    for(std::size_t v : model.triangle(t)) pts.push_back(v);
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  return pts;
}

/*!
\ingroup PkgBubbleMesh3Ref

Stage 1 of the method: one fixed bubble on every model point that a triangle
uses, with radius `surface_radius_factor` times the median length of the edges
incident to the point (the paper says mean; the median keeps the one long
edge of a coarse neighbour from inflating a fine point's bubble, which on
modelA1 filled the corners of its box with bubbles of 2-4 km). Every edge
counts once, whatever the number of triangles and patches that share it, so a
point on a contact curve sees the edges of all the surfaces that meet there. Points no triangle uses get no
bubble. Bubbles come in increasing point order; `surface_point` is the point
index, `region` is `no_index`, `is_fixed` is true.

\cgalNamedParamsBegin
  \cgalParamNBegin{surface_radius_factor}
    \cgalParamDescription{radius over median incident edge length}
    \cgalParamType{double}
    \cgalParamDefault{0.5 (METHOD.md, stage 1)}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class GeomTraits, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Bubble<GeomTraits> >
place_surface_bubbles(const Geological_model_3<GeomTraits>& model,
                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double factor = choose_parameter(get_parameter(np, internal_np::surface_radius_factor), 0.5);

  // unique undirected edges over all triangles of all patches
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  edges.reserve(3 * model.number_of_triangles());
  for(const auto& t : model.triangles())
    for(int e = 0; e < 3; ++e)
    {
      const std::size_t a = t[e], b = t[(e + 1) % 3];
      if(a != b) edges.emplace_back((std::min)(a, b), (std::max)(a, b));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  std::vector<std::pair<std::size_t, double> > incident; // (point, edge length)
  incident.reserve(2 * edges.size());
  for(const auto& e : edges)
  {
    const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(model.point(e.first), model.point(e.second))));
    incident.emplace_back(e.first, l);
    incident.emplace_back(e.second, l);
  }
  std::sort(incident.begin(), incident.end());

  std::vector<Bubble<GeomTraits> > bubbles;
  for(std::size_t k = 0; k < incident.size();)
  {
    std::size_t end = k;
    while(end < incident.size() && incident[end].first == incident[k].first) ++end;
    const std::size_t m = end - k;
    const double median = (m % 2 == 1) ? incident[k + m / 2].second
                                       : 0.5 * (incident[k + m / 2 - 1].second + incident[k + m / 2].second);
    bubbles.emplace_back(model.point(incident[k].first), factor * median, no_index, incident[k].first, true);
    k = end;
  }
  return bubbles;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_PLACE_SURFACE_BUBBLES_H
