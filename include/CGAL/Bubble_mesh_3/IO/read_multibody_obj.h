// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_READ_MULTIBODY_OBJ_H
#define CGAL_BUBBLE_MESH_3_IO_READ_MULTIBODY_OBJ_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/IO/reader_parameters.h>
#include <CGAL/Bubble_mesh_3/IO/internal/Line_reader.h>
#include <CGAL/Bubble_mesh_3/IO/internal/bodies_to_model.h>

#include <cstddef>
#include <fstream>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {

/*!
\ingroup PkgBubbleMesh3IO

Reads a multi-body Wavefront OBJ file into `model` (which is replaced; on
error it is left untouched).

The format:
- `v x y z` a point (further numbers on the line, e.g. colours, are ignored);
- `o NAME` or `g NAME` starts a group; NAME is the rest of the line. Each
  group is a body (one region named NAME) given by its closed surface. Groups
  with the same name are one group; groups without faces are dropped (so an
  exporter's extra `o`/`g` lines are harmless);
- `f a b c` a triangle of the current group, with 1-based indices, negative
  indices counting back from the last point read, and the `a/t/n` slash forms.
  A polygon with more than three corners is split into a fan from its first
  corner (fine for the convex polygons exporters write);
- a triangle shared by two bodies (the same three points, in any order) is
  their interface and appears in both groups; a triangle in one group only
  separates that body from the outside (region 0);
- `vt`, `vn`, `vp`, `l`, `p`, `s`, `usemtl`, `mtllib` lines are ignored; any
  other statement is an error.

Directives, in comments other OBJ tools ignore:
- `#@inside BODY` in a group (before its faces; again in a group given again) makes the group a surface
  inside the body named BODY (a fault that ends inside it, for instance):
  a patch with that body on both sides, named after the group;
- `#@patch NAME` gives the faces that follow, up to the next group, the
  patch name NAME (`write_multibody_obj()` writes them so that patch names
  survive a round trip). Faces without a name get one patch per pair of
  regions, named `A/B` after the region on the negative then the positive
  side (`outside` for region 0).

Orientation: a body whose closed surface encloses a negative volume is
flipped as a whole (an open surface is not: it has no inside, and validation
reports it); triangles oriented against their neighbours are kept as
they are, for `validate_geological_model()` to report. A contact triangle
listed with the same orientation in both its bodies is an error.

Coincident points are merged (see the named parameter), so bodies need not
share point indices.

\param is the input stream
\param name the name used for the input in messages (e.g. the file name)
\param model the model to fill
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{merge_tolerance}
    \cgalParamDescription{points closer than this fraction of the bounding-box diagonal are merged}
    \cgalParamType{double}
    \cgalParamDefault{0: only identical coordinates are merged}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Geological_model_error naming the file, line and offending element.
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void read_multibody_obj(std::istream& is, const std::string& name, Geological_model_3<GeomTraits>& model,
                        const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef typename Geological_model_3<GeomTraits>::Point_3 Point_3;
  typedef internal::Body_soup<Point_3> Soup;
  Soup soup;
  soup.file = name;
  internal::Line_reader in(is, name);

  std::map<std::string, std::size_t> body_of_name;
  std::map<std::string, std::size_t> patch_name_index;
  std::size_t current = std::size_t(-1);
  std::size_t current_patch_name = Soup::no_name;

  auto start_group = [&](const std::string& group_name, std::size_t line) {
    auto ins = body_of_name.emplace(group_name, soup.bodies.size());
    if(ins.second)
    {
      soup.bodies.emplace_back();
      soup.bodies.back().name = group_name;
      soup.bodies.back().line = line;
    }
    current = ins.first->second;
    current_patch_name = Soup::no_name;
  };

  std::vector<std::size_t> corner;
  bool any_statement = false;
  while(in.next())
  {
    if(in.empty()) continue;
    const std::string_view key = in[0];
    if(key[0] == '#')
    {
      if(key.size() < 2 || key[1] != '@') continue;
      any_statement = true;
      const std::string directive(key.substr(2));
      const std::string arg = in.rest_after(1);
      if(directive == "inside")
      {
        if(current == std::size_t(-1)) in.error_here("'#@inside' before any 'o' or 'g' group");
        if(arg.empty()) in.error_here("'#@inside' needs the name of the body the surface lies in");
        // a group given again (a fault in pieces) may say again where it lies
        if(!soup.bodies[current].triangles.empty() && soup.bodies[current].inside != arg)
          in.error_here("'#@inside' must come before the faces of group '" + soup.bodies[current].name + "'" +
                        (soup.bodies[current].inside.empty() ? std::string()
                                                             : ", which lies inside '" + soup.bodies[current].inside + "'"));
        if(arg == soup.bodies[current].name)
          in.error_here("group '" + arg + "' cannot lie inside itself");
        soup.bodies[current].inside = arg;
      }
      else if(directive == "patch")
      {
        if(arg.empty()) in.error_here("'#@patch' needs a patch name");
        auto ins = patch_name_index.emplace(arg, soup.patch_names.size());
        if(ins.second) soup.patch_names.push_back(arg);
        current_patch_name = ins.first->second;
      }
      else
        in.error_here("unknown directive " + internal::quoted(key) + " (known: #@inside, #@patch)");
      continue;
    }
    any_statement = true;
    if(key == "v")
    {
      if(in.size() < 4) in.error_here("vertex " + std::to_string(soup.points.size() + 1) + " needs three coordinates");
      const std::string what = "coordinate of vertex " + std::to_string(soup.points.size() + 1);
      const double x = in.to_double(1, "x " + what), y = in.to_double(2, "y " + what), z = in.to_double(3, "z " + what);
      soup.points.push_back(Point_3(x, y, z));
      soup.point_lines.push_back(in.line_number());
      soup.point_ids.push_back(static_cast<long long>(soup.points.size()));
    }
    else if(key == "o" || key == "g")
    {
      std::string group_name = in.rest_after(1);
      if(group_name.empty()) group_name = "default";
      start_group(group_name, in.line_number());
    }
    else if(key == "f")
    {
      if(in.size() < 4) in.error_here("a face needs at least three vertices, this one has " + std::to_string(in.size() - 1));
      if(current == std::size_t(-1)) start_group("default", in.line_number());
      corner.clear();
      for(std::size_t i = 1; i < in.size(); ++i)
      {
        std::string_view tok = in[i];
        tok = tok.substr(0, tok.find('/'));
        const long long v = in.to_integer(tok, "vertex index");
        const long long n = static_cast<long long>(soup.points.size());
        long long index = v;  // 1-based
        if(v < 0) index = n + 1 + v;
        if(v == 0 || index < 1)
          in.error_here("face refers to vertex " + std::to_string(v) + ", which does not exist (" + std::to_string(n) +
                        " vertices read so far; indices are 1-based)");
        // positive indices may point to vertices defined later: checked at the end
        corner.push_back(static_cast<std::size_t>(index - 1));
      }
      typename Soup::Body& body = soup.bodies[current];
      for(std::size_t i = 1; i + 1 < corner.size(); ++i)
      {
        body.triangles.push_back({{corner[0], corner[i], corner[i + 1]}});
        body.triangle_lines.push_back(in.line_number());
        body.triangle_patch_names.push_back(current_patch_name);
      }
    }
    else if(key == "vt" || key == "vn" || key == "vp" || key == "l" || key == "p" || key == "s" ||
            key == "usemtl" || key == "mtllib")
      continue;
    else
      in.error_here("unknown OBJ statement " + internal::quoted(key));
  }

  if(!any_statement) throw Geological_model_error(name + ": empty file (no vertices, no faces)");
  for(const typename Soup::Body& body : soup.bodies)
    for(std::size_t t = 0; t < body.triangles.size(); ++t)
      for(std::size_t v : body.triangles[t])
        if(v >= soup.points.size())
          throw Geological_model_error(in.where(body.triangle_lines[t]) + "face of group '" + body.name +
                                       "' refers to vertex " + std::to_string(v + 1) + ", but the file has " +
                                       std::to_string(soup.points.size()) + " vertices");
  std::size_t number_of_triangles = 0;
  for(const typename Soup::Body& body : soup.bodies) number_of_triangles += body.triangles.size();
  if(number_of_triangles == 0)
    throw Geological_model_error(name + ": no faces (" + std::to_string(soup.points.size()) + " vertices, " +
                                 std::to_string(in.line_number()) + " lines)");

  internal::bodies_to_model(soup, model, internal::merge_tolerance(np));
}

/*!
\ingroup PkgBubbleMesh3IO
Reads the multi-body OBJ file `filename` into `model`; see the stream overload.
\throws Geological_model_error if the file cannot be opened or is not valid.
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void read_multibody_obj(const std::string& filename, Geological_model_3<GeomTraits>& model,
                        const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::ifstream is;
  internal::open_for_reading(is, filename);
  read_multibody_obj(is, filename, model, np);
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_READ_MULTIBODY_OBJ_H
