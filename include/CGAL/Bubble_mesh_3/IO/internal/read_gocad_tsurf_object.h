// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_INTERNAL_READ_GOCAD_TSURF_OBJECT_H
#define CGAL_BUBBLE_MESH_3_IO_INTERNAL_READ_GOCAD_TSURF_OBJECT_H

#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/IO/internal/Line_reader.h>

#include <array>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

// One `GOCAD TSurf` object as read: its points (in file order, one per VRTX
// or PVRTX; ATOM/PATOM ids alias the point they name) and its parts (TFACE
// sections) of triangles, as indices into `points`.
struct Gocad_tsurf_object
{
  struct Part
  {
    std::size_t line = 0;  // the TFACE line (0: no TFACE, an implicit first part)
    std::vector<std::array<std::size_t, 3> > triangles;
    std::vector<std::size_t> triangle_lines;
  };

  std::string name;
  std::size_t line = 0;  // the `GOCAD TSurf` line
  bool z_is_depth = false;
  bool has_zpositive = false;
  std::vector<std::array<double, 3> > points;
  std::vector<std::size_t> point_lines;
  std::vector<long long> point_ids;  // the VRTX id of each point
  std::vector<Part> parts;

  std::size_t number_of_triangles() const
  {
    std::size_t n = 0;
    for(const Part& p : parts) n += p.triangles.size();
    return n;
  }
};

// true for GOCAD keywords (upper case, digits, '_'), which readers skip when unknown
inline bool is_gocad_keyword(std::string_view t)
{
  if(t.empty() || !((t[0] >= 'A' && t[0] <= 'Z') || t[0] == '_')) return false;
  for(char c : t)
    if(!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

// Skips a `KEY ... {` block up to its `}` (the opening line is the current
// one); calls `on_line` on each line inside. Returns false if the current line
// opens no block.
template <class OnLine>
bool skip_brace_block(Line_reader& in, OnLine on_line)
{
  const std::string& l = in.line();
  const std::size_t open = l.find('{');
  if(open == std::string::npos) return false;
  if(l.find('}', open) != std::string::npos)
  {
    on_line(l.substr(open + 1, l.find('}', open) - open - 1));
    return true;
  }
  const std::size_t start = in.line_number();
  const std::string what = in.empty() ? std::string("block") : std::string(in[0]);
  while(in.next())
  {
    const std::size_t close = in.line().find('}');
    if(close != std::string::npos)
    {
      on_line(in.line().substr(0, close));
      return true;
    }
    on_line(in.line());
  }
  throw Geological_model_error(in.where() + "file ends inside the " + what + " block opened at line " +
                               std::to_string(start) + " (no '}')");
}

// `name: value` inside a HEADER block
inline void header_name(const std::string& text, std::string& name)
{
  const std::string t = trim(text);
  if(t.compare(0, 5, "name:") == 0 && name.empty()) name = trim(std::string_view(t).substr(5));
}

// `ZPOSITIVE Depth|Elevation` (the current line)
inline bool zpositive_is_depth(const Line_reader& in)
{
  if(in.size() < 2) in.error_here("ZPOSITIVE needs 'Depth' or 'Elevation'");
  std::string v(in[1]);
  for(char& c : v) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if(v == "depth") return true;
  if(v == "elevation") return false;
  in.error_here("ZPOSITIVE must be 'Depth' or 'Elevation', not " + quoted(in[1]));
}

/*
 Reads one TSurf object; the current line of `in` is its `GOCAD TSurf`
 line. Stops after its END. Triangles may name vertices defined anywhere in
 the object (resolved at END); every failure names the file, line, and the
 vertex id or value at fault.
*/
inline void read_gocad_tsurf_object(Line_reader& in, Gocad_tsurf_object& obj)
{
  obj = Gocad_tsurf_object();
  obj.line = in.line_number();
  std::unordered_map<long long, std::size_t> index_of_id;
  struct Pending
  {
    std::array<long long, 3> ids;
    std::size_t part, line;
  };
  std::vector<Pending> pending;
  auto label = [&]() { return obj.name.empty() ? std::string("the TSurf object of line ") + std::to_string(obj.line)
                                                : "TSurf '" + obj.name + "'"; };
  auto current_part = [&]() -> std::size_t {
    if(obj.parts.empty()) obj.parts.emplace_back();
    return obj.parts.size() - 1;
  };

  while(in.next())
  {
    if(in.empty() || in[0][0] == '#') continue;
    const std::string_view key = in[0];
    if(key == "END")
    {
      // resolve the triangles now that all the object's vertices are known
      for(const Pending& p : pending)
      {
        std::array<std::size_t, 3> tri;
        for(int i = 0; i < 3; ++i)
        {
          auto it = index_of_id.find(p.ids[i]);
          if(it == index_of_id.end())
            throw Geological_model_error(in.where(p.line) + "TRGL refers to vertex " + std::to_string(p.ids[i]) +
                                         ", which is not defined in " + label() + " (" +
                                         std::to_string(obj.points.size()) + " vertices)");
          tri[i] = it->second;
        }
        obj.parts[p.part].triangles.push_back(tri);
        obj.parts[p.part].triangle_lines.push_back(p.line);
      }
      return;
    }
    if(key == "VRTX" || key == "PVRTX")
    {
      const long long id = in.to_integer(1, std::string(key) + " id");
      const std::string what = "coordinate of vertex " + std::to_string(id);
      const double x = in.to_double(2, "x " + what), y = in.to_double(3, "y " + what), z = in.to_double(4, "z " + what);
      if(!index_of_id.emplace(id, obj.points.size()).second)
        in.error_here("vertex id " + std::to_string(id) + " is defined twice in " + label());
      obj.points.push_back({{x, y, z}});
      obj.point_lines.push_back(in.line_number());
      obj.point_ids.push_back(id);
      current_part();
    }
    else if(key == "ATOM" || key == "PATOM")
    {
      const long long id = in.to_integer(1, std::string(key) + " id");
      const long long target = in.to_integer(2, std::string(key) + " vertex");
      auto it = index_of_id.find(target);
      if(it == index_of_id.end())
        in.error_here(std::string(key) + " " + std::to_string(id) + " refers to vertex " + std::to_string(target) +
                      ", which is not defined before it in " + label());
      const std::size_t target_index = it->second;
      if(!index_of_id.emplace(id, target_index).second)
        in.error_here("vertex id " + std::to_string(id) + " is defined twice in " + label());
      current_part();
    }
    else if(key == "TRGL")
    {
      Pending p;
      for(int i = 0; i < 3; ++i) p.ids[i] = in.to_integer(1 + i, "TRGL vertex");
      p.part = current_part();
      p.line = in.line_number();
      pending.push_back(p);
    }
    else if(key == "TFACE")
    {
      obj.parts.emplace_back();
      obj.parts.back().line = in.line_number();
    }
    else if(key == "GOCAD")
      in.error_here("a new GOCAD object starts inside " + label() + " (its END is missing)");
    else if(in.line().find('{') != std::string::npos)
    {
      const bool is_header = (key == "HEADER");  // `key` dies with the line
      skip_brace_block(in, [&](const std::string& l) {
        if(is_header) header_name(l, obj.name);
      });
    }
    else if(key == "ZPOSITIVE")
    {
      obj.z_is_depth = zpositive_is_depth(in);
      obj.has_zpositive = true;
    }
    else if(!is_gocad_keyword(key))
      in.error_here("unexpected " + quoted(key) + " in " + label());
    // other keywords (BSTONE, BORDER, PROPERTIES, GEOLOGICAL_TYPE, ...) carry nothing we need
  }
  throw Geological_model_error(in.where() + "file ends inside " + label() + " started at line " +
                               std::to_string(obj.line) + " (no END): truncated file?");
}

} // namespace internal
} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_INTERNAL_READ_GOCAD_TSURF_OBJECT_H
