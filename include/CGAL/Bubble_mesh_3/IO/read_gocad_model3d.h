// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_READ_GOCAD_MODEL3D_H
#define CGAL_BUBBLE_MESH_3_IO_READ_GOCAD_MODEL3D_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/merge_coincident_points.h>
#include <CGAL/Bubble_mesh_3/IO/reader_parameters.h>
#include <CGAL/Bubble_mesh_3/IO/internal/Line_reader.h>
#include <CGAL/Bubble_mesh_3/IO/internal/read_gocad_tsurf_object.h>
#include <CGAL/Bubble_mesh_3/IO/internal/check_triangles.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

// +1 if the part has the key triangle with the same orientation, -1 reversed, 0 not found.
// Exact coordinates first; then within `tol` (headers written with fewer digits).
inline int find_key_triangle(const Gocad_tsurf_object& obj, const Gocad_tsurf_object::Part& part,
                             const std::array<std::array<double, 3>, 3>& key, double tol, double loose)
{
  auto close = [&](const std::array<double, 3>& a, const std::array<double, 3>& b, double t) {
    return std::abs(a[0] - b[0]) <= t && std::abs(a[1] - b[1]) <= t && std::abs(a[2] - b[2]) <= t;
  };
  auto match = [&](const std::array<std::size_t, 3>& tri, double t) {
    for(int s = 0; s < 3; ++s)
    {
      if(!close(obj.points[tri[s]], key[0], t)) continue;
      if(close(obj.points[tri[(s + 1) % 3]], key[1], t) && close(obj.points[tri[(s + 2) % 3]], key[2], t)) return 1;
      if(close(obj.points[tri[(s + 2) % 3]], key[1], t) && close(obj.points[tri[(s + 1) % 3]], key[2], t)) return -1;
    }
    return 0;
  };
  for(double t : {0., tol})
    for(const auto& tri : part.triangles)
      if(const int sign = match(tri, t)) return sign;
  // key points written with fewer digits than the vertices (single precision, say):
  // taken only when one triangle alone is that close
  if(loose < 0.) return 0;
  int found = 0;
  for(const auto& tri : part.triangles)
    if(const int sign = match(tri, loose))
    {
      if(found != 0) return 0;
      found = sign;
    }
  return found;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

Reads a GOCAD Model3d file (`.ml`) into `model` (which is replaced; on error
it is left untouched).

The header lists the surfaces (`TSURF name`), their parts
(`TFACE id kind surface` followed by the three points of a key triangle of
the part), the regions (`REGION id name` followed by signed TFACE ids and a
closing `0`) and optionally LAYER and SURFACE groups (ignored), up to `END`.
Then comes one `GOCAD TSurf` object per surface; its TFACE sections are the
parts, with VRTX/PVRTX and ATOM/PATOM vertices and TRGL triangles.

- Each part becomes a patch named after its surface, with a suffix `_k`
  (k = 1, 2, ...) only when the surface has several parts.
- Parts are matched to header TFACEs by their key triangle (exact
  coordinates, else within 1e-7 of the surface's bounding-box diagonal, else
  - for key points written with about seven digits - within 1e-6 of the
  largest coordinate if a single triangle of the part is that close), trying
  the part of the same rank first; a key triangle found in no part is an
  error.
- The (first) region named `Universe`, in any case, is the outside (region
  0); the other regions keep their names and their order. TSurf objects or
  sections that no header TFACE names are ignored.
- A TFACE listed in two regions separates them. One listed with both signs
  in the `Universe` lies outside the model (a fault running on beyond the
  box): it is left out, with a note in `model.notes()`. With `ZPOSITIVE Elevation`
  (the default) the region listing it as `+id` lies on the side the key
  triangle's normal (right-hand rule) points to; with `ZPOSITIVE Depth` on
  the other side. A TFACE listed with both signs in one region is a surface
  inside that region (a fault ending inside it); one listed in a single
  region only separates it from the outside if the file has no `Universe`
  region, else it lies inside that region. One listed with the same sign in
  two regions gets the first on its positive side and a note: its sides are
  for `orient_patch_sides()` to decide from the geometry.
- Coordinates are kept as they are in the file; coincident points (contacts
  are stored once per surface) are merged.

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

\throws Geological_model_error naming the file, line and offending element
(TFACE id, region, surface, vertex id, coordinates).
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void read_gocad_model3d(std::istream& is, const std::string& name, Geological_model_3<GeomTraits>& model,
                        const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Geological_model_3<GeomTraits> Model;
  typedef std::array<double, 3> P3;
  internal::Line_reader in(is, name);

  // ---- header
  while(in.next() && in.empty()) {}
  if(in.line_number() == 0 || in.empty())
    throw Geological_model_error(name + ": empty file (no 'GOCAD Model3d' line)");
  if(in.size() < 2 || !internal::equal_ignoring_case(in[0], "GOCAD") || !internal::equal_ignoring_case(in[1], "Model3d"))
    in.error_here("not a GOCAD Model3d file: it starts with " + internal::quoted(in.line()));

  struct Tface
  {
    long long id;
    std::string kind, surface;
    std::array<P3, 3> key;
    std::size_t line;
    std::vector<std::pair<std::size_t, int> > regions;  // (region in the header list, sign)
  };
  struct Region_entry
  {
    std::string name;
    std::size_t line;
  };
  struct Reference
  {
    long long tface;
    std::size_t region, line;
  };
  std::vector<Tface> tfaces;
  std::map<long long, std::size_t> tface_of_id;
  std::vector<std::string> tsurf_names;
  std::vector<Region_entry> regions;
  std::vector<Reference> references;
  bool z_is_depth = false;
  enum { NONE, REGION_LIST, OTHER_LIST } list = NONE;
  bool header_done = false;
  while(in.next())
  {
    if(in.empty() || in[0][0] == '#') continue;
    const std::string_view key = in[0];
    if(key == "END") { header_done = true; break; }
    if(key == "TSURF")
    {
      const std::string n = in.rest_after(1);
      if(n.empty()) in.error_here("TSURF without a name");
      tsurf_names.push_back(n);
      list = NONE;
    }
    else if(key == "TFACE")
    {
      Tface t;
      t.id = in.to_integer(1, "TFACE id");
      t.line = in.line_number();
      if(in.size() >= 4) { t.kind = std::string(in[2]); t.surface = in.rest_after(3); }
      else if(in.size() == 3) t.surface = std::string(in[2]);
      else in.error_here("TFACE " + std::to_string(t.id) + " needs a surface name");
      if(!tface_of_id.emplace(t.id, tfaces.size()).second)
        in.error_here("TFACE " + std::to_string(t.id) + " is defined twice (first at line " +
                      std::to_string(tfaces[tface_of_id[t.id]].line) + ")");
      for(int k = 0; k < 3; ++k)
      {
        if(!in.next())
          throw Geological_model_error(in.where() + "file ends in the key triangle of TFACE " + std::to_string(t.id));
        const std::string what = "coordinate of key point " + std::to_string(k + 1) + " of TFACE " + std::to_string(t.id);
        if(in.size() != 3) in.error_here(what.substr(14) + " must be three numbers, got " + internal::quoted(in.line()));
        t.key[k] = {{in.to_double(0, "x " + what), in.to_double(1, "y " + what), in.to_double(2, "z " + what)}};
      }
      tfaces.push_back(t);
      list = NONE;
    }
    else if(key == "REGION")
    {
      in.to_integer(1, "REGION id");
      const std::string n = in.rest_after(2);
      if(n.empty()) in.error_here("REGION without a name");
      regions.push_back(Region_entry{n, in.line_number()});
      list = REGION_LIST;
    }
    else if(key == "ZPOSITIVE")
    {
      z_is_depth = internal::zpositive_is_depth(in);
    }
    else if(key == "GOCAD")
      in.error_here("a GOCAD object starts before the Model3d header's END");
    else if(in.line().find('{') != std::string::npos)
    {
      internal::skip_brace_block(in, [](const std::string&) {});
      list = NONE;
    }
    else if(internal::is_gocad_keyword(key))
      list = OTHER_LIST;  // LAYER, SURFACE and unknown keywords: their id lists are skipped
    else if(list == NONE)
      in.error_here("unexpected " + internal::quoted(key) + " in the Model3d header");
    else
    {
      for(std::size_t i = 0; i < in.size(); ++i)
      {
        const long long v = in.to_integer(i, list == REGION_LIST ? "TFACE id in REGION '" + regions.back().name + "'"
                                                                 : std::string("id"));
        if(v == 0) { list = NONE; break; }
        if(list == REGION_LIST) references.push_back(Reference{v, regions.size() - 1, in.line_number()});
      }
    }
  }
  if(!header_done)
    throw Geological_model_error(in.where() + "file ends inside the Model3d header (no END): truncated file?");
  if(tfaces.empty()) throw Geological_model_error(in.where() + "the Model3d header has no TFACE");

  for(const Reference& r : references)
  {
    auto it = tface_of_id.find(r.tface < 0 ? -r.tface : r.tface);
    if(it == tface_of_id.end())
      throw Geological_model_error(in.where(r.line) + "REGION '" + regions[r.region].name + "' refers to TFACE " +
                                   std::to_string(r.tface < 0 ? -r.tface : r.tface) + ", which does not exist");
    tfaces[it->second].regions.push_back({r.region, r.tface > 0 ? 1 : -1});
  }

  // ---- the TSurf objects
  std::vector<internal::Gocad_tsurf_object> objects;
  std::map<std::string, std::size_t> object_of_name;
  while(in.next())
  {
    if(in.empty() || in[0][0] == '#') continue;
    if(in.size() < 2 || !internal::equal_ignoring_case(in[0], "GOCAD"))
      in.error_here("expected a 'GOCAD TSurf' object, got " + internal::quoted(in.line()));
    if(!internal::equal_ignoring_case(in[1], "TSurf")) in.error_here("unsupported GOCAD object " + internal::quoted(in[1]) + " in a Model3d file");
    objects.emplace_back();
    internal::read_gocad_tsurf_object(in, objects.back());
    if(!object_of_name.emplace(objects.back().name, objects.size() - 1).second)
      throw Geological_model_error(in.where(objects.back().line) + "two TSurf objects are named '" +
                                   objects.back().name + "'");
  }

  // ---- match header TFACEs to TFACE sections
  std::map<std::string, std::vector<std::size_t> > tfaces_of_surface;
  for(std::size_t t = 0; t < tfaces.size(); ++t) tfaces_of_surface[tfaces[t].surface].push_back(t);
  std::vector<std::size_t> object_of_tface(tfaces.size()), part_of_tface(tfaces.size());
  std::vector<int> key_sign(tfaces.size());
  for(const auto& st : tfaces_of_surface)
  {
    auto oit = object_of_name.find(st.first);
    if(oit == object_of_name.end())
      throw Geological_model_error(in.where(tfaces[st.second.front()].line) + "TFACE " +
                                   std::to_string(tfaces[st.second.front()].id) + " belongs to surface '" + st.first +
                                   "', but the file has no TSurf object of that name (truncated file?)");
    const internal::Gocad_tsurf_object& obj = objects[oit->second];
    double diag2 = 0;
    if(!obj.points.empty())
    {
      P3 lo = obj.points[0], hi = obj.points[0];
      for(const P3& p : obj.points)
        for(int d = 0; d < 3; ++d) { lo[d] = (std::min)(lo[d], p[d]); hi[d] = (std::max)(hi[d], p[d]); }
      for(int d = 0; d < 3; ++d) diag2 += (hi[d] - lo[d]) * (hi[d] - lo[d]);
    }
    const double tol = 1e-7 * std::sqrt(diag2);
    double largest = 0; // coordinate, for key points rounded to about seven digits
    for(const P3& p : obj.points)
      for(int d = 0; d < 3; ++d) largest = (std::max)(largest, std::abs(p[d]));
    const double loose = tol + 1e-6 * largest;
    std::vector<long long> part_used(obj.parts.size(), -1);
    for(std::size_t rank = 0; rank < st.second.size(); ++rank)
    {
      const std::size_t t = st.second[rank];
      int sign = 0;
      std::size_t part = 0;
      // the close matches everywhere first, the loose one only then
      for(double l : {-1., loose})
      {
        if(rank < obj.parts.size()) sign = internal::find_key_triangle(obj, obj.parts[rank], tfaces[t].key, tol, l);
        if(sign != 0) part = rank;
        else
          for(part = 0; part < obj.parts.size(); ++part)
            if(part != rank && (sign = internal::find_key_triangle(obj, obj.parts[part], tfaces[t].key, tol, l)) != 0) break;
        if(sign != 0) break;
      }
      if(sign == 0)
        throw Geological_model_error(
          in.where(tfaces[t].line) + "the key triangle of TFACE " + std::to_string(tfaces[t].id) + " " +
          internal::point_text(tfaces[t].key[0][0], tfaces[t].key[0][1], tfaces[t].key[0][2]) + " " +
          internal::point_text(tfaces[t].key[1][0], tfaces[t].key[1][1], tfaces[t].key[1][2]) + " " +
          internal::point_text(tfaces[t].key[2][0], tfaces[t].key[2][1], tfaces[t].key[2][2]) +
          " is in none of the " + std::to_string(obj.parts.size()) + " TFACE sections of TSurf '" + st.first + "'");
      if(part_used[part] >= 0)
        throw Geological_model_error(in.where(tfaces[t].line) + "TFACE " + std::to_string(tfaces[t].id) +
                                     " and TFACE " + std::to_string(part_used[part]) +
                                     " have their key triangles in the same TFACE section of TSurf '" + st.first + "'");
      part_used[part] = tfaces[t].id;
      object_of_tface[t] = oit->second;
      part_of_tface[t] = part;
      key_sign[t] = sign;
    }
  }

  // ---- regions and patches
  Model m;
  m.set_file_name(name);
  std::vector<std::size_t> model_region(regions.size(), 0);
  bool has_universe = false;
  for(std::size_t r = 0; r < regions.size(); ++r)
  {
    std::string lower = regions[r].name;
    for(char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if(lower == "universe" && !has_universe) { has_universe = true; continue; }
    model_region[r] = m.add_region(regions[r].name);
  }
  if(m.number_of_regions() == 0)
    throw Geological_model_error(
      name + (has_universe ? ": the Model3d header has no REGION but the Universe (the outside): no body to mesh "
                             "(surfaces that enclose no volume, e.g. not sealed against each other in the "
                             "modelling tool)"
                           : ": the Model3d header has no REGION"));

  std::vector<std::size_t> object_offset(objects.size() + 1, 0);
  for(std::size_t o = 0; o < objects.size(); ++o)
  {
    object_offset[o + 1] = object_offset[o] + objects[o].points.size();
    for(std::size_t i = 0; i < objects[o].points.size(); ++i)
    {
      const P3& p = objects[o].points[i];
      m.add_point(typename Model::Point_3(p[0], p[1], p[2]), typename Model::Source{name, objects[o].point_lines[i]});
    }
  }

  for(std::size_t t = 0; t < tfaces.size(); ++t)
  {
    const Tface& tf = tfaces[t];
    const std::string where = in.where(tf.line) + "TFACE " + std::to_string(tf.id) + " (surface '" + tf.surface + "')";
    std::size_t pos = 0, neg = 0;
    auto listing = [&]() {
      std::string s;
      for(const auto& rs : tf.regions)
        s += std::string(s.empty() ? "" : ", ") + "REGION '" + regions[rs.first].name + "' as " + (rs.second > 0 ? "+" : "-") +
             std::to_string(tf.id);
      return s;
    };
    // `plus` lies on the side of the key normal (Elevation), `minus` on the other
    std::size_t plus = 0, minus = 0;
    if(tf.regions.size() == 2 && tf.regions[0].second != tf.regions[1].second)
    {
      const auto& a = tf.regions[0].second > 0 ? tf.regions[0] : tf.regions[1];
      const auto& b = tf.regions[0].second > 0 ? tf.regions[1] : tf.regions[0];
      plus = model_region[a.first];
      minus = model_region[b.first];
    }
    else if(tf.regions.size() == 1)
    {
      plus = model_region[tf.regions[0].first];
      minus = has_universe ? plus : 0;
      if(tf.regions[0].second < 0) std::swap(plus, minus);
    }
    else if(tf.regions.size() == 2 && tf.regions[0].first != tf.regions[1].first)
    {
      // the same sign in both regions: one of them is wrong; either way round will
      // do, since orient_patch_sides() takes the sides from the geometry
      plus = model_region[tf.regions[0].first];
      minus = model_region[tf.regions[1].first];
      m.add_note(where + " is listed with the same sign in both its regions (" + listing() +
                 "): its sides are left to the geometry");
    }
    else if(tf.regions.empty())
      throw Geological_model_error(where + " is listed in no REGION");
    else
      throw Geological_model_error(where + " cannot be placed: it is listed as " + listing() +
                                   " (expected once with + and once with -)");
    if(plus == 0 && minus == 0)
    {
      // a part outside the model (a fault running on beyond the box): nothing to mesh
      m.add_note(where + " has the Universe on both sides: it lies outside the model and is left out");
      continue;
    }
    const bool flip = (key_sign[t] < 0) != z_is_depth;
    pos = flip ? minus : plus;
    neg = flip ? plus : minus;

    std::string patch_name = tf.surface;
    const std::vector<std::size_t>& parts = tfaces_of_surface[tf.surface];
    if(parts.size() > 1)
      patch_name += "_" + std::to_string(std::find(parts.begin(), parts.end(), t) - parts.begin() + 1);
    const std::size_t patch = m.add_patch(patch_name, pos, neg);
    const internal::Gocad_tsurf_object& obj = objects[object_of_tface[t]];
    const internal::Gocad_tsurf_object::Part& part = obj.parts[part_of_tface[t]];
    const std::size_t off = object_offset[object_of_tface[t]];
    for(std::size_t i = 0; i < part.triangles.size(); ++i)
      m.add_triangle(off + part.triangles[i][0], off + part.triangles[i][1], off + part.triangles[i][2], patch,
                     typename Model::Source{name, part.triangle_lines[i]});
  }

  merge_coincident_points(m, internal::merge_tolerance(np));
  internal::check_triangles_not_degenerate(m);
  model = std::move(m);
}

/*!
\ingroup PkgBubbleMesh3IO
Reads the GOCAD Model3d file `filename` into `model`; see the stream overload.
\throws Geological_model_error if the file cannot be opened or is not valid.
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void read_gocad_model3d(const std::string& filename, Geological_model_3<GeomTraits>& model,
                        const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::ifstream is;
  internal::open_for_reading(is, filename);
  read_gocad_model3d(is, filename, model, np);
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_READ_GOCAD_MODEL3D_H
