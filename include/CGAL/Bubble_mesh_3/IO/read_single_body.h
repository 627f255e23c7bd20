// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_READ_SINGLE_BODY_H
#define CGAL_BUBBLE_MESH_3_IO_READ_SINGLE_BODY_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/IO/internal/Line_reader.h>
#include <CGAL/Bubble_mesh_3/IO/internal/bodies_to_model.h>
#include <CGAL/Bubble_mesh_3/IO/reader_parameters.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {

/*!
\ingroup PkgBubbleMesh3IO

Reads the closed surface of one body from an OFF (`.off`), PLY (`.ply`) or
STL (`.stl`) file, the formats surface modellers and scanners export, into
`model` (replaced; left untouched on error): one region named after the file
(its name without folder and extension) and one patch between it and the
outside. CGAL's `read_OFF()`, `read_PLY()` and `read_STL()` parse the file;
polygons with more than three corners are split into fans from their first
corner; a body enclosing a negative volume is turned outward, and
coincident points (an STL file repeats them per triangle) are merged, as in
`read_multibody_obj()`.

\cgalNamedParamsBegin
  \cgalParamNBegin{merge_tolerance}
    \cgalParamDescription{points closer than this fraction of the bounding-box diagonal are merged}
    \cgalParamType{double}
    \cgalParamDefault{0: only identical coordinates are merged}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Geological_model_error naming the file when it cannot be opened or
parsed, and the polygon or vertex at fault (an index out of range, a polygon
with fewer than three corners, a coordinate that is not finite).
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void read_single_body(const std::string& filename, Geological_model_3<GeomTraits>& model,
                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef typename GeomTraits::Point_3 Point_3;
  {
    std::ifstream is; // a clear message for a missing file
    internal::open_for_reading(is, filename);
  }
  const std::string base = internal::file_name_part(filename);
  const std::size_t dot = base.find_last_of('.');
  const std::string ext = internal::file_extension(base);
  const std::string body = dot == std::string::npos || dot == 0 ? base : base.substr(0, dot);

  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  bool ok = false;
  std::string format;
  if(ext == "off") { format = "OFF"; ok = CGAL::IO::read_OFF(filename, points, polygons); }
  else if(ext == "ply") { format = "PLY"; ok = CGAL::IO::read_PLY(filename, points, polygons); }
  else if(ext == "stl") { format = "STL"; ok = CGAL::IO::read_STL(filename, points, polygons); }
  else
    throw Geological_model_error("cannot read '" + filename + "' as a single body: the extension is not .off, .ply or .stl");
  if(!ok)
    throw Geological_model_error(filename + ": not a valid " + format + " file (CGAL's read_" + format + "() failed)");
  if(polygons.empty()) throw Geological_model_error(filename + ": the " + format + " file has no face");

  internal::Body_soup<Point_3> soup;
  soup.file = filename;
  soup.points = points;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const Point_3& p = points[i];
    const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(double x : c)
      if(!std::isfinite(x))
        throw Geological_model_error(filename + ": vertex " + std::to_string(i) + " " +
                                     internal::point_text(c[0], c[1], c[2]) + " has a coordinate that is not finite");
  }
  soup.bodies.resize(1);
  soup.bodies[0].name = body.empty() ? std::string("body") : body;
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const std::vector<std::size_t>& poly = polygons[f];
    if(poly.size() < 3)
      throw Geological_model_error(filename + ": face " + std::to_string(f) + " has " + std::to_string(poly.size()) +
                                   (poly.size() == 1 ? " corner" : " corners") + "; a face needs three or more");
    for(std::size_t v : poly)
      if(v >= points.size())
        throw Geological_model_error(filename + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                     ", which does not exist (" + std::to_string(points.size()) + " vertices)");
    for(std::size_t k = 1; k + 1 < poly.size(); ++k)
    {
      soup.bodies[0].triangles.push_back({{poly[0], poly[k], poly[k + 1]}});
      soup.bodies[0].triangle_lines.push_back(0);
      soup.bodies[0].triangle_patch_names.push_back(internal::Body_soup<Point_3>::no_name);
    }
  }
  internal::bodies_to_model(soup, model, internal::merge_tolerance(np));
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_READ_SINGLE_BODY_H
