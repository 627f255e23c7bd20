// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_FACE_GRAPHS_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_FACE_GRAPHS_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Named_function_parameters.h>
#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3IO

Adds to `g` the boundary of region `r` of `model`, oriented outward from the
region: the triangles of the patches that have `r` on exactly one side
(surfaces inside the region are left out). With `r == 0` it is the outer
boundary of the model, oriented outward from the model. The inverse of
`geological_model_from_face_graphs()`, region by region.

\tparam FaceGraph a model of `MutableFaceGraph`
\param model the geological model
\param r the region (0 for the outer boundary of the model)
\param g the face graph the triangles are added to
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the property map that receives the points of `g`'s vertices}
    \cgalParamType{a model of `WritablePropertyMap` whose value type is constructible from three doubles}
    \cgalParamDefault{`get(CGAL::vertex_point, g)`. Note that CGAL 5.5.1's default map for
      OpenMesh stores floats, which real coordinates (1e6 m) do not survive: pass a map that stores doubles}
  \cgalParamNEnd
\cgalNamedParamsEnd
\throws Geological_model_error if `r` is not a region or a triangle cannot be
added (the boundary is not a manifold surface there), naming the triangle.
*/
template <class GeomTraits, class FaceGraph, class CGAL_NP_TEMPLATE_PARAMETERS>
void region_boundary_to_face_graph(const Geological_model_3<GeomTraits>& model, std::size_t r, FaceGraph& g,
                                   const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<FaceGraph> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::GetVertexPointMap<FaceGraph, CGAL_NP_CLASS>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  if(r > model.number_of_regions())
    throw Geological_model_error("region_boundary_to_face_graph: region " + std::to_string(r) + " does not exist (" +
                                 std::to_string(model.number_of_regions()) + " regions)");
  VPM vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_property_map(CGAL::vertex_point, g));
  std::vector<vertex_descriptor> vertex_of_point(model.number_of_points(), GT::null_vertex());
  std::vector<vertex_descriptor> corners(3);
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& patch = model.patch(model.patch_of_triangle(t));
    if(patch.is_inside_region() || (patch.negative_region != r && patch.positive_region != r)) continue;
    std::array<std::size_t, 3> tri = model.triangle(t);
    // outward from r: as stored when r is on the negative side (for the outside, when it is positive)
    if((r != 0 && patch.positive_region == r) || (r == 0 && patch.negative_region == 0)) std::swap(tri[1], tri[2]);
    for(int i = 0; i < 3; ++i)
    {
      vertex_descriptor& v = vertex_of_point[tri[i]];
      if(v == GT::null_vertex())
      {
        v = add_vertex(g);
        const auto& p = model.point(tri[i]);
        put(vpm, v, Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
      }
      corners[i] = v;
    }
    if(CGAL::Euler::add_face(corners, g) == GT::null_face())
      throw Geological_model_error(model.where(model.triangle_source(t)) + "triangle " + std::to_string(t) + " of " +
                                   model.patch_label(model.patch_of_triangle(t)) + " cannot be added to the boundary of " +
                                   model.region_label(r) + ": the boundary is not a manifold surface there");
  }
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_FACE_GRAPHS_H
