// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_READ_TET_MESH_H
#define CGAL_BUBBLE_MESH_3_IO_READ_TET_MESH_H

#include <CGAL/Bubble_mesh_3/mesh_quality.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {

/*!
\ingroup PkgBubbleMesh3IO

Thrown by the tetrahedral mesh readers. The message starts with `file:line: `
where a line applies, and says what is wrong.
*/
class Tet_mesh_read_error : public std::runtime_error
{
public:
  /// an error with the message `what`
  explicit Tet_mesh_read_error(const std::string& what) : std::runtime_error(what) {}
};

namespace internal {

inline std::string printable(std::string_view s)
{
  std::string r = "'";
  for(std::size_t i = 0; i < s.size() && i < 40; ++i)
    r += (static_cast<unsigned char>(s[i]) >= 32 && static_cast<unsigned char>(s[i]) < 127) ? s[i] : '?';
  return r + (s.size() > 40 ? "...'" : "'");
}

inline bool iequals(std::string_view a, std::string_view b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

// a number from text, or an error naming `what` through `fail`
template <class Fail>
double parse_double(std::string_view t, const std::string& what, Fail fail)
{
  std::string_view s = t;
  if(!s.empty() && s[0] == '+') s.remove_prefix(1);
  double v = 0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if(res.ec != std::errc() || res.ptr != s.data() + s.size())
    fail(what + " " + printable(t) + " is not a number");
  if(!std::isfinite(v)) fail(what + " " + printable(t) + " is not a finite number");
  return v;
}

// an integer; "7.0" (some writers print labels as reals) is accepted when integral
template <class Fail>
long long parse_integer(std::string_view t, const std::string& what, Fail fail)
{
  std::string_view s = t;
  if(!s.empty() && s[0] == '+') s.remove_prefix(1);
  long long v = 0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if(res.ec == std::errc() && res.ptr == s.data() + s.size()) return v;
  double d = 0;
  const auto rd = std::from_chars(s.data(), s.data() + s.size(), d);
  if(rd.ec == std::errc() && rd.ptr == s.data() + s.size() && std::isfinite(d) && d == std::floor(d) &&
     std::abs(d) < 9.0e15)
    return static_cast<long long>(d);
  fail(what + " " + printable(t) + " is not an integer");
  return 0;
}

// Text split into lines and whitespace-separated tokens, read either line by
// line or token by token across lines; every error names the file and line.
class Mesh_text_reader
{
public:
  // `comment`: a character that starts a comment up to the end of the line ('\0': none)
  Mesh_text_reader(std::istream& is, const std::string& name, char comment)
    : is_(is), name_(name), comment_(comment) {}

  const std::string& name() const { return name_; }
  std::size_t line_number() const { return line_number_; }

  [[noreturn]] void error(const std::string& what) const
  {
    throw Tet_mesh_read_error(name_ + ":" + std::to_string(line_number_) + ": " + what);
  }

  // one more line, empty or not; false at the end of the input
  bool read_line()
  {
    if(!std::getline(is_, line_))
    {
      if(is_.bad()) error("read error");
      tokens_.clear();
      next_ = 0;
      return false;
    }
    ++line_number_;
    if(line_.find('\0') != std::string::npos)
      error("binary data (a NUL byte): only the ASCII variant of this format is read");
    std::size_t end = line_.size();
    if(comment_ != '\0')
    {
      const std::size_t c = line_.find(comment_);
      if(c != std::string::npos) end = c;
    }
    tokens_.clear();
    next_ = 0;
    const char* ws = " \t\r\v\f";
    std::size_t i = 0;
    while(i < end)
    {
      i = line_.find_first_not_of(ws, i);
      if(i == std::string::npos || i >= end) break;
      std::size_t j = line_.find_first_of(ws, i);
      if(j == std::string::npos || j > end) j = end;
      tokens_.emplace_back(line_.data() + i, j - i);
      i = j;
    }
    return true;
  }

  // the next line that has a token; false at the end of the input
  bool next_line()
  {
    while(read_line())
      if(!tokens_.empty()) return true;
    return false;
  }

  // the same, as a requirement
  void expect_line(const std::string& what)
  {
    if(!next_line()) error("unexpected end of file, expected " + what);
  }

  const std::string& line() const { return line_; }
  std::size_t size() const { return tokens_.size(); }
  // next_token() continues on the next line
  void skip_rest_of_line() { next_ = tokens_.size(); }
  // tokens of the current line not yet taken by next_token()
  std::size_t remaining_on_line() const { return tokens_.size() - next_; }
  std::string_view operator[](std::size_t i) const { return tokens_[i]; }

  // the next token, on this line or a later one
  bool next_token(std::string_view& t)
  {
    while(next_ >= tokens_.size())
      if(!read_line()) return false;
    t = tokens_[next_++];
    return true;
  }

  std::string_view token(const std::string& what)
  {
    std::string_view t;
    if(!next_token(t)) error("unexpected end of file, expected " + what);
    return t;
  }

  double to_double(std::string_view t, const std::string& what) const
  {
    return parse_double(t, what, [this](const std::string& m) { error(m); });
  }
  long long to_integer(std::string_view t, const std::string& what) const
  {
    return parse_integer(t, what, [this](const std::string& m) { error(m); });
  }
  double real(const std::string& what) { return to_double(token(what), what); }
  long long integer(const std::string& what) { return to_integer(token(what), what); }
  std::size_t count(const std::string& what)
  {
    const long long n = integer(what);
    if(n < 0) error(what + " is negative (" + std::to_string(n) + ")");
    return static_cast<std::size_t>(n);
  }
  // token i of the current line as a number
  double real_at(std::size_t i, const std::string& what) const
  {
    if(i >= tokens_.size()) error("missing " + what);
    return to_double(tokens_[i], what);
  }
  long long integer_at(std::size_t i, const std::string& what) const
  {
    if(i >= tokens_.size()) error("missing " + what);
    return to_integer(tokens_[i], what);
  }

private:
  std::istream& is_;
  std::string name_;
  char comment_;
  std::string line_;
  std::size_t line_number_ = 0;
  std::vector<std::string_view> tokens_;
  std::size_t next_ = 0;
};

inline void open_mesh_file(std::ifstream& is, const std::string& filename)
{
  is.open(filename, std::ios::in | std::ios::binary);
  if(!is)
    throw Tet_mesh_read_error("cannot open '" + filename + "' for reading: " + std::strerror(errno));
}

// opens `filename` and reads it with `read(stream, filename)`
template <class Read>
Labeled_tetrahedral_mesh_3 read_file(const std::string& filename, Read read)
{
  std::ifstream is;
  open_mesh_file(is, filename);
  return read(is, filename);
}

inline bool has_extension(const std::string& f, const std::string& ext)
{
  return f.size() > ext.size() && iequals(std::string_view(f).substr(f.size() - ext.size()), ext);
}

// checks one element's vertex indices (0-based) as it is read
template <std::size_t N, class Fail>
void check_element(const std::array<std::size_t, N>& v, std::size_t number_of_points, const char* what, Fail fail)
{
  for(std::size_t i = 0; i < N; ++i)
  {
    if(v[i] >= number_of_points)
      fail(std::string(what) + " refers to vertex " + std::to_string(v[i]) + " (0-based) but there are " +
           std::to_string(number_of_points) + " vertices");
    for(std::size_t j = 0; j < i; ++j)
      if(v[i] == v[j]) fail(std::string(what) + " repeats vertex " + std::to_string(v[i]) + " (0-based)");
  }
}

// label of an element from a real-valued attribute: must be an integer
template <class Fail>
int integral_label(double v, const std::string& what, Fail fail)
{
  if(!(v == std::floor(v)) || std::abs(v) > 2.0e9)
    fail(what + " " + std::to_string(v) + " is not an integer label");
  return static_cast<int>(v);
}

// ---------------------------------------------------------------- Medit

inline Labeled_tetrahedral_mesh_3 read_medit(std::istream& is, const std::string& name)
{
  Mesh_text_reader in(is, name, '#');
  Labeled_tetrahedral_mesh_3 m;
  auto fail = [&in](const std::string& s) { in.error(s); };
  bool vertices_seen = false;
  std::vector<std::size_t> pending_lines; // tets read before the vertices: checked at the end
  std::string_view kw;
  while(in.next_token(kw))
  {
    const std::string k(kw);
    auto is_kw = [&](const char* s) { return iequals(k, s); };
    if(is_kw("End")) break;
    if(is_kw("MeshVersionFormatted"))
    {
      const long long v = in.integer("version after MeshVersionFormatted");
      if(v < 1 || v > 4) in.error("unknown MeshVersionFormatted " + std::to_string(v));
    }
    else if(is_kw("Dimension"))
    {
      const long long d = in.integer("dimension");
      if(d != 3) in.error("Dimension " + std::to_string(d) + ": only 3D meshes are read");
    }
    else if(is_kw("Vertices"))
    {
      const std::size_t n = in.count("number of vertices");
      m.points.reserve(n);
      for(std::size_t i = 0; i < n; ++i)
      {
        const double x = in.real("x of vertex"), y = in.real("y of vertex"), z = in.real("z of vertex");
        in.integer("reference of vertex");
        m.points.push_back({{x, y, z}});
      }
      vertices_seen = true;
    }
    else if(is_kw("Tetrahedra") || is_kw("Triangles"))
    {
      const bool tets = is_kw("Tetrahedra");
      const std::size_t nv = tets ? 4 : 3;
      const std::size_t n = in.count("number of " + k);
      for(std::size_t i = 0; i < n; ++i)
      {
        std::array<std::size_t, 4> v = {{0, 0, 0, 0}};
        for(std::size_t j = 0; j < nv; ++j)
        {
          const long long x = in.integer("vertex index");
          if(x < 1) in.error("vertex index " + std::to_string(x) + " (Medit counts from 1)");
          v[j] = std::size_t(x - 1);
        }
        const long long ref = in.integer("reference (label)");
        if(tets)
        {
          if(vertices_seen) check_element(v, m.points.size(), "tetrahedron", fail);
          else pending_lines.push_back(in.line_number());
          m.tetrahedra.push_back(v);
          m.regions.push_back(int(ref));
        }
        else
        {
          const std::array<std::size_t, 3> t = {{v[0], v[1], v[2]}};
          if(vertices_seen) check_element(t, m.points.size(), "triangle", fail);
          m.boundary_triangles.push_back(t);
          m.boundary_patches.push_back(int(ref));
        }
      }
    }
    else
    {
      // sections that do not matter here: skip their numbers
      static const std::pair<const char*, int> skipped[] = {
        {"Edges", 3}, {"Quadrilaterals", 5}, {"Corners", 1}, {"RequiredVertices", 1}, {"Ridges", 1},
        {"RequiredEdges", 1}, {"RequiredTriangles", 1}, {"RequiredQuadrilaterals", 1},
        {"RequiredTetrahedra", 1}, {"Normals", 3}, {"Tangents", 3}, {"NormalAtVertices", 2},
        {"TangentAtVertices", 2}, {"TangentAtEdges", 3}, {"NormalAtTriangleVertices", 3},
        {"NormalAtQuadrilateralVertices", 3}};
      int width = -1;
      for(const auto& s : skipped)
        if(is_kw(s.first)) width = s.second;
      if(is_kw("Hexahedra") || is_kw("Prisms") || is_kw("Pyramids"))
        in.error(k + ": only tetrahedral meshes are read (the quality report covers tetrahedra)");
      if(width < 0)
        in.error("unknown keyword " + printable(k) +
                 " (read: Vertices, Triangles, Tetrahedra; skipped: Edges, Corners, Ridges, Required*, Normals, ...)");
      const std::size_t n = in.count("number of " + k);
      for(std::size_t i = 0; i < n * std::size_t(width); ++i) in.real(k + " value");
    }
  }
  if(!vertices_seen) in.error("no Vertices section");
  for(std::size_t i = 0; i < pending_lines.size(); ++i)
    check_element(m.tetrahedra[i], m.points.size(), "tetrahedron",
                  [&](const std::string& s) { throw Tet_mesh_read_error(name + ":" + std::to_string(pending_lines[i]) + ": " + s); });
  return m;
}

// ---------------------------------------------------------------- Gmsh

// Gmsh element types: corner count of tetrahedra and triangles (any order), or
// 0 for the other types; 3D non-tetrahedra are refused
inline int gmsh_corners(long long type, bool& other_3d)
{
  other_3d = false;
  switch(type)
  {
  case 4: case 11: case 29: case 30: case 31: return 4;   // tetrahedra, orders 1-5
  case 2: case 9: case 20: case 21: case 22: case 23: case 24: case 25: return 3; // triangles
  case 5: case 6: case 7: case 12: case 13: case 14: case 17: case 18: case 19:
  case 92: case 93: case 94: case 95: case 96: case 97: case 98: case 99: case 100:
  case 101: case 102: case 103: case 104: case 105: case 106: case 107: case 108: case 109:
  case 110: case 111: case 112: case 113: case 114: case 115: case 116: case 117: case 118:
    other_3d = true; return 0;
  default: return 0;
  }
}

struct Gmsh_elements
{
  Labeled_tetrahedral_mesh_3& m;
  const std::unordered_map<long long, std::size_t>& node;
  Mesh_text_reader& in;

  std::size_t index(std::string_view t)
  {
    const long long tag = in.to_integer(t, "node tag");
    auto it = node.find(tag);
    if(it == node.end()) in.error("element refers to node " + std::to_string(tag) + ", which is not in $Nodes");
    return it->second;
  }
  // one element, its nodes from token `first` of the current line
  void add(long long type, std::size_t first, int label)
  {
    bool other_3d = false;
    const int corners = gmsh_corners(type, other_3d);
    if(other_3d)
      in.error("element type " + std::to_string(type) +
               " is a 3D element other than a tetrahedron: only tetrahedral meshes are read");
    if(corners == 0) return;
    if(in.size() < first + std::size_t(corners)) in.error("too few node tags for element type " + std::to_string(type));
    auto fail = [this](const std::string& s) { in.error(s); };
    if(corners == 4)
    {
      const std::array<std::size_t, 4> v = {{index(in[first]), index(in[first + 1]), index(in[first + 2]),
                                             index(in[first + 3])}};
      check_element(v, m.points.size(), "tetrahedron", fail);
      m.tetrahedra.push_back(v);
      m.regions.push_back(label);
    }
    else
    {
      const std::array<std::size_t, 3> v = {{index(in[first]), index(in[first + 1]), index(in[first + 2])}};
      check_element(v, m.points.size(), "triangle", fail);
      m.boundary_triangles.push_back(v);
      m.boundary_patches.push_back(label);
    }
  }
};

inline void gmsh_skip_section(Mesh_text_reader& in, const std::string& section)
{
  const std::string end = "$End" + section.substr(1);
  while(in.next_line())
    if(in[0] == end) return;
  in.error("unexpected end of file in section " + section + " (no " + end + ")");
}

inline void gmsh_expect_end(Mesh_text_reader& in, const std::string& section)
{
  in.expect_line("$End" + section.substr(1));
  if(in[0] != "$End" + section.substr(1))
    in.error("expected $End" + section.substr(1) + ", found " + printable(in.line()) +
             " (more lines than the section's counts say)");
}

inline Labeled_tetrahedral_mesh_3 read_gmsh(std::istream& is, const std::string& name)
{
  Mesh_text_reader in(is, name, '\0');
  Labeled_tetrahedral_mesh_3 m;
  std::unordered_map<long long, std::size_t> node;
  std::map<std::pair<int, long long>, long long> physical; // (dim, entity) -> first physical tag
  std::map<int, std::string> names3;
  int major = 0;
  bool nodes_seen = false;
  while(in.next_line())
  {
    const std::string section(in[0]);
    if(section.empty() || section[0] != '$') in.error("expected a section such as $Nodes, found " + printable(in.line()));
    if(section == "$MeshFormat")
    {
      in.expect_line("version line");
      const std::string v(in[0]);
      if(v.rfind("4.1", 0) == 0) major = 4;
      else if(v.rfind("2.", 0) == 0) major = 2;
      else in.error("Gmsh format " + v + " is not read (read: 4.1 and 2.2; Gmsh writes them with -format msh41 / msh22)");
      if(in.integer_at(1, "file type") != 0) in.error("binary .msh is not read: save as ASCII (Gmsh: -bin 0)");
      gmsh_expect_end(in, section);
    }
    else if(major == 0)
      in.error("the file does not start with $MeshFormat");
    else if(section == "$PhysicalNames")
    {
      in.expect_line("number of physical names");
      const long long n = in.integer_at(0, "number of physical names");
      for(long long i = 0; i < n; ++i)
      {
        in.expect_line("physical name");
        const long long dim = in.integer_at(0, "dimension"), tag = in.integer_at(1, "physical tag");
        const std::size_t a = in.line().find('"'), b = in.line().rfind('"');
        if(a == std::string::npos || b == a) in.error("physical name without quotes");
        if(dim == 3) names3[int(tag)] = in.line().substr(a + 1, b - a - 1);
      }
      gmsh_expect_end(in, section);
    }
    else if(section == "$Entities" && major == 4)
    {
      in.expect_line("entity counts");
      std::array<long long, 4> count;
      for(std::size_t d = 0; d < 4; ++d) count[d] = in.integer_at(d, "entity count");
      for(int dim = 0; dim < 4; ++dim)
        for(long long i = 0; i < count[std::size_t(dim)]; ++i)
        {
          in.expect_line("entity");
          const long long tag = in.integer_at(0, "entity tag");
          const std::size_t at = dim == 0 ? 4 : 7; // after x y z, or after the bounding box
          const long long np = in.integer_at(at, "number of physical tags");
          if(np > 0) physical[std::make_pair(dim, tag)] = in.integer_at(at + 1, "physical tag");
        }
      gmsh_expect_end(in, section);
    }
    else if(section == "$Nodes")
    {
      in.expect_line("node counts");
      if(major == 4)
      {
        const long long blocks = in.integer_at(0, "number of node blocks");
        m.points.reserve(std::size_t(in.integer_at(1, "number of nodes")));
        for(long long b = 0; b < blocks; ++b)
        {
          in.expect_line("node block header");
          const long long parametric = in.integer_at(2, "parametric flag");
          const long long n = in.integer_at(3, "number of nodes in block");
          const std::size_t first = m.points.size();
          std::vector<long long> tags;
          for(long long i = 0; i < n; ++i)
          {
            in.expect_line("node tag");
            tags.push_back(in.integer_at(0, "node tag"));
          }
          for(long long i = 0; i < n; ++i)
          {
            in.expect_line("node coordinates");
            if(parametric == 0 && in.size() != 3) in.error("expected 3 coordinates, found " + std::to_string(in.size()) + " numbers");
            m.points.push_back({{in.real_at(0, "x"), in.real_at(1, "y"), in.real_at(2, "z")}});
          }
          for(long long i = 0; i < n; ++i)
            if(!node.emplace(tags[std::size_t(i)], first + std::size_t(i)).second)
              in.error("node tag " + std::to_string(tags[std::size_t(i)]) + " appears twice");
        }
      }
      else
      {
        const long long n = in.integer_at(0, "number of nodes");
        for(long long i = 0; i < n; ++i)
        {
          in.expect_line("node");
          const long long tag = in.integer_at(0, "node tag");
          if(!node.emplace(tag, m.points.size()).second) in.error("node tag " + std::to_string(tag) + " appears twice");
          m.points.push_back({{in.real_at(1, "x"), in.real_at(2, "y"), in.real_at(3, "z")}});
        }
      }
      nodes_seen = true;
      gmsh_expect_end(in, section);
    }
    else if(section == "$Elements")
    {
      if(!nodes_seen) in.error("$Elements before $Nodes");
      Gmsh_elements elements{m, node, in};
      in.expect_line("element counts");
      if(major == 4)
      {
        const long long blocks = in.integer_at(0, "number of element blocks");
        for(long long b = 0; b < blocks; ++b)
        {
          in.expect_line("element block header");
          const int dim = int(in.integer_at(0, "entity dimension"));
          const long long entity = in.integer_at(1, "entity tag");
          const long long type = in.integer_at(2, "element type");
          const long long n = in.integer_at(3, "number of elements in block");
          // region: the entity's physical group when it has one, else the entity
          auto ph = physical.find(std::make_pair(dim, entity));
          const int label = int(ph != physical.end() ? ph->second : entity);
          for(long long i = 0; i < n; ++i)
          {
            in.expect_line("element");
            elements.add(type, 1, label);
          }
        }
      }
      else
      {
        const long long n = in.integer_at(0, "number of elements");
        for(long long i = 0; i < n; ++i)
        {
          in.expect_line("element");
          const long long type = in.integer_at(1, "element type");
          const long long ntags = in.integer_at(2, "number of tags");
          if(ntags < 0) in.error("negative number of tags");
          // tags: physical, elementary, ...: the physical one when not 0
          long long label = 0;
          if(ntags >= 1) label = in.integer_at(3, "physical tag");
          if(label == 0 && ntags >= 2) label = in.integer_at(4, "elementary tag");
          elements.add(type, 3 + std::size_t(ntags), int(label));
        }
      }
      gmsh_expect_end(in, section);
    }
    else if(section == "$PartitionedEntities")
      in.error("partitioned .msh files are not read: save the mesh unpartitioned");
    else
      gmsh_skip_section(in, section);
  }
  if(major == 0) in.error("empty file: no $MeshFormat");
  if(!nodes_seen) in.error("no $Nodes section");
  // names belong to physical tags; they name regions only when labels are physical tags
  for(const auto& n : names3) m.region_names[n.first] = n.second;
  return m;
}

// ---------------------------------------------------------------- TetGen

inline std::string tetgen_base(const std::string& filename)
{
  for(const char* ext : {".node", ".ele", ".face"})
    if(has_extension(filename, ext)) return filename.substr(0, filename.size() - std::strlen(ext));
  return filename;
}

inline Labeled_tetrahedral_mesh_3 read_tetgen(const std::string& filename)
{
  const std::string base = tetgen_base(filename);
  Labeled_tetrahedral_mesh_3 m;
  long long first_index = 0;
  {
    std::ifstream is;
    open_mesh_file(is, base + ".node");
    Mesh_text_reader in(is, base + ".node", '#');
    in.expect_line("header: number of points, dimension, attributes, boundary markers");
    const long long n = in.integer_at(0, "number of points");
    if(n < 0) in.error("negative number of points");
    if(in.size() > 1 && in.integer_at(1, "dimension") != 3)
      in.error("dimension " + std::string(in[1]) + ": only 3D meshes are read");
    m.points.reserve(std::size_t(n));
    for(long long i = 0; i < n; ++i)
    {
      in.expect_line("point");
      const long long idx = in.integer_at(0, "point index");
      if(i == 0) first_index = idx;
      if(idx != first_index + i)
        in.error("point index " + std::to_string(idx) + ", expected " + std::to_string(first_index + i) +
                 " (TetGen numbers points consecutively)");
      m.points.push_back({{in.real_at(1, "x"), in.real_at(2, "y"), in.real_at(3, "z")}});
    }
  }
  auto vertex = [&](Mesh_text_reader& in, std::size_t i) {
    const long long v = in.integer_at(i, "point index") - first_index;
    if(v < 0) in.error("point index " + std::string(in[i]) + " is below the first index " + std::to_string(first_index));
    return std::size_t(v);
  };
  {
    std::ifstream is;
    open_mesh_file(is, base + ".ele");
    Mesh_text_reader in(is, base + ".ele", '#');
    auto fail = [&in](const std::string& s) { in.error(s); };
    in.expect_line("header: number of tetrahedra, nodes per tetrahedron, attributes");
    const long long n = in.integer_at(0, "number of tetrahedra");
    const long long per = in.size() > 1 ? in.integer_at(1, "nodes per tetrahedron") : 4;
    const long long attributes = in.size() > 2 ? in.integer_at(2, "number of attributes") : 0;
    if(per != 4 && per != 10) in.error("nodes per tetrahedron " + std::to_string(per) + " (4 or 10)");
    if(n < 0 || attributes < 0) in.error("negative count in the header");
    for(long long i = 0; i < n; ++i)
    {
      in.expect_line("tetrahedron");
      if(in.size() < std::size_t(1 + per + attributes))
        in.error("expected " + std::to_string(1 + per + attributes) + " numbers, found " + std::to_string(in.size()));
      const std::array<std::size_t, 4> v = {{vertex(in, 1), vertex(in, 2), vertex(in, 3), vertex(in, 4)}};
      check_element(v, m.points.size(), "tetrahedron", fail);
      m.tetrahedra.push_back(v);
      // the region attribute (-A) is the first attribute; none: label 0
      m.regions.push_back(attributes > 0
                            ? integral_label(in.real_at(std::size_t(1 + per), "region attribute"), "region attribute", fail)
                            : 0);
    }
  }
  std::ifstream fs(base + ".face", std::ios::in | std::ios::binary);
  if(fs) // optional: the boundary and constrained faces, with markers
  {
    Mesh_text_reader in(fs, base + ".face", '#');
    auto fail = [&in](const std::string& s) { in.error(s); };
    in.expect_line("header: number of faces, boundary marker flag");
    const long long n = in.integer_at(0, "number of faces");
    const bool markers = in.size() > 1 && in.integer_at(1, "boundary marker flag") != 0;
    for(long long i = 0; i < n; ++i)
    {
      in.expect_line("face");
      const std::array<std::size_t, 3> v = {{vertex(in, 1), vertex(in, 2), vertex(in, 3)}};
      check_element(v, m.points.size(), "face", fail);
      m.boundary_triangles.push_back(v);
      m.boundary_patches.push_back(markers ? int(in.integer_at(4, "boundary marker")) : 0);
    }
  }
  return m;
}

// ---------------------------------------------------------------- VTK (legacy and XML)

// VTK cell types: tetrahedra (linear, quadratic) give their first 4 points,
// triangles their first 3; other 3D cells are refused
inline int vtk_corners(long long type, bool& other_3d)
{
  other_3d = (type == 11 || type == 12 || type == 13 || type == 14 || type == 25 || type == 26 ||
              type == 27 || type == 29 || type == 32 || type == 33 || type == 42 || type == 72 ||
              type == 73 || type == 74 || type == 75 || type == 79 || type == 80 || type == 81);
  if(type == 10 || type == 24 || type == 71) return 4;
  if(type == 5 || type == 22 || type == 69) return 3;
  return 0;
}

// which cell array holds the region label: a known name first, else the first
// array with one component
inline int vtk_label_priority(const std::string& name)
{
  static const char* known[] = {"MeshDomain", "medit:ref", "gmsh:physical", "CellEntityIds", "cell_scalars",
                                "region", "regions", "subdomain", "subdomain_index", "material",
                                "MaterialIds", "gmsh:geometrical", "label", "labels"};
  for(std::size_t i = 0; i < sizeof(known) / sizeof(known[0]); ++i)
    if(iequals(name, known[i])) return int(i);
  return 1000;
}

// cells of a VTK file into tets and boundary triangles
template <class Fail>
void vtk_cells_to_mesh(const std::vector<long long>& connectivity, const std::vector<long long>& offsets,
                       const std::vector<long long>& types, const std::vector<double>* labels,
                       Labeled_tetrahedral_mesh_3& m, Fail fail)
{
  if(types.size() + 1 != offsets.size()) fail("cell offsets and types disagree in number");
  for(std::size_t c = 0; c < types.size(); ++c)
  {
    bool other_3d = false;
    const int corners = vtk_corners(types[c], other_3d);
    if(other_3d)
      fail("cell " + std::to_string(c) + " has VTK type " + std::to_string(types[c]) +
           ", a 3D cell other than a tetrahedron: only tetrahedral meshes are read");
    if(corners == 0) continue;
    const long long b = offsets[c], e = offsets[c + 1];
    if(b < 0 || e < b + corners || e > (long long)connectivity.size())
      fail("cell " + std::to_string(c) + " has bad offsets " + std::to_string(b) + ".." + std::to_string(e));
    std::array<std::size_t, 4> v = {{0, 0, 0, 0}};
    for(int k = 0; k < corners; ++k)
    {
      if(connectivity[std::size_t(b + k)] < 0) fail("cell " + std::to_string(c) + " has a negative point index");
      v[std::size_t(k)] = std::size_t(connectivity[std::size_t(b + k)]);
    }
    auto fail_cell = [&](const std::string& s) { fail("cell " + std::to_string(c) + ": " + s); };
    const int label = labels ? integral_label((*labels)[c], "label", fail_cell) : 0;
    if(corners == 4)
    {
      check_element(v, m.points.size(), "tetrahedron", fail_cell);
      m.tetrahedra.push_back(v);
      m.regions.push_back(label);
    }
    else
    {
      const std::array<std::size_t, 3> t = {{v[0], v[1], v[2]}};
      check_element(t, m.points.size(), "triangle", fail_cell);
      m.boundary_triangles.push_back(t);
      m.boundary_patches.push_back(label);
    }
  }
}

inline Labeled_tetrahedral_mesh_3 read_vtk_legacy(std::istream& is, const std::string& name)
{
  Mesh_text_reader in(is, name, '\0');
  Labeled_tetrahedral_mesh_3 m;
  auto fail = [&in](const std::string& s) { in.error(s); };
  if(!in.read_line() || in.line().rfind("# vtk DataFile", 0) != 0) in.error("not a legacy VTK file (no '# vtk DataFile' line)");
  double version = 0;
  {
    const std::size_t p = in.line().find("Version");
    if(p != std::string::npos) version = std::atof(in.line().c_str() + p + 7);
  }
  if(!in.read_line()) in.error("unexpected end of file: no title line");
  in.expect_line("ASCII or BINARY");
  if(!iequals(in[0], "ASCII")) in.error("binary legacy VTK is not read: save as ASCII");
  in.expect_line("DATASET");
  if(!iequals(in[0], "DATASET") || in.size() < 2 || !iequals(in[1], "UNSTRUCTURED_GRID"))
    in.error("expected DATASET UNSTRUCTURED_GRID, found " + printable(in.line()));
  in.skip_rest_of_line();

  std::vector<long long> connectivity, offsets(1, 0), types;
  std::vector<double> best_labels;
  int best_priority = 1001;
  std::size_t number_of_cells = 0;
  bool in_cell_data = false;
  auto read_values = [&](std::size_t n, const std::string& what) {
    std::vector<double> v(n);
    for(std::size_t i = 0; i < n; ++i) v[i] = in.real(what);
    return v;
  };
  auto consider = [&](const std::string& array, std::size_t components, std::vector<double>&& values) {
    const int p = vtk_label_priority(array);
    if(in_cell_data && components == 1 && p < best_priority)
    {
      best_priority = p;
      best_labels = std::move(values);
    }
  };
  std::size_t data_size = 0; // values per attribute in the current POINT_DATA / CELL_DATA block
  std::string_view t;
  while(in.next_token(t))
  {
    const std::string k(t);
    if(iequals(k, "POINTS"))
    {
      const std::size_t n = in.count("number of points");
      in.token("point data type");
      m.points.resize(n);
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t c = 0; c < 3; ++c) m.points[i][c] = in.real("point coordinate");
    }
    else if(iequals(k, "CELLS"))
    {
      const std::size_t n = in.count("number of cells"), size = in.count("size of the cell list");
      if(version >= 5.)
      {
        // 5.x: CELLS n_offsets n_connectivity, then OFFSETS and CONNECTIVITY arrays
        if(!iequals(in.token("OFFSETS"), "OFFSETS")) in.error("expected OFFSETS");
        in.token("offsets type");
        offsets.clear();
        for(std::size_t i = 0; i < n; ++i) offsets.push_back(in.integer("offset"));
        if(!iequals(in.token("CONNECTIVITY"), "CONNECTIVITY")) in.error("expected CONNECTIVITY");
        in.token("connectivity type");
        for(std::size_t i = 0; i < size; ++i) connectivity.push_back(in.integer("point index"));
        number_of_cells = n == 0 ? 0 : n - 1;
      }
      else
      {
        for(std::size_t c = 0; c < n; ++c)
        {
          const std::size_t k2 = in.count("number of points of a cell");
          for(std::size_t j = 0; j < k2; ++j) connectivity.push_back(in.integer("point index"));
          offsets.push_back((long long)connectivity.size());
        }
        if(connectivity.size() + n != size) in.error("the cell list size " + std::to_string(size) + " does not match the cells");
        number_of_cells = n;
      }
    }
    else if(iequals(k, "CELL_TYPES"))
    {
      const std::size_t n = in.count("number of cell types");
      for(std::size_t i = 0; i < n; ++i) types.push_back(in.integer("cell type"));
    }
    else if(iequals(k, "CELL_DATA") || iequals(k, "POINT_DATA"))
    {
      in_cell_data = iequals(k, "CELL_DATA");
      data_size = in.count("number of values");
    }
    else if(iequals(k, "SCALARS"))
    {
      // SCALARS name type [components] on one line, then LOOKUP_TABLE name
      const std::string array(in.token("array name"));
      in.token("data type");
      std::size_t components = 1;
      if(in.remaining_on_line() > 0) components = in.count("number of components");
      std::string_view next = in.token("LOOKUP_TABLE or values");
      std::vector<double> v;
      if(iequals(next, "LOOKUP_TABLE"))
      {
        in.token("lookup table name");
        v = read_values(data_size * components, "value of " + array);
      }
      else if(data_size * components > 0)
      {
        v.push_back(in.to_double(next, "value of " + array));
        std::vector<double> rest = read_values(data_size * components - 1, "value of " + array);
        v.insert(v.end(), rest.begin(), rest.end());
      }
      consider(array, components, std::move(v));
    }
    else if(iequals(k, "FIELD"))
    {
      in.token("field name");
      const std::size_t arrays = in.count("number of arrays");
      for(std::size_t a = 0; a < arrays; ++a)
      {
        const std::string array(in.token("array name"));
        const std::size_t components = in.count("number of components");
        const std::size_t tuples = in.count("number of tuples");
        in.token("data type");
        consider(array, components, read_values(components * tuples, "value of " + array));
      }
    }
    else if(iequals(k, "VECTORS") || iequals(k, "NORMALS") || iequals(k, "TENSORS"))
    {
      in.token("array name");
      in.token("data type");
      read_values(data_size * (iequals(k, "TENSORS") ? 9 : 3), "value");
    }
    else if(iequals(k, "LOOKUP_TABLE"))
    {
      in.token("table name");
      read_values(4 * in.count("table size"), "table value");
    }
    else if(iequals(k, "METADATA"))
    {
      // ends at a blank line
      while(in.read_line() && in.size() > 0) {}
    }
    else
      in.error("unexpected " + printable(k) + " (read: POINTS, CELLS, CELL_TYPES, CELL_DATA, POINT_DATA)");
  }
  if(types.size() != number_of_cells) in.error("CELL_TYPES has " + std::to_string(types.size()) + " entries for " +
                                               std::to_string(number_of_cells) + " cells");
  if(best_priority <= 1000 && best_labels.size() != number_of_cells)
    in.error("the label array has " + std::to_string(best_labels.size()) + " values for " +
             std::to_string(number_of_cells) + " cells");
  vtk_cells_to_mesh(connectivity, offsets, types, best_priority <= 1000 ? &best_labels : nullptr, m, fail);
  return m;
}

// a minimal XML scan of VTU files: ascii, inline base64 ("binary") and raw appended data
class Vtu_file
{
public:
  Vtu_file(const std::string& text, const std::string& name) : s_(text), name_(name) {}

  [[noreturn]] void error(std::size_t pos, const std::string& what) const
  {
    const std::size_t line = 1 + std::size_t(std::count(s_.begin(), s_.begin() + std::ptrdiff_t((std::min)(pos, s_.size())), '\n'));
    throw Tet_mesh_read_error(name_ + ":" + std::to_string(line) + ": " + what);
  }

  // value of attribute `a` in the tag starting at `tag` ("" if absent)
  std::string attribute(std::size_t tag, const std::string& a) const
  {
    const std::size_t end = tag_end(tag);
    std::size_t p = tag;
    while(true)
    {
      p = s_.find(a, p);
      if(p == std::string::npos || p >= end) return std::string();
      const bool starts = std::isspace(static_cast<unsigned char>(s_[p - 1]));
      std::size_t q = p + a.size();
      while(q < end && std::isspace(static_cast<unsigned char>(s_[q]))) ++q;
      if(starts && q < end && s_[q] == '=')
      {
        ++q;
        while(q < end && std::isspace(static_cast<unsigned char>(s_[q]))) ++q;
        const char quote = s_[q];
        if(quote != '"' && quote != '\'') error(tag, "attribute " + a + " without quotes");
        const std::size_t r = s_.find(quote, q + 1);
        if(r == std::string::npos || r > end) error(tag, "unterminated attribute " + a);
        return s_.substr(q + 1, r - q - 1);
      }
      p += a.size();
    }
  }

  std::size_t tag_end(std::size_t tag) const
  {
    const std::size_t e = s_.find('>', tag);
    if(e == std::string::npos) error(tag, "unterminated tag");
    return e;
  }

  // first `<name` (followed by a space, '>' or '/') at or after `from`, before `to`
  std::size_t find_tag(const std::string& name, std::size_t from, std::size_t to = std::string::npos) const
  {
    std::size_t p = from;
    while(true)
    {
      p = s_.find("<" + name, p);
      if(p == std::string::npos || p >= to) return std::string::npos;
      const char c = s_[p + 1 + name.size()];
      if(std::isspace(static_cast<unsigned char>(c)) || c == '>' || c == '/') return p;
      ++p;
    }
  }

  struct Array
  {
    std::size_t tag = std::string::npos;
    std::string name, type, format;
    std::size_t components = 1;
  };

  std::vector<Array> arrays(std::size_t from, std::size_t to) const
  {
    std::vector<Array> r;
    for(std::size_t p = find_tag("DataArray", from, to); p != std::string::npos; p = find_tag("DataArray", p + 1, to))
    {
      Array a;
      a.tag = p;
      a.name = attribute(p, "Name");
      a.type = attribute(p, "type");
      a.format = attribute(p, "format");
      const std::string nc = attribute(p, "NumberOfComponents");
      if(!nc.empty()) a.components = std::size_t(std::max(1LL, parse_integer(nc, "NumberOfComponents", [&](const std::string& m) { error(p, m); })));
      r.push_back(a);
    }
    return r;
  }

  // values of an array as doubles (labels, coordinates) or integers (indices)
  template <class T>
  std::vector<T> values(const Array& a) const
  {
    auto fail = [&](const std::string& m) { error(a.tag, "DataArray " + printable(a.name) + ": " + m); };
    std::vector<T> r;
    if(a.format == "ascii" || a.format.empty())
    {
      const std::size_t b = tag_end(a.tag) + 1;
      const std::size_t e = s_.find("</DataArray>", b);
      if(e == std::string::npos) fail("no </DataArray>");
      std::size_t p = b;
      while(true)
      {
        while(p < e && std::isspace(static_cast<unsigned char>(s_[p]))) ++p;
        if(p >= e) break;
        std::size_t q = p;
        while(q < e && !std::isspace(static_cast<unsigned char>(s_[q]))) ++q;
        const std::string_view tok(s_.data() + p, q - p);
        auto here = [&](const std::string& m) { error(p, "DataArray " + printable(a.name) + ": " + m); };
        if constexpr(std::is_floating_point<T>::value) r.push_back(parse_double(tok, "value", here));
        else r.push_back(T(parse_integer(tok, "value", here)));
        p = q;
      }
      return r;
    }
    std::string bytes;
    if(a.format == "binary")
    {
      const std::size_t b = tag_end(a.tag) + 1;
      const std::size_t e = s_.find("</DataArray>", b);
      if(e == std::string::npos) fail("no </DataArray>");
      bytes = decode_base64(b, e);
      const std::size_t h = header_bytes();
      if(bytes.size() < h) fail("truncated base64 data");
      const std::uint64_t n = read_unsigned(bytes.data(), h);
      if(n > bytes.size() - h) fail("base64 data shorter than its header says");
      bytes = bytes.substr(h, std::size_t(n));
    }
    else if(a.format == "appended")
    {
      const std::size_t base = appended_start(a.tag);
      const std::string off = attribute(a.tag, "offset");
      if(off.empty()) fail("appended array without offset");
      const std::size_t o = std::size_t(parse_integer(off, "offset", fail));
      const std::size_t h = header_bytes();
      if(base + o + h > s_.size()) fail("offset " + off + " is beyond the end of the file");
      const std::uint64_t n = read_unsigned(s_.data() + base + o, h);
      if(n > s_.size() - (base + o + h)) fail("appended data shorter than its header says (truncated file?)");
      bytes = s_.substr(base + o + h, std::size_t(n));
    }
    else
      fail("format " + printable(a.format) + " is not read (ascii, binary, appended)");
    decode(bytes, a, r, fail);
    return r;
  }

  // checks the file header: unstructured grid, little endian, no compression
  void check_header()
  {
    const std::size_t v = find_tag("VTKFile", 0);
    if(v == std::string::npos) error(0, "not a VTK XML file (no <VTKFile>)");
    if(attribute(v, "type") != "UnstructuredGrid")
      error(v, "VTKFile type " + printable(attribute(v, "type")) + ": only UnstructuredGrid (.vtu) is read");
    if(!attribute(v, "compressor").empty())
      error(v, "compressed data (" + attribute(v, "compressor") + ") is not read: save without compression");
    const std::string order = attribute(v, "byte_order");
    if(order == "BigEndian") error(v, "big-endian binary data is not read");
    const std::string h = attribute(v, "header_type");
    header_ = (h == "UInt64") ? 8 : 4;
  }

private:
  std::size_t header_bytes() const { return header_; }

  static std::uint64_t read_unsigned(const char* p, std::size_t n)
  {
    std::uint64_t v = 0;
    for(std::size_t i = 0; i < n; ++i) v |= std::uint64_t(static_cast<unsigned char>(p[i])) << (8 * i);
    return v;
  }

  std::size_t appended_start(std::size_t at) const
  {
    const std::size_t t = find_tag("AppendedData", 0);
    if(t == std::string::npos) error(at, "appended array but no <AppendedData>");
    if(attribute(t, "encoding") != "raw")
      error(t, "AppendedData encoding " + printable(attribute(t, "encoding")) + " is not read (raw only)");
    const std::size_t u = s_.find('_', tag_end(t));
    if(u == std::string::npos) error(t, "AppendedData without the '_' marker");
    return u + 1;
  }

  // base64 in groups of 4 characters; '=' padding may also end an inner block
  // (VTK encodes the header and the data separately)
  std::string decode_base64(std::size_t b, std::size_t e) const
  {
    auto value = [](char c) -> int {
      if(c >= 'A' && c <= 'Z') return c - 'A';
      if(c >= 'a' && c <= 'z') return c - 'a' + 26;
      if(c >= '0' && c <= '9') return c - '0' + 52;
      if(c == '+') return 62;
      if(c == '/') return 63;
      return -1;
    };
    std::string out;
    int group[4];
    int n = 0, pad = 0;
    for(std::size_t p = b; p < e; ++p)
    {
      const char c = s_[p];
      if(std::isspace(static_cast<unsigned char>(c))) continue;
      if(c == '=') { group[n++] = 0; ++pad; }
      else
      {
        const int v = value(c);
        if(v < 0) error(p, "invalid base64 character");
        group[n++] = v;
      }
      if(n == 4)
      {
        const unsigned triple = (unsigned(group[0]) << 18) | (unsigned(group[1]) << 12) | (unsigned(group[2]) << 6) | unsigned(group[3]);
        out += char((triple >> 16) & 255);
        if(pad < 2) out += char((triple >> 8) & 255);
        if(pad < 1) out += char(triple & 255);
        n = 0;
        pad = 0;
      }
    }
    return out;
  }

  template <class T, class Fail>
  static void decode(const std::string& bytes, const Array& a, std::vector<T>& r, Fail fail)
  {
    auto run = [&](auto sample) {
      typedef decltype(sample) S;
      if(bytes.size() % sizeof(S) != 0) fail("byte count is not a multiple of the type size");
      const std::size_t n = bytes.size() / sizeof(S);
      r.reserve(n);
      for(std::size_t i = 0; i < n; ++i)
      {
        S v;
        std::memcpy(&v, bytes.data() + i * sizeof(S), sizeof(S));
        if constexpr(std::is_floating_point<S>::value)
          if(!std::isfinite(v)) fail("value " + std::to_string(i) + " is not finite");
        r.push_back(T(v));
      }
    };
    const std::string& t = a.type;
    if(t == "Float64") run(double());
    else if(t == "Float32") run(float());
    else if(t == "Int8") run(std::int8_t());
    else if(t == "UInt8") run(std::uint8_t());
    else if(t == "Int16") run(std::int16_t());
    else if(t == "UInt16") run(std::uint16_t());
    else if(t == "Int32") run(std::int32_t());
    else if(t == "UInt32") run(std::uint32_t());
    else if(t == "Int64") run(std::int64_t());
    else if(t == "UInt64") run(std::uint64_t());
    else fail("data type " + printable(t) + " is not read");
  }

  const std::string& s_;
  std::string name_;
  std::size_t header_ = 4;
};

inline Labeled_tetrahedral_mesh_3 read_vtu(const std::string& text, const std::string& name)
{
  Vtu_file f(text, name);
  f.check_header();
  Labeled_tetrahedral_mesh_3 m;
  const std::size_t piece = f.find_tag("Piece", 0);
  if(piece == std::string::npos) f.error(0, "no <Piece>");
  if(f.find_tag("Piece", piece + 1) != std::string::npos)
    f.error(f.find_tag("Piece", piece + 1), "several <Piece> elements: only one-piece files are read");
  auto fail_at = [&](std::size_t p) { return [&f, p](const std::string& s) { f.error(p, s); }; };
  const std::size_t np = std::size_t(parse_integer(f.attribute(piece, "NumberOfPoints"), "NumberOfPoints", fail_at(piece)));
  const std::size_t nc = std::size_t(parse_integer(f.attribute(piece, "NumberOfCells"), "NumberOfCells", fail_at(piece)));

  auto section = [&](const std::string& tag) {
    const std::size_t b = f.find_tag(tag, piece);
    if(b == std::string::npos) return std::make_pair(b, b);
    const std::size_t e = text.find("</" + tag + ">", b);
    return std::make_pair(b, e == std::string::npos ? f.tag_end(b) : e);
  };
  const auto points = section("Points");
  if(points.first == std::string::npos) f.error(piece, "no <Points>");
  const std::vector<Vtu_file::Array> pa = f.arrays(points.first, points.second);
  if(pa.empty()) f.error(points.first, "<Points> without a DataArray");
  const std::vector<double> xyz = f.values<double>(pa[0]);
  if(xyz.size() != 3 * np)
    f.error(pa[0].tag, "Points: " + std::to_string(xyz.size()) + " coordinates for " + std::to_string(np) + " points");
  m.points.resize(np);
  for(std::size_t i = 0; i < np; ++i)
    for(std::size_t c = 0; c < 3; ++c) m.points[i][c] = xyz[3 * i + c];

  const auto cells = section("Cells");
  if(cells.first == std::string::npos) f.error(piece, "no <Cells>");
  std::vector<long long> connectivity, offsets, types;
  bool has[3] = {false, false, false};
  for(const Vtu_file::Array& a : f.arrays(cells.first, cells.second))
  {
    if(a.name == "connectivity") { connectivity = f.values<long long>(a); has[0] = true; }
    else if(a.name == "offsets") { offsets = f.values<long long>(a); has[1] = true; }
    else if(a.name == "types") { types = f.values<long long>(a); has[2] = true; }
  }
  if(!has[0] || !has[1] || !has[2]) f.error(cells.first, "<Cells> needs the arrays connectivity, offsets and types");
  if(offsets.size() != nc || types.size() != nc)
    f.error(cells.first, "<Cells>: " + std::to_string(offsets.size()) + " offsets and " + std::to_string(types.size()) +
                           " types for " + std::to_string(nc) + " cells");
  offsets.insert(offsets.begin(), 0); // VTU offsets are the ends

  std::vector<double> labels;
  bool labelled = false;
  const auto cell_data = section("CellData");
  if(cell_data.first != std::string::npos)
  {
    int best = 1001;
    const Vtu_file::Array* chosen = nullptr;
    const std::vector<Vtu_file::Array> ca = f.arrays(cell_data.first, cell_data.second);
    for(const Vtu_file::Array& a : ca)
      if(a.components == 1 && vtk_label_priority(a.name) < best)
      {
        best = vtk_label_priority(a.name);
        chosen = &a;
      }
    if(chosen)
    {
      labels = f.values<double>(*chosen);
      if(labels.size() != nc)
        f.error(chosen->tag, "cell array " + printable(chosen->name) + " has " + std::to_string(labels.size()) +
                               " values for " + std::to_string(nc) + " cells");
      labelled = true;
    }
  }
  vtk_cells_to_mesh(connectivity, offsets, types, labelled ? &labels : nullptr, m, fail_at(cells.first));
  return m;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

reads a Medit `.mesh` file (ASCII): `Vertices`, `Tetrahedra` (the reference of
a tetrahedron is its region) and `Triangles` (the reference is the patch);
other sections of surface meshes (`Edges`, `Corners`, `Ridges`, `Required*`,
normals) are skipped. Hexahedra, prisms or pyramids are an error.

\throws Tet_mesh_read_error with file and line
*/
inline Labeled_tetrahedral_mesh_3 read_medit_tet_mesh(const std::string& filename)
{
  return internal::read_file(filename, internal::read_medit);
}

/*!
\ingroup PkgBubbleMesh3IO

reads a Gmsh `.msh` file, ASCII format 4.1 or 2.2. Tetrahedra (any order:
the corner nodes are used) are the mesh, triangles the boundary triangles.
The label of an element is its physical tag: in 4.1 the first physical tag of
its entity, or the entity tag when the entity has none; in 2.2 the first tag,
or the second (elementary) when the first is 0. 3D physical names name the regions.
Other 3D element types are an error; points and lines are skipped.

\throws Tet_mesh_read_error with file and line
*/
inline Labeled_tetrahedral_mesh_3 read_gmsh_tet_mesh(const std::string& filename)
{
  return internal::read_file(filename, internal::read_gmsh);
}

/*!
\ingroup PkgBubbleMesh3IO

reads a TetGen mesh: `B.node` and `B.ele`, and `B.face` when it exists, where
`filename` is `B.node`, `B.ele`, `B.face` or `B`. The region of a tetrahedron
is its first attribute (TetGen's `-A`), 0 when the file has none; the boundary
marker of a face is its patch. Indices may start at 0 or 1 (as the .node file does).

\throws Tet_mesh_read_error with file and line
*/
inline Labeled_tetrahedral_mesh_3 read_tetgen_tet_mesh(const std::string& filename)
{
  return internal::read_tetgen(filename);
}

/*!
\ingroup PkgBubbleMesh3IO

reads a VTK XML unstructured grid (`.vtu`) with one piece. Data arrays may be
`ascii`, `binary` (inline base64) or `appended` with raw encoding (what
`CGAL::IO::output_to_vtu()` writes by default); compressed data is an error.
Cells of type tetrahedron (10, and the corners of 24) are the mesh, triangles
(5, 22) the boundary triangles. The label is the one-component cell array named
`MeshDomain`, `medit:ref`, `gmsh:physical`, `CellEntityIds`, `cell_scalars`,
`region`, `subdomain`, `material`, ... (first in that order), else the first
one-component cell array, else 0.

\throws Tet_mesh_read_error with file and line
*/
inline Labeled_tetrahedral_mesh_3 read_vtu_tet_mesh(const std::string& filename)
{
  std::ifstream is;
  internal::open_mesh_file(is, filename);
  std::ostringstream ss;
  ss << is.rdbuf();
  if(is.bad()) throw Tet_mesh_read_error(filename + ": read error");
  const std::string text = ss.str();
  return internal::read_vtu(text, filename);
}

/*!
\ingroup PkgBubbleMesh3IO

reads a legacy VTK file (`.vtk`, ASCII, `DATASET UNSTRUCTURED_GRID`, versions
2.0 to 5.1), as Gmsh and TetGen (`-k`) write it. Cells and labels as in `read_vtu_tet_mesh()`.

\throws Tet_mesh_read_error with file and line
*/
inline Labeled_tetrahedral_mesh_3 read_vtk_tet_mesh(const std::string& filename)
{
  return internal::read_file(filename, internal::read_vtk_legacy);
}

/*!
\ingroup PkgBubbleMesh3IO

reads a labelled tetrahedral mesh, choosing the reader by the file extension:
`.mesh` (Medit), `.msh` (Gmsh), `.node`/`.ele` (TetGen), `.vtu`, `.vtk`.

\throws Tet_mesh_read_error on an unknown extension, a missing file, or a bad file (with file and line)
*/
inline Labeled_tetrahedral_mesh_3 read_tet_mesh(const std::string& filename)
{
  using internal::has_extension;
  if(has_extension(filename, ".mesh")) return read_medit_tet_mesh(filename);
  if(has_extension(filename, ".msh")) return read_gmsh_tet_mesh(filename);
  if(has_extension(filename, ".node") || has_extension(filename, ".ele")) return read_tetgen_tet_mesh(filename);
  if(has_extension(filename, ".vtu")) return read_vtu_tet_mesh(filename);
  if(has_extension(filename, ".vtk")) return read_vtk_tet_mesh(filename);
  if(has_extension(filename, ".meshb"))
    throw Tet_mesh_read_error(filename + ": binary Medit (.meshb) is not read: save as .mesh");
  throw Tet_mesh_read_error(filename + ": unknown mesh format (read: .mesh, .msh, .node/.ele, .vtu, .vtk)");
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_READ_TET_MESH_H
