// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_READ_GOCAD_TSURF_H
#define CGAL_BUBBLE_MESH_3_IO_READ_GOCAD_TSURF_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/merge_coincident_points.h>
#include <CGAL/Bubble_mesh_3/IO/reader_parameters.h>
#include <CGAL/Bubble_mesh_3/IO/internal/Line_reader.h>
#include <CGAL/Bubble_mesh_3/IO/internal/bodies_to_model.h>
#include <CGAL/Bubble_mesh_3/IO/internal/check_triangles.h>
#include <CGAL/Bubble_mesh_3/IO/internal/read_gocad_tsurf_object.h>

#include <cstddef>
#include <istream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {

/*!
\ingroup PkgBubbleMesh3IO

Reads a region assignment for `read_gocad_tsurf()`: one line per TSurf
object, `OBJECTNAME POSITIVE_REGION NEGATIVE_REGION` (names without blanks;
`outside` stands for region 0; the positive region lies on the side the
object's triangle normals point to). Blank lines and lines starting with `#`
are ignored. An object with the same region on both sides is a surface inside
that region.

\throws Geological_model_error naming the line of a malformed or repeated entry.
*/
inline Region_assignment read_region_assignment(std::istream& is, const std::string& name)
{
  Region_assignment a;
  std::map<std::string, std::size_t> line_of;
  internal::Line_reader in(is, name);
  while(in.next())
  {
    if(in.empty() || in[0][0] == '#') continue;
    if(in.size() != 3)
      in.error_here("expected 'OBJECTNAME POSITIVE_REGION NEGATIVE_REGION', got " + internal::quoted(in.line(), 80));
    const std::string object(in[0]);
    if(!line_of.emplace(object, in.line_number()).second)
      in.error_here("object '" + object + "' is assigned twice (first at line " + std::to_string(line_of[object]) + ")");
    a[object] = std::make_pair(std::string(in[1]), std::string(in[2]));
  }
  if(a.empty()) throw Geological_model_error(name + ": the region assignment is empty");
  return a;
}

/// \ingroup PkgBubbleMesh3IO
/// reads the region assignment file `filename`; see the stream overload
inline Region_assignment read_region_assignment(const std::string& filename)
{
  std::ifstream is;
  internal::open_for_reading(is, filename);
  return read_region_assignment(is, filename);
}

/*!
\ingroup PkgBubbleMesh3IO

Reads a GOCAD TSurf file (`.ts`) holding one or several `GOCAD TSurf`
objects (VRTX/PVRTX, ATOM/PATOM, TRGL, TFACE sections, END) into `model`
(replaced; left untouched on error). CGAL's `read_GOCAD()` reads one object
only; this reader reads them all.

By default each object is the closed surface of one body (a region named
after the object), exactly as the groups of `read_multibody_obj()`: a
triangle found in two objects is their interface, one found in a single
object separates its body from the outside, and an object whose closed
surface encloses a negative volume is flipped as a whole. An open object
(a fault) needs a region assignment: as a body it fails validation.

With a region assignment (named parameter `region_assignment` or
`region_assignment_file`, see `read_region_assignment()`), each object
instead gives the patches between the two regions assigned to it, with the
orientation of the file: one patch per TFACE section, named after the object
(with a suffix `_k` when the object has several sections). Regions are
numbered in the order they are first named, object by object.

\cgalNamedParamsBegin
  \cgalParamNBegin{merge_tolerance}
    \cgalParamDescription{points closer than this fraction of the bounding-box diagonal are merged}
    \cgalParamType{double}
    \cgalParamDefault{0: only identical coordinates are merged}
  \cgalParamNEnd
  \cgalParamNBegin{region_assignment}
    \cgalParamDescription{object name -> (positive region name, negative region name)}
    \cgalParamType{`Region_assignment`}
    \cgalParamDefault{empty: one body per object}
  \cgalParamNEnd
  \cgalParamNBegin{region_assignment_file}
    \cgalParamDescription{a file read with `read_region_assignment()`}
    \cgalParamType{std::string}
    \cgalParamDefault{empty}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Geological_model_error naming the file, line and offending element.
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void read_gocad_tsurf(std::istream& is, const std::string& name, Geological_model_3<GeomTraits>& model,
                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Geological_model_3<GeomTraits> Model;
  typedef typename Model::Point_3 Point_3;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  Region_assignment assignment =
    choose_parameter(get_parameter(np, Bubble_mesh_3::internal_np::region_assignment), Region_assignment());
  const std::string assignment_file =
    choose_parameter(get_parameter(np, Bubble_mesh_3::internal_np::region_assignment_file), std::string());
  if(!assignment_file.empty())
  {
    const Region_assignment from_file = read_region_assignment(assignment_file);
    assignment.insert(from_file.begin(), from_file.end());
  }
  const double tolerance = internal::merge_tolerance(np);

  internal::Line_reader in(is, name);
  std::vector<internal::Gocad_tsurf_object> objects;
  std::set<std::string> names;
  while(in.next())
  {
    if(in.empty() || in[0][0] == '#') continue;
    if(in.size() < 2 || !internal::equal_ignoring_case(in[0], "GOCAD"))
      in.error_here("expected a 'GOCAD TSurf' object, got " + internal::quoted(in.line()));
    if(!internal::equal_ignoring_case(in[1], "TSurf")) in.error_here("unsupported GOCAD object " + internal::quoted(in[1]) + " in a TSurf file");
    objects.emplace_back();
    internal::read_gocad_tsurf_object(in, objects.back());
    internal::Gocad_tsurf_object& obj = objects.back();
    if(obj.name.empty()) obj.name = "TSurf_" + std::to_string(objects.size());
    if(!names.insert(obj.name).second)
      throw Geological_model_error(in.where(obj.line) + "two TSurf objects are named '" + obj.name + "'");
    if(obj.number_of_triangles() == 0)
      throw Geological_model_error(in.where(obj.line) + "TSurf '" + obj.name + "' has no triangles");
  }
  if(objects.empty())
    throw Geological_model_error(name + ": no 'GOCAD TSurf' object (" + std::string(in.line_number() ? "" : "empty file, ") +
                                 std::to_string(in.line_number()) + " lines)");

  if(assignment.empty())
  {
    internal::Body_soup<Point_3> soup;
    soup.file = name;
    for(const internal::Gocad_tsurf_object& obj : objects)
    {
      const std::size_t off = soup.points.size();
      for(std::size_t i = 0; i < obj.points.size(); ++i)
        soup.points.push_back(Point_3(obj.points[i][0], obj.points[i][1], obj.points[i][2]));
      soup.point_lines.insert(soup.point_lines.end(), obj.point_lines.begin(), obj.point_lines.end());
      soup.point_ids.insert(soup.point_ids.end(), obj.point_ids.begin(), obj.point_ids.end());
      soup.bodies.emplace_back();
      typename internal::Body_soup<Point_3>::Body& body = soup.bodies.back();
      body.name = obj.name;
      body.line = obj.line;
      for(const auto& part : obj.parts)
        for(std::size_t t = 0; t < part.triangles.size(); ++t)
        {
          body.triangles.push_back({{off + part.triangles[t][0], off + part.triangles[t][1], off + part.triangles[t][2]}});
          body.triangle_lines.push_back(part.triangle_lines[t]);
        }
    }
    internal::bodies_to_model(soup, model, tolerance);
    return;
  }

  Model m;
  m.set_file_name(name);
  std::map<std::string, std::size_t> region_of_name;
  region_of_name["outside"] = 0;
  auto region = [&](const std::string& n) {
    auto ins = region_of_name.emplace(n, 0);
    if(ins.second) ins.first->second = m.add_region(n);
    return ins.first->second;
  };
  for(const internal::Gocad_tsurf_object& obj : objects)
    if(!assignment.count(obj.name))
      throw Geological_model_error(in.where(obj.line) + "TSurf '" + obj.name + "' is not in the region assignment" +
                                   (assignment_file.empty() ? std::string() : " '" + assignment_file + "'"));
  for(const auto& entry : assignment)
    if(!names.count(entry.first))
      throw Geological_model_error(name + ": the region assignment" +
                                   (assignment_file.empty() ? std::string() : " '" + assignment_file + "'") +
                                   " names TSurf '" + entry.first + "', which the file does not contain");
  for(const internal::Gocad_tsurf_object& obj : objects)
  {
    const auto& sides = assignment[obj.name];
    const std::size_t pos = region(sides.first), neg = region(sides.second);
    if(pos == 0 && neg == 0)
      throw Geological_model_error(in.where(obj.line) + "TSurf '" + obj.name + "' is assigned the outside on both sides");
    const std::size_t off = m.number_of_points();
    for(std::size_t i = 0; i < obj.points.size(); ++i)
      m.add_point(Point_3(obj.points[i][0], obj.points[i][1], obj.points[i][2]),
                  typename Model::Source{name, obj.point_lines[i]});
    for(std::size_t k = 0; k < obj.parts.size(); ++k)
    {
      const auto& part = obj.parts[k];
      if(part.triangles.empty()) continue;
      const std::size_t patch =
        m.add_patch(obj.parts.size() > 1 ? obj.name + "_" + std::to_string(k + 1) : obj.name, pos, neg);
      for(std::size_t t = 0; t < part.triangles.size(); ++t)
        m.add_triangle(off + part.triangles[t][0], off + part.triangles[t][1], off + part.triangles[t][2], patch,
                       typename Model::Source{name, part.triangle_lines[t]});
    }
  }
  merge_coincident_points(m, tolerance);
  internal::check_triangles_not_degenerate(m);
  model = std::move(m);
}

/*!
\ingroup PkgBubbleMesh3IO
Reads the GOCAD TSurf file `filename` into `model`; see the stream overload.
\throws Geological_model_error if the file cannot be opened or is not valid.
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void read_gocad_tsurf(const std::string& filename, Geological_model_3<GeomTraits>& model,
                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::ifstream is;
  internal::open_for_reading(is, filename);
  read_gocad_tsurf(is, filename, model, np);
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_READ_GOCAD_TSURF_H
