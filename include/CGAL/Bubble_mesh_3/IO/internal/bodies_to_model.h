// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_INTERNAL_BODIES_TO_MODEL_H
#define CGAL_BUBBLE_MESH_3_IO_INTERNAL_BODIES_TO_MODEL_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/merge_coincident_points.h>
#include <CGAL/Bubble_mesh_3/IO/internal/Line_reader.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

/*
 Closed surfaces, one per body, that share the triangles of their contacts
 (each contact triangle appears once in each of the two bodies), plus
 surfaces that lie inside a body. The OBJ, TSurf and face-graph readers fill
 this and `bodies_to_model()` turns it into a geological model.
*/
template <class Point_3>
struct Body_soup
{
  static constexpr std::size_t no_name = std::size_t(-1);

  struct Body
  {
    std::string name;
    std::string inside;       // not empty: a surface inside the body of that name
    std::size_t line = 0;     // where it starts in the file (0: unknown)
    std::vector<std::array<std::size_t, 3> > triangles;  // into `points`
    std::vector<std::size_t> triangle_lines;             // 0: unknown
    std::vector<std::size_t> triangle_patch_names;       // into `patch_names`, or no_name
  };

  std::string file;                    // for messages
  std::vector<Point_3> points;
  std::vector<std::size_t> point_lines;
  std::vector<long long> point_ids;    // the vertex numbers of the file, for messages (empty: 0-based index)
  std::vector<std::string> patch_names;
  std::vector<Body> bodies;
};

/*
 Regions: one per body that has triangles and is not an inside surface, in
 the order of the bodies. A body whose closed surface encloses a negative
 volume is flipped as a whole (open or flat bodies are left as they are) (exporters disagree on orientation); triangles oriented
 against their neighbours inside a body are kept as they are, for validation
 to report. A triangle found in one body separates it from the outside; found
 in two bodies (same three points after merging, opposite orientations) it
 is their interface, kept once with the orientation of the first body.
 Patches: one per (positive region, negative region, patch name), in order of
 first appearance; unnamed ones are called "A/B" after their negative and
 positive regions, inside surfaces after the body that holds them.
*/
template <class Point_3, class GeomTraits>
void bodies_to_model(const Body_soup<Point_3>& soup, Geological_model_3<GeomTraits>& result,
                     double relative_tolerance)
{
  typedef Body_soup<Point_3> Soup;
  typedef Geological_model_3<GeomTraits> Model;
  typedef std::array<std::size_t, 3> Tri;
  const std::string& file = soup.file;

  auto triangle_text = [&](std::size_t b, std::size_t t) {
    const typename Soup::Body& body = soup.bodies[b];
    std::string s;
    const std::size_t line = t < body.triangle_lines.size() ? body.triangle_lines[t] : 0;
    if(!file.empty()) s += file + (line ? ":" + std::to_string(line) : std::string()) + ": ";
    s += "triangle " + std::to_string(t) + " of " +
         (body.inside.empty() ? "body '" : "surface '") + body.name + "'";
    return s;
  };
  auto vertex_id = [&](std::size_t v) {
    return std::to_string(v < soup.point_ids.size() ? soup.point_ids[v] : static_cast<long long>(v));
  };
  auto coordinates = [&](std::size_t v) {
    const Point_3& p = soup.points[v];
    return point_text(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };

  // ---- regions
  std::map<std::string, std::size_t> region_of_name;
  std::vector<std::size_t> body_region(soup.bodies.size(), 0);
  Model model;
  model.set_file_name(file);
  for(std::size_t b = 0; b < soup.bodies.size(); ++b)
  {
    const typename Soup::Body& body = soup.bodies[b];
    if(!body.inside.empty() || body.triangles.empty()) continue;
    if(region_of_name.count(body.name))
      throw Geological_model_error((file.empty() ? std::string() : file + ": ") + "two bodies are named '" +
                                   body.name + "'");
    region_of_name[body.name] = body_region[b] = model.add_region(body.name);
  }
  for(std::size_t b = 0; b < soup.bodies.size(); ++b)
  {
    const typename Soup::Body& body = soup.bodies[b];
    if(body.inside.empty() || body.triangles.empty()) continue;
    auto it = region_of_name.find(body.inside);
    if(it == region_of_name.end())
      throw Geological_model_error(
        (file.empty() ? std::string() : file + (body.line ? ":" + std::to_string(body.line) : std::string()) + ": ") +
        "surface '" + body.name + "' is said to be inside body '" + body.inside + "', but there is no such body");
    body_region[b] = it->second;
  }

  // ---- points, merged
  const std::size_t np = soup.points.size();
  for(const typename Soup::Body& body : soup.bodies)
    for(std::size_t t = 0; t < body.triangles.size(); ++t)
      for(std::size_t v : body.triangles[t])
        if(v >= np)
          throw Geological_model_error(triangle_text(&body - soup.bodies.data(), t) + " refers to vertex " +
                                       std::to_string(v) + " which does not exist (" + std::to_string(np) +
                                       " points)");
  const std::vector<std::size_t> rep = Bubble_mesh_3::internal::coincident_point_representatives(soup.points, relative_tolerance);

  std::vector<std::vector<Tri> > tris(soup.bodies.size());
  for(std::size_t b = 0; b < soup.bodies.size(); ++b)
  {
    const typename Soup::Body& body = soup.bodies[b];
    tris[b].reserve(body.triangles.size());
    for(std::size_t t = 0; t < body.triangles.size(); ++t)
    {
      Tri tri = body.triangles[t];
      for(std::size_t& v : tri) v = rep[v];
      for(int i = 0; i < 3; ++i)
        if(tri[i] == tri[(i + 1) % 3])
          throw Geological_model_error(triangle_text(b, t) +  " is degenerate: its vertices " +
                                       vertex_id(body.triangles[t][i]) + " and " +
                                       vertex_id(body.triangles[t][(i + 1) % 3]) + " are the same point " +
                                       coordinates(tri[i]));
      tris[b].push_back(tri);
    }
  }

  // ---- orientation of each body as a whole: only a closed surface (every
  // edge used an even number of times) has an inside; its volume is taken
  // about its own centre and must stand clear of rounding (flat bodies are
  // left alone), so that reading what the writer wrote makes the same choice
  for(std::size_t b = 0; b < soup.bodies.size(); ++b)
  {
    if(!soup.bodies[b].inside.empty() || tris[b].empty()) continue;
    std::vector<std::pair<std::size_t, std::size_t> > edges;
    edges.reserve(3 * tris[b].size());
    for(const Tri& tri : tris[b])
      for(int i = 0; i < 3; ++i)
        edges.push_back(std::minmax(tri[i], tri[(i + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    bool closed = true;
    for(std::size_t i = 0; i < edges.size() && closed;)
    {
      std::size_t j = i;
      while(j < edges.size() && edges[j] == edges[i]) ++j;
      closed = ((j - i) % 2 == 0);
      i = j;
    }
    if(!closed) continue;

    double lo[3], hi[3], c[3];
    for(int d = 0; d < 3; ++d) lo[d] = hi[d] = CGAL::to_double(soup.points[tris[b][0][0]][d]);
    for(const Tri& tri : tris[b])
      for(std::size_t v : tri)
        for(int d = 0; d < 3; ++d)
        {
          lo[d] = (std::min)(lo[d], CGAL::to_double(soup.points[v][d]));
          hi[d] = (std::max)(hi[d], CGAL::to_double(soup.points[v][d]));
        }
    double diag2 = 0;
    for(int d = 0; d < 3; ++d) { c[d] = 0.5 * (lo[d] + hi[d]); diag2 += (hi[d] - lo[d]) * (hi[d] - lo[d]); }
    double vol = 0;
    for(const Tri& tri : tris[b])
    {
      double q[3][3];
      for(int i = 0; i < 3; ++i)
        for(int d = 0; d < 3; ++d) q[i][d] = CGAL::to_double(soup.points[tri[i]][d]) - c[d];
      vol += q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) - q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
             q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
    }
    if(vol < -1e-10 * diag2 * std::sqrt(diag2))
      for(Tri& tri : tris[b]) std::swap(tri[1], tri[2]);
  }

  // ---- match triangles across bodies
  struct Occurrence
  {
    std::size_t body, triangle, other_body = std::size_t(-1), other_triangle = 0;
  };
  struct Key_hash
  {
    std::size_t operator()(const Tri& k) const
    {
      std::size_t h = k[0];
      h = h * 1000003u ^ k[1];
      h = h * 1000003u ^ k[2];
      return h;
    }
  };
  std::vector<Occurrence> occurrences;
  std::unordered_map<Tri, std::size_t, Key_hash> occurrence_of_key;
  auto same_orientation = [](const Tri& a, const Tri& b) {
    for(int s = 0; s < 3; ++s)
      if(a[0] == b[s] && a[1] == b[(s + 1) % 3] && a[2] == b[(s + 2) % 3]) return true;
    return false;
  };
  for(std::size_t b = 0; b < soup.bodies.size(); ++b)
    for(std::size_t t = 0; t < tris[b].size(); ++t)
    {
      Tri key = tris[b][t];
      std::sort(key.begin(), key.end());
      auto ins = occurrence_of_key.emplace(key, occurrences.size());
      if(ins.second)
      {
        occurrences.push_back(Occurrence{b, t});
        continue;
      }
      Occurrence& o = occurrences[ins.first->second];
      // messages are built only on failure: this loop sees every contact triangle
      auto fail = [&](const std::string& relation, const std::string& why) {
        throw Geological_model_error(triangle_text(b, t) + relation + triangle_text(o.body, o.triangle) +
                                     " (corners " + coordinates(key[0]) + " " + coordinates(key[1]) + " " +
                                     coordinates(key[2]) + ")" + why);
      };
      if(o.body == b) fail(" is a duplicate of ", "");
      if(!soup.bodies[b].inside.empty() || !soup.bodies[o.body].inside.empty())
        fail(" coincides with ", ": a surface inside a body cannot also bound a body");
      if(o.other_body != std::size_t(-1))
        fail(" coincides with ", " and with " + triangle_text(o.other_body, o.other_triangle) +
                                   ": a triangle can separate two bodies only");
      if(same_orientation(tris[b][t], tris[o.body][o.triangle]))
        fail(" has the same orientation as ",
             ": both bodies see it as outward, so one of them is oriented inconsistently there");
      o.other_body = b;
      o.other_triangle = t;
    }

  // ---- patches and triangles
  auto region_name = [&](std::size_t r) { return r == 0 ? std::string("outside") : model.region(r).name; };
  // (positive, negative, name): the name as an index into soup.patch_names, or past
  // them for the default name of an inside surface (its body) or of a region pair
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::size_t> patch_of_key;
  const std::size_t default_name = soup.patch_names.size() + soup.bodies.size();
  for(std::size_t i = 0; i < np; ++i)
    model.add_point(typename Model::Point_3(CGAL::to_double(soup.points[i].x()), CGAL::to_double(soup.points[i].y()),
                                            CGAL::to_double(soup.points[i].z())),
                    typename Model::Source{file, i < soup.point_lines.size() ? soup.point_lines[i] : 0});
  for(const Occurrence& o : occurrences)
  {
    const typename Soup::Body& body = soup.bodies[o.body];
    const std::size_t neg = body_region[o.body];
    std::size_t pos = 0;
    if(!body.inside.empty()) pos = neg;
    else if(o.other_body != std::size_t(-1)) pos = body_region[o.other_body];

    std::size_t name_index = Soup::no_name;
    if(o.triangle < body.triangle_patch_names.size()) name_index = body.triangle_patch_names[o.triangle];
    if(name_index == Soup::no_name && o.other_body != std::size_t(-1) &&
       o.other_triangle < soup.bodies[o.other_body].triangle_patch_names.size())
      name_index = soup.bodies[o.other_body].triangle_patch_names[o.other_triangle];
    std::size_t name_key = default_name;
    if(name_index != Soup::no_name && name_index < soup.patch_names.size()) name_key = name_index;
    else if(!body.inside.empty()) name_key = soup.patch_names.size() + o.body;
    auto ins = patch_of_key.emplace(std::make_tuple(pos, neg, name_key), 0);
    if(ins.second)
    {
      std::string name;
      if(name_key < soup.patch_names.size()) name = soup.patch_names[name_key];
      else if(name_key < default_name) name = body.name;
      else name = region_name(neg) + "/" + region_name(pos);
      ins.first->second = model.add_patch(name, pos, neg);
    }
    const Tri& tri = tris[o.body][o.triangle];
    const std::size_t line = o.triangle < body.triangle_lines.size() ? body.triangle_lines[o.triangle] : 0;
    model.add_triangle(tri[0], tri[1], tri[2], ins.first->second, typename Model::Source{file, line});
  }
  model.remove_unused_points();
  result = std::move(model);
}

} // namespace internal
} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_INTERNAL_BODIES_TO_MODEL_H
