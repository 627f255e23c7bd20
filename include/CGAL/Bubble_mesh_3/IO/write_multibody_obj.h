// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_MULTIBODY_OBJ_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_MULTIBODY_OBJ_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>

#include <cstddef>
#include <iomanip>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

// a name usable after `o`, `#@inside` and `#@patch`: one line, no outer blanks, not empty
inline std::string obj_name(const std::string& name, const std::string& fallback)
{
  std::string s;
  for(char c : name) s += (c == '\n' || c == '\r' || c == '\t') ? ' ' : c;
  const std::size_t b = s.find_first_not_of(' ');
  if(b == std::string::npos) return fallback;
  return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

Writes `model` as a multi-body OBJ file that `read_multibody_obj()` reads
back to the same regions, patches, triangles and coordinates.

All points are written once, with 17 significant digits (exact round trip
of doubles). Each region becomes a group `o NAME` holding its whole closed
boundary, oriented outward, so an interface triangle appears in both its
regions; each patch's run of faces is preceded by `#@patch PATCHNAME`.
Each surface inside a region becomes its own group (named after the patch,
made unique if needed) with `#@inside REGIONNAME`. Names are written on one
line (tabs and line breaks become blanks; an empty name becomes `region_R`
or `patch_P`).

\throws Geological_model_error if two regions have the same name (groups
of the same name would be merged when read) or a patch has the outside on
both sides, or if the stream fails.
*/
template <class GeomTraits>
void write_multibody_obj(std::ostream& os, const Geological_model_3<GeomTraits>& model)
{
  typedef Geological_model_3<GeomTraits> Model;
  const std::size_t R = model.number_of_regions();
  std::vector<std::string> region_name(R + 1);
  std::map<std::string, std::size_t> region_of_name;
  for(std::size_t r = 1; r <= R; ++r)
  {
    region_name[r] = internal::obj_name(model.region(r).name, "region_" + std::to_string(r));
    auto ins = region_of_name.emplace(region_name[r], r);
    if(!ins.second)
      throw Geological_model_error("cannot write multi-body OBJ: " + model.region_label(ins.first->second) + " and " +
                                   model.region_label(r) + " have the same name");
  }

  // triangles of each patch, in model order
  std::vector<std::vector<std::size_t> > patch_triangles(model.number_of_patches());
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t) patch_triangles[model.patch_of_triangle(t)].push_back(t);
  for(std::size_t p = 0; p < model.number_of_patches(); ++p)
  {
    const typename Model::Patch& patch = model.patch(p);
    if(patch.positive_region == 0 && patch.negative_region == 0 && !patch_triangles[p].empty())
      throw Geological_model_error("cannot write multi-body OBJ: " + model.patch_label(p) +
                                   " has the outside on both sides");
  }

  const std::streamsize old_precision = os.precision();
  os << std::setprecision(17);
  os << "# multi-body OBJ written by Bubble_mesh_3: " << R << " regions, " << model.number_of_patches()
     << " patches, " << model.number_of_triangles() << " triangles\n"
     << "# each 'o' group is the closed, outward-oriented boundary of one region; '#@inside R' marks a\n"
     << "# surface inside region R, '#@patch P' names the patch of the faces that follow\n";
  for(const typename Model::Point_3& p : model.points())
    os << "v " << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' ' << CGAL::to_double(p.z()) << '\n';

  auto write_face = [&](std::size_t t, bool reversed) {
    const typename Model::Triangle& tri = model.triangle(t);
    if(reversed) os << "f " << tri[0] + 1 << ' ' << tri[2] + 1 << ' ' << tri[1] + 1 << '\n';
    else os << "f " << tri[0] + 1 << ' ' << tri[1] + 1 << ' ' << tri[2] + 1 << '\n';
  };
  auto patch_name = [&](std::size_t p) { return internal::obj_name(model.patch(p).name, "patch_" + std::to_string(p)); };

  for(std::size_t r = 1; r <= R; ++r)
  {
    os << "o " << region_name[r] << '\n';
    for(std::size_t p = 0; p < model.number_of_patches(); ++p)
    {
      const typename Model::Patch& patch = model.patch(p);
      if(patch.is_inside_region() || patch_triangles[p].empty()) continue;
      if(patch.negative_region != r && patch.positive_region != r) continue;
      os << "#@patch " << patch_name(p) << '\n';
      // outward from r: as stored when r is on the negative side
      for(std::size_t t : patch_triangles[p]) write_face(t, patch.positive_region == r);
    }
  }

  std::set<std::string> used_names;
  for(const auto& rn : region_of_name) used_names.insert(rn.first);
  for(std::size_t p = 0; p < model.number_of_patches(); ++p)
  {
    const typename Model::Patch& patch = model.patch(p);
    if(!patch.is_inside_region() || patch_triangles[p].empty()) continue;
    std::string group = patch_name(p);
    if(used_names.count(group)) group += "_patch_" + std::to_string(p);
    for(int k = 2; used_names.count(group); ++k) group = patch_name(p) + "_patch_" + std::to_string(p) + "_" + std::to_string(k);
    used_names.insert(group);
    os << "o " << group << '\n'
       << "#@inside " << region_name[patch.positive_region] << '\n'
       << "#@patch " << patch_name(p) << '\n';
    for(std::size_t t : patch_triangles[p]) write_face(t, false);
  }
  os.precision(old_precision);
  if(!os) throw Geological_model_error("writing the multi-body OBJ failed (stream error)");
}

/*!
\ingroup PkgBubbleMesh3IO
Writes `model` to the multi-body OBJ file `filename`: to `filename.tmp`
first, renamed to `filename` once complete, so that a failed write never
leaves a truncated file under the final name.
\throws Geological_model_error if the file cannot be written.
*/
template <class GeomTraits>
void write_multibody_obj(const std::string& filename, const Geological_model_3<GeomTraits>& model)
{
  internal::write_atomically(filename, [&](std::ostream& os) { write_multibody_obj(os, model); });
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_MULTIBODY_OBJ_H
