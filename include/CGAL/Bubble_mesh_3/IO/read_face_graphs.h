// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_READ_FACE_GRAPHS_H
#define CGAL_BUBBLE_MESH_3_IO_READ_FACE_GRAPHS_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/IO/reader_parameters.h>
#include <CGAL/Bubble_mesh_3/IO/internal/bodies_to_model.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3IO

Builds a geological model from the closed surfaces of its bodies, one
`FaceGraph` per body (e.g. `CGAL::Surface_mesh`, or OpenMesh's
`TriMesh_ArrayKernelT` through `<CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>`).
The bodies become regions 1, 2, ... in the order given, named after `names`
(`body_1`, `body_2`, ... when `names` is empty). The logic is that of
`IO::read_multibody_obj()`: a triangle found in two bodies is their interface,
one found in a single body separates it from the outside, a closed body enclosing a
negative volume is flipped as a whole, coincident points are merged, and
faces with more than three vertices are split into fans.

\tparam FaceGraph a model of `FaceGraph` with an internal `vertex_point` property map
\param bodies the closed surfaces of the bodies
\param model the model to fill (replaced; left untouched on error)
\param names the region names, one per body, or empty
\param np optional named parameters: `merge_tolerance` (see `IO::read_multibody_obj()`)

\throws Geological_model_error naming the body and face at fault (for instance a
face with a non-finite coordinate, or a contact face given twice in one body).
*/
template <class FaceGraph, class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void geological_model_from_face_graphs(const std::vector<FaceGraph>& bodies, Geological_model_3<GeomTraits>& model,
                                       const std::vector<std::string>& names = std::vector<std::string>(),
                                       const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<FaceGraph> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename Geological_model_3<GeomTraits>::Point_3 Point_3;
  typedef IO::internal::Body_soup<Point_3> Soup;

  if(!names.empty() && names.size() != bodies.size())
    throw Geological_model_error("geological_model_from_face_graphs: " + std::to_string(bodies.size()) + " bodies but " +
                                 std::to_string(names.size()) + " names");
  Soup soup;
  for(std::size_t b = 0; b < bodies.size(); ++b)
  {
    const FaceGraph& g = bodies[b];
    soup.bodies.emplace_back();
    typename Soup::Body& body = soup.bodies.back();
    body.name = names.empty() ? "body_" + std::to_string(b + 1) : names[b];
    const auto vpm = get(CGAL::vertex_point, g);
    std::map<vertex_descriptor, std::size_t> index;
    std::size_t face_number = 0;
    std::vector<std::size_t> corner;
    for(face_descriptor f : faces(g))
    {
      corner.clear();
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, g), g))
      {
        auto ins = index.emplace(v, soup.points.size());
        if(ins.second)
        {
          const auto& p = get(vpm, v);
          const double x = CGAL::to_double(p[0]), y = CGAL::to_double(p[1]), z = CGAL::to_double(p[2]);
          if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
            throw Geological_model_error("body '" + body.name + "': face " + std::to_string(face_number) +
                                         " has a vertex with a non-finite coordinate " +
                                         IO::internal::point_text(x, y, z));
          soup.points.push_back(Point_3(x, y, z));
        }
        corner.push_back(ins.first->second);
      }
      if(corner.size() < 3)
        throw Geological_model_error("body '" + body.name + "': face " + std::to_string(face_number) + " has " +
                                     std::to_string(corner.size()) + " vertices");
      for(std::size_t i = 1; i + 1 < corner.size(); ++i)
      {
        body.triangles.push_back({{corner[0], corner[i], corner[i + 1]}});
        body.triangle_lines.push_back(0);
      }
      ++face_number;
    }
  }
  IO::internal::bodies_to_model(soup, model, IO::internal::merge_tolerance(np));
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_READ_FACE_GRAPHS_H
