// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the mesh writers: a hand-filled C3T3 (a 2x1x1 box, two regions,
// an interface, boundary patches, a fault inside a region) is written in
// every format and read back by small parsers here; each read-back must give
// the same counts and labels per element, the names, region volumes and
// patch areas, positive tets and triangle normals pointing into the
// positive region. The .mesh is also read by CGAL. Usage:
//   test_writers [OUTPUT_DIR]   (default BUBBLE_MESH_3_BINARY_DIR/test_writers_out)
// test_writers_consumers.sh runs it with its own folder and hands the files
// (and box_expected.json) to Gmsh, VTK and CalculiX.

#include <CGAL/Bubble_mesh_3/IO/write_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/File_medit.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h> // defines what read_MEDIT calls
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <array>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K> Model;
namespace BIO = CGAL::Bubble_mesh_3::IO;

// A pure-type domain: Mesh_triangulation_3 only reads these typedefs.
struct Label_domain
{
  typedef K R;
  typedef int Subdomain_index;
  typedef int Surface_patch_index;
  typedef int Index;
};
typedef CGAL::Mesh_triangulation_3<Label_domain, K>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;

typedef std::array<double, 3> P3;

// ---------------------------------------------------------------------------
// the box: [0,2]x[0,1]x[0,1] on a lattice of step 1/4; region 1 is x < 1,
// region 2 is x > 1
// ---------------------------------------------------------------------------

const std::string long_fault_name =
  "Fault F1 that ends inside Layer 1, with a name much longer than the eighty characters Abaqus allows";

enum Patch_index { WEST, EAST, SIDES_1, SIDES_2, CONTACT, FAULT, UNUSED, NUMBER_OF_PATCHES };

Model make_model()
{
  Model model;
  model.add_region("Layer 1 (sand)");
  model.add_region("2nd layer");
  model.add_patch("west", 1, 0); // normal +x, into region 1: the opposite of the usual outward
  model.add_patch("east", 0, 2);
  model.add_patch("sides", 0, 1);
  model.add_patch("sides", 0, 2); // same name: formats that look names up must tell them apart
  model.add_patch("contact \"A\"", 2, 1);
  model.add_patch(long_fault_name, 1, 1);
  model.add_patch("unused", 0, 1); // no facet: written nowhere
  // only the fault's triangles are needed: its orientation comes from them (normal +z)
  const std::size_t a = model.add_point(K::Point_3(0, 0, 0.5)), b = model.add_point(K::Point_3(0.5, 0, 0.5)),
                    c = model.add_point(K::Point_3(0.5, 1, 0.5)), d = model.add_point(K::Point_3(0, 1, 0.5));
  model.add_triangle(a, b, c, FAULT);
  model.add_triangle(a, c, d, FAULT);
  return model;
}

// the patch label (index + 1) of a facet, or 0
int classify_facet(const std::array<P3, 3>& p)
{
  auto all = [&](int d, double v) { return p[0][d] == v && p[1][d] == v && p[2][d] == v; };
  const double max_x = (std::max)({p[0][0], p[1][0], p[2][0]});
  if(all(0, 0.)) return WEST + 1;
  if(all(0, 2.)) return EAST + 1;
  if(all(0, 1.)) return CONTACT + 1;
  if(all(1, 0.) || all(1, 1.) || all(2, 0.) || all(2, 1.)) return (max_x <= 1 ? SIDES_1 : SIDES_2) + 1;
  if(all(2, 0.5) && max_x <= 0.5) return FAULT + 1;
  return 0;
}

P3 to_p3(const Tr::Bare_point& p) { return {{p.x(), p.y(), p.z()}}; }

void fill_c3t3(C3T3& c3t3)
{
  Tr& tr = c3t3.triangulation();
  std::vector<Tr::Point> points;
  for(int i = 0; i <= 8; ++i)
    for(int j = 0; j <= 4; ++j)
      for(int k = 0; k <= 4; ++k) points.push_back(Tr::Point(Tr::Bare_point(0.25 * i, 0.25 * j, 0.25 * k)));
  tr.insert(points.begin(), points.end());
  auto cp = tr.geom_traits().construct_point_3_object();
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
  {
    double x = 0;
    for(int i = 0; i < 4; ++i) x += cp(c->vertex(i)->point()).x() / 4;
    c3t3.add_to_complex(c, x < 1 ? 1 : 2);
  }
  for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f)
  {
    std::array<P3, 3> p;
    for(int i = 0; i < 3; ++i) p[i] = to_p3(cp(f->first->vertex((f->second + 1 + i) % 4)->point()));
    const int label = classify_facet(p);
    if(label != 0) c3t3.add_to_complex(*f, label);
  }
}

// ---------------------------------------------------------------------------
// what every read-back must give
// ---------------------------------------------------------------------------

struct Expected
{
  std::size_t points = 0;
  std::map<int, std::size_t> tets_per_region, triangles_per_label;
  std::map<int, double> volume_per_region{{1, 1.0}, {2, 1.0}};
  std::map<int, double> area_per_label{{WEST + 1, 1.0},    {EAST + 1, 1.0},    {SIDES_1 + 1, 4.0},
                                       {SIDES_2 + 1, 4.0}, {CONTACT + 1, 1.0}, {FAULT + 1, 0.5}};
  std::size_t tets() const { return sum(tets_per_region); }
  std::size_t triangles() const { return sum(triangles_per_label); }
  static std::size_t sum(const std::map<int, std::size_t>& m)
  {
    std::size_t s = 0;
    for(const auto& e : m) s += e.second;
    return s;
  }
};

Expected count_c3t3(const C3T3& c3t3)
{
  Expected e;
  std::set<Tr::Vertex_handle> used;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    ++e.tets_per_region[c3t3.subdomain_index(c)];
    for(int i = 0; i < 4; ++i) used.insert(c->vertex(i));
  }
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    ++e.triangles_per_label[c3t3.surface_patch_index(*f)];
  e.points = used.size();
  return e;
}

// the direction a triangle of patch `label` at `q` must face: into the positive region
P3 expected_normal(int label, const P3& q)
{
  switch(label - 1)
  {
  case WEST: case EAST: case CONTACT: return {{1, 0, 0}};
  case FAULT: return {{0, 0, 1}};
  default: // outward on the sides
    if(q[1] == 0) return {{0, -1, 0}};
    if(q[1] == 1) return {{0, 1, 0}};
    if(q[2] == 0) return {{0, 0, -1}};
    return {{0, 0, 1}};
  }
}

P3 sub(const P3& a, const P3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
P3 cross(const P3& a, const P3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const P3& a) { return std::sqrt(dot(a, a)); }

// a mesh as read back from a file, numbers 0-based
struct Read_mesh
{
  std::vector<P3> points;
  std::vector<std::array<std::size_t, 4> > tets;
  std::vector<int> tet_regions;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<int> triangle_labels;
};

void check_read_mesh(const std::string& format, const Read_mesh& m, const Expected& e)
{
  std::cout << format << ": " << m.points.size() << " points, " << m.tets.size() << " tets, "
            << m.triangles.size() << " triangles\n";
  assert(m.points.size() == e.points);
  assert(m.tets.size() == e.tets() && m.tet_regions.size() == m.tets.size());
  assert(m.triangles.size() == e.triangles() && m.triangle_labels.size() == m.triangles.size());

  std::map<int, std::size_t> tets_per_region, triangles_per_label;
  std::map<int, double> volume, area;
  for(std::size_t t = 0; t < m.tets.size(); ++t)
  {
    for(std::size_t v : m.tets[t]) assert(v < m.points.size());
    const P3& p0 = m.points[m.tets[t][0]];
    const double vol =
      dot(sub(m.points[m.tets[t][3]], p0), cross(sub(m.points[m.tets[t][1]], p0), sub(m.points[m.tets[t][2]], p0))) / 6;
    assert(vol > 0); // positively oriented
    ++tets_per_region[m.tet_regions[t]];
    volume[m.tet_regions[t]] += vol;
  }
  std::size_t facing = 0;
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    for(std::size_t v : m.triangles[t]) assert(v < m.points.size());
    const P3 &a = m.points[m.triangles[t][0]], &b = m.points[m.triangles[t][1]], &c = m.points[m.triangles[t][2]];
    const P3 n = cross(sub(b, a), sub(c, a));
    const int label = m.triangle_labels[t];
    const P3 centroid{{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3}};
    // a triangle must lie on its patch, and face its positive region
    std::array<P3, 3> abc{{a, b, c}};
    assert(classify_facet(abc) == label);
    if(dot(n, expected_normal(label, centroid)) > 0) ++facing;
    ++triangles_per_label[label];
    area[label] += norm(n) / 2;
  }
  std::cout << "  per region (tets, volume):";
  for(const auto& r : e.tets_per_region)
  {
    std::cout << " " << r.first << ":(" << tets_per_region[r.first] << ", " << volume[r.first] << ")";
    assert(tets_per_region[r.first] == r.second);
    assert(std::abs(volume[r.first] - e.volume_per_region.at(r.first)) < 1e-12);
  }
  std::cout << "\n  per patch label (triangles, area):";
  for(const auto& l : e.triangles_per_label)
  {
    std::cout << " " << l.first << ":(" << triangles_per_label[l.first] << ", " << area[l.first] << ")";
    assert(triangles_per_label[l.first] == l.second);
    assert(std::abs(area[l.first] - e.area_per_label.at(l.first)) < 1e-12);
  }
  std::cout << "\n  triangles facing their positive region: " << facing << " of " << m.triangles.size() << "\n";
  assert(facing == m.triangles.size());
}

// ---------------------------------------------------------------------------
// small readers, one per format
// ---------------------------------------------------------------------------

std::string slurp(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  assert(in);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// the text between the first `"` after `from` and the next `"`
std::string quoted_name(const std::string& line, std::size_t from = 0)
{
  const std::size_t a = line.find('"', from), b = line.find('"', a + 1);
  assert(a != std::string::npos && b != std::string::npos);
  return line.substr(a + 1, b - a - 1);
}

typedef std::map<int, std::string> Names;

Read_mesh read_medit(const std::string& file, Names& regions, Names& patches)
{
  std::ifstream in(file);
  assert(in);
  Read_mesh m;
  std::string word;
  int version = 0, dim = 0;
  in >> word >> version;
  assert(word == "MeshVersionFormatted" && version == 2);
  in >> word >> dim;
  assert(word == "Dimension" && dim == 3);
  std::size_t n = 0;
  while(in >> word && word != "End")
  {
    in >> n;
    if(word == "Vertices")
      for(std::size_t i = 0; i < n; ++i)
      {
        P3 p;
        int ref;
        in >> p[0] >> p[1] >> p[2] >> ref;
        m.points.push_back(p);
      }
    else if(word == "Triangles")
      for(std::size_t i = 0; i < n; ++i)
      {
        std::array<std::size_t, 3> t;
        int ref;
        in >> t[0] >> t[1] >> t[2] >> ref;
        for(auto& v : t) --v;
        m.triangles.push_back(t);
        m.triangle_labels.push_back(ref);
      }
    else if(word == "Tetrahedra")
      for(std::size_t i = 0; i < n; ++i)
      {
        std::array<std::size_t, 4> t;
        int ref;
        in >> t[0] >> t[1] >> t[2] >> t[3] >> ref;
        for(auto& v : t) --v;
        m.tets.push_back(t);
        m.tet_regions.push_back(ref);
      }
    else
      assert(false);
  }
  assert(word == "End");
  // names: "# region r "name"" and "# patch k ref l "name"" after End
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream ls(line);
    std::string hash, kind;
    int a = 0, b = 0;
    if(!(ls >> hash >> kind >> a)) continue;
    if(kind == "region") regions[a] = quoted_name(line);
    if(kind == "patch")
    {
      std::string ref;
      ls >> ref >> b;
      assert(ref == "ref" && b == a + 1);
      patches[b] = quoted_name(line);
    }
  }
  return m;
}

// the numbers in the first element whose start tag contains `tag`, from `from` on
std::vector<double> vtu_numbers(const std::string& xml, const std::string& tag, std::size_t from = 0)
{
  const std::size_t at = xml.find(tag, from);
  assert(at != std::string::npos);
  const std::size_t open = xml.find('>', at) + 1, close = xml.find('<', open);
  std::istringstream ss(xml.substr(open, close - open));
  std::vector<double> v;
  double x;
  while(ss >> x) v.push_back(x);
  return v;
}

std::vector<std::string> vtu_strings(const std::string& xml, const std::string& name)
{
  std::vector<std::string> out(1);
  for(double c : vtu_numbers(xml, "<Array type=\"String\" Name=\"" + name + "\""))
  {
    if(c == 0) out.emplace_back();
    else out.back() += char(int(c));
  }
  out.pop_back();
  return out;
}

Read_mesh read_vtu(const std::string& file, std::vector<std::string>& region_names,
                   std::vector<std::string>& patch_names)
{
  const std::string xml = slurp(file);
  assert(xml.find("<VTKFile type=\"UnstructuredGrid\"") != std::string::npos);
  Read_mesh m;
  const std::vector<double> pts = vtu_numbers(xml, "<DataArray", xml.find("<Points>"));
  for(std::size_t i = 0; i + 2 < pts.size(); i += 3) m.points.push_back({{pts[i], pts[i + 1], pts[i + 2]}});
  const std::vector<double> conn = vtu_numbers(xml, "Name=\"connectivity\""),
                            offsets = vtu_numbers(xml, "Name=\"offsets\""), types = vtu_numbers(xml, "Name=\"types\""),
                            region = vtu_numbers(xml, "Name=\"region\""), patch = vtu_numbers(xml, "Name=\"patch\"");
  assert(offsets.size() == types.size() && region.size() == types.size() && patch.size() == types.size());
  std::size_t begin = 0;
  for(std::size_t c = 0; c < types.size(); ++c)
  {
    const std::size_t end = std::size_t(offsets[c]);
    if(types[c] == 10)
    {
      assert(end - begin == 4 && region[c] >= 1 && patch[c] == -1);
      m.tets.push_back({{std::size_t(conn[begin]), std::size_t(conn[begin + 1]), std::size_t(conn[begin + 2]),
                         std::size_t(conn[begin + 3])}});
      m.tet_regions.push_back(int(region[c]));
    }
    else
    {
      assert(types[c] == 5 && end - begin == 3 && region[c] == -1 && patch[c] >= 1);
      m.triangles.push_back({{std::size_t(conn[begin]), std::size_t(conn[begin + 1]), std::size_t(conn[begin + 2])}});
      m.triangle_labels.push_back(int(patch[c]));
    }
    begin = end;
  }
  assert(begin == conn.size());
  region_names = vtu_strings(xml, "region_names");
  patch_names = vtu_strings(xml, "patch_names");
  return m;
}

Read_mesh read_gmsh(const std::string& file, Names& region_names, Names& patch_names)
{
  std::ifstream in(file);
  assert(in);
  Read_mesh m;
  std::string word;
  std::map<std::pair<int, int>, int> physical; // (dim, entity) -> physical tag
  std::map<std::size_t, P3> nodes;
  while(in >> word)
  {
    if(word == "$MeshFormat")
    {
      std::string version;
      int binary, size;
      in >> version >> binary >> size;
      assert(version == "4.1" && binary == 0 && size == 8);
    }
    else if(word == "$PhysicalNames")
    {
      int n;
      in >> n;
      std::string line;
      std::getline(in, line);
      for(int i = 0; i < n; ++i)
      {
        std::getline(in, line);
        std::istringstream ls(line);
        int dim, tag;
        ls >> dim >> tag;
        (dim == 3 ? region_names : patch_names)[tag] = quoted_name(line);
      }
    }
    else if(word == "$Entities")
    {
      std::size_t np, nc, ns, nv;
      in >> np >> nc >> ns >> nv;
      assert(np == 0 && nc == 0);
      for(std::size_t i = 0; i < ns + nv; ++i)
      {
        int tag, nphys, phys, nbound, b;
        double box[6];
        in >> tag;
        for(double& x : box) in >> x;
        in >> nphys >> phys >> nbound;
        assert(nphys == 1 && phys == tag); // physical tag = entity tag = label
        for(int j = 0; j < nbound; ++j) in >> b;
        physical[std::make_pair(i < ns ? 2 : 3, tag)] = phys;
        for(int d = 0; d < 3; ++d) assert(box[d] <= box[d + 3]);
      }
    }
    else if(word == "$Nodes")
    {
      std::size_t blocks, n, lo, hi;
      in >> blocks >> n >> lo >> hi;
      assert(lo == 1 && hi == n);
      for(std::size_t b = 0; b < blocks; ++b)
      {
        int dim, tag, parametric;
        std::size_t count;
        in >> dim >> tag >> parametric >> count;
        assert(parametric == 0 && physical.count(std::make_pair(dim, tag)));
        std::vector<std::size_t> tags(count);
        for(auto& t : tags) in >> t;
        for(auto t : tags) in >> nodes[t][0] >> nodes[t][1] >> nodes[t][2];
      }
      assert(nodes.size() == n);
      for(const auto& p : nodes) m.points.push_back(p.second);
    }
    else if(word == "$Elements")
    {
      std::size_t blocks, n, lo, hi;
      in >> blocks >> n >> lo >> hi;
      std::set<std::size_t> element_tags;
      for(std::size_t b = 0; b < blocks; ++b)
      {
        int dim, tag, type;
        std::size_t count;
        in >> dim >> tag >> type >> count;
        const int label = physical.at(std::make_pair(dim, tag));
        assert((dim == 3 && type == 4) || (dim == 2 && type == 2));
        for(std::size_t i = 0; i < count; ++i)
        {
          std::size_t e, v[4];
          in >> e;
          assert(element_tags.insert(e).second);
          for(int j = 0; j < (dim == 3 ? 4 : 3); ++j)
          {
            in >> v[j];
            assert(nodes.count(v[j]));
            --v[j];
          }
          if(dim == 3)
          {
            m.tets.push_back({{v[0], v[1], v[2], v[3]}});
            m.tet_regions.push_back(label);
          }
          else
          {
            m.triangles.push_back({{v[0], v[1], v[2]}});
            m.triangle_labels.push_back(label);
          }
        }
      }
      assert(element_tags.size() == n && *element_tags.begin() == lo && *element_tags.rbegin() == hi);
    }
  }
  return m;
}

// the `#   n "name"` comment lines of a TetGen file
void read_tetgen_names(std::istream& in, Names& names)
{
  while(in.peek() == '#')
  {
    std::string line;
    std::getline(in, line);
    std::istringstream ls(line.substr(1));
    int n;
    if(line.find('"') != std::string::npos && ls >> n) names[n] = quoted_name(line);
  }
}

Read_mesh read_tetgen(const std::string& base, Names& region_names, Names& patch_names)
{
  Read_mesh m;
  std::ifstream node(base + ".node"), ele(base + ".ele"), face(base + ".face");
  assert(node && ele && face);
  Names none;
  read_tetgen_names(node, none);
  std::size_t n, dim, attributes, markers;
  node >> n >> dim >> attributes >> markers;
  assert(dim == 3 && attributes == 0 && markers == 0);
  for(std::size_t i = 0; i < n; ++i)
  {
    std::size_t id;
    P3 p;
    node >> id >> p[0] >> p[1] >> p[2];
    assert(id == i + 1); // numbered from 1
    m.points.push_back(p);
  }
  read_tetgen_names(ele, region_names);
  std::size_t per;
  ele >> n >> per >> attributes;
  assert(per == 4 && attributes == 1);
  for(std::size_t i = 0; i < n; ++i)
  {
    std::size_t id;
    std::array<std::size_t, 4> t;
    int region;
    ele >> id >> t[0] >> t[1] >> t[2] >> t[3] >> region;
    assert(id == i + 1);
    for(auto& v : t) --v;
    m.tets.push_back(t);
    m.tet_regions.push_back(region);
  }
  read_tetgen_names(face, patch_names);
  face >> n >> markers;
  assert(markers == 1);
  for(std::size_t i = 0; i < n; ++i)
  {
    std::size_t id;
    std::array<std::size_t, 3> t;
    int marker;
    face >> id >> t[0] >> t[1] >> t[2] >> marker;
    assert(id == i + 1);
    for(auto& v : t) --v;
    m.triangles.push_back(t);
    m.triangle_labels.push_back(marker);
  }
  return m;
}

std::vector<std::string> split_commas(const std::string& line)
{
  std::vector<std::string> out;
  std::string item;
  std::istringstream ss(line);
  while(std::getline(ss, item, ','))
  {
    const std::size_t a = item.find_first_not_of(' '), b = item.find_last_not_of(" \r");
    out.push_back(a == std::string::npos ? std::string() : item.substr(a, b - a + 1));
  }
  return out;
}

std::string keyword_value(const std::string& line, const std::string& key)
{
  for(const std::string& item : split_commas(line))
    if(item.compare(0, key.size() + 1, key + "=") == 0) return item.substr(key.size() + 1);
  return std::string();
}

struct Abaqus_file
{
  Read_mesh mesh;                                                   // points and tets
  std::map<std::string, std::vector<std::size_t> > elsets;           // name -> elements (0-based)
  std::map<std::string, std::vector<std::pair<std::size_t, int> > > surfaces; // name -> (element, face)
  std::map<std::string, std::set<std::size_t> > nsets;              // name -> nodes (0-based)
};

Abaqus_file read_abaqus(const std::string& file)
{
  std::ifstream in(file);
  assert(in);
  Abaqus_file a;
  std::map<std::size_t, std::pair<std::array<std::size_t, 4>, std::string> > elements;
  std::string line, block, name;
  std::size_t expected_node = 1;
  while(std::getline(in, line))
  {
    if(line.compare(0, 2, "**") == 0) continue;
    if(line[0] == '*')
    {
      block = split_commas(line)[0];
      if(block == "*ELEMENT")
      {
        assert(keyword_value(line, "TYPE") == "C3D4");
        name = keyword_value(line, "ELSET");
      }
      if(block == "*SURFACE")
      {
        assert(keyword_value(line, "TYPE") == "ELEMENT");
        name = keyword_value(line, "NAME");
      }
      if(block == "*NSET") name = keyword_value(line, "NSET");
      continue;
    }
    const std::vector<std::string> f = split_commas(line);
    if(block == "*NODE")
    {
      assert(f.size() == 4 && std::stoul(f[0]) == expected_node++);
      a.mesh.points.push_back({{std::stod(f[1]), std::stod(f[2]), std::stod(f[3])}});
    }
    else if(block == "*ELEMENT")
    {
      assert(f.size() == 5);
      const std::size_t e = std::stoul(f[0]) - 1;
      elements[e] = std::make_pair(std::array<std::size_t, 4>{{std::stoul(f[1]) - 1, std::stoul(f[2]) - 1,
                                                                std::stoul(f[3]) - 1, std::stoul(f[4]) - 1}},
                                   name);
      a.elsets[name].push_back(e);
    }
    else if(block == "*SURFACE")
    {
      assert(f.size() == 2 && f[1].size() == 2 && f[1][0] == 'S');
      a.surfaces[name].emplace_back(std::stoul(f[0]) - 1, f[1][1] - '0');
    }
    else if(block == "*NSET")
    {
      assert(f.size() <= 16);
      for(const std::string& s : f) a.nsets[name].insert(std::stoul(s) - 1);
    }
  }
  // elements are numbered 0..T-1 (1..T in the file) across the ELSET blocks
  std::size_t next = 0;
  for(const auto& e : elements)
  {
    assert(e.first == next++);
    a.mesh.tets.push_back(e.second.first);
    a.mesh.tet_regions.push_back(0); // set by the caller from the ELSET names
  }
  return a;
}

Read_mesh read_flac3d(const std::string& file, std::map<std::string, std::vector<std::size_t> >& zone_groups,
                      std::map<std::string, std::vector<std::size_t> >& face_groups)
{
  std::ifstream in(file);
  assert(in);
  Read_mesh m;
  std::string line;
  std::vector<std::size_t>* group = nullptr;
  while(std::getline(in, line))
  {
    if(line.empty() || line[0] == '*')
    {
      group = nullptr;
      continue;
    }
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if(key == "G")
    {
      std::size_t id;
      P3 p;
      ls >> id >> p[0] >> p[1] >> p[2];
      assert(id == m.points.size() + 1);
      m.points.push_back(p);
    }
    else if(key == "Z" || key == "F")
    {
      std::string type;
      std::size_t id;
      ls >> type >> id;
      if(key == "Z")
      {
        std::array<std::size_t, 4> t;
        ls >> t[0] >> t[1] >> t[2] >> t[3];
        assert(type == "T4" && id == m.tets.size() + 1);
        for(auto& v : t) --v;
        m.tets.push_back(t);
        m.tet_regions.push_back(0);
      }
      else
      {
        std::array<std::size_t, 3> t;
        ls >> t[0] >> t[1] >> t[2];
        assert(type == "T3" && id == m.triangles.size() + 1);
        for(auto& v : t) --v;
        m.triangles.push_back(t);
        m.triangle_labels.push_back(0);
      }
    }
    else if(key == "ZGROUP" || key == "FGROUP")
    {
      assert(line.substr(line.rfind('"') + 1) == " SLOT 1");
      group = &(key == "ZGROUP" ? zone_groups : face_groups)[quoted_name(line)];
      assert(group->empty());
    }
    else
    {
      assert(group != nullptr); // a line of ids
      std::size_t id = std::stoul(key);
      std::size_t count = 0;
      do { group->push_back(id - 1); ++count; } while(ls >> id);
      assert(count <= 10);
    }
  }
  return m;
}

// ---------------------------------------------------------------------------

bool file_exists(const std::string& f)
{
  struct stat st;
  return stat(f.c_str(), &st) == 0;
}

// the message of the std::runtime_error `f` throws (it must throw one)
std::string message_of(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch(const std::runtime_error& e)
  {
    return e.what();
  }
  std::cerr << "FAIL: no std::runtime_error\n";
  assert(false);
  return std::string();
}

void expect_error(const std::string& what, const std::function<void()>& f, const std::vector<std::string>& needles)
{
  const std::string msg = message_of(f);
  std::cout << "  " << what << ": " << msg << "\n";
  for(const std::string& n : needles)
  {
    if(msg.find(n) == std::string::npos) std::cerr << "FAIL: the message lacks '" << n << "'\n";
    assert(msg.find(n) != std::string::npos);
  }
}

std::string json_string(const std::string& s)
{
  std::string r = "\"";
  for(char c : s)
  {
    if(c == '"' || c == '\\') r += '\\';
    r += c;
  }
  return r + "\"";
}

int main(int argc, char** argv)
{
  const std::string out_dir = argc > 1 ? argv[1] : std::string(BUBBLE_MESH_3_BINARY_DIR) + "/test_writers_out";
  mkdir(out_dir.c_str(), 0755);
  assert(file_exists(out_dir));
  const std::string base = out_dir + "/box";

  const Model model = make_model();
  C3T3 c3t3;
  fill_c3t3(c3t3);
  const Expected e = count_c3t3(c3t3);
  std::cout << "hand-filled C3T3: " << e.points << " vertices, " << e.tets() << " tets (" << e.tets_per_region.at(1)
            << " + " << e.tets_per_region.at(2) << "), " << e.triangles() << " complex facets in "
            << e.triangles_per_label.size() << " patches\n";
  assert(e.points == 9 * 5 * 5);
  assert(e.triangles_per_label.size() == 6 && e.triangles_per_label.count(UNUSED + 1) == 0);
  assert(e.triangles_per_label.at(FAULT + 1) == 16 && e.triangles_per_label.at(CONTACT + 1) == 32);

  // the shared extraction: who oriented what
  {
    const BIO::internal::Mesh_arrays m = BIO::internal::extract_mesh_arrays(c3t3, model);
    std::cout << "orientation: " << m.oriented_by_regions << " facets by their regions, " << m.oriented_by_geometry
              << " by the model's triangles, " << m.oriented_by_default << " by default\n";
    assert(m.oriented_by_geometry == 16 && m.oriented_by_default == 0);
    assert(m.oriented_by_regions == e.triangles() - 16);
  }

  for(const char* ext : {".mesh", ".vtu", ".msh", ".node", ".inp", ".f3grid"})
  {
    BIO::write_mesh(base + ext, c3t3, model);
    assert(file_exists(base + ext) && !file_exists(base + ext + ".tmp"));
  }
  assert(file_exists(base + ".ele") && file_exists(base + ".face"));

  // names every format must keep (after the quoting each format needs)
  const std::string region_1 = "Layer 1 (sand)", region_2 = "2nd layer";
  const Names model_patch_names{{WEST + 1, "west"},    {EAST + 1, "east"},
                                {SIDES_1 + 1, "sides"}, {SIDES_2 + 1, "sides"},
                                {CONTACT + 1, "contact 'A'"}, {FAULT + 1, long_fault_name}};
  Names unique_patch_names = model_patch_names; // Gmsh and FLAC3D look groups up by name
  unique_patch_names[SIDES_2 + 1] = "sides_2";

  // Medit, by our parser and by CGAL's
  {
    Names regions, patches;
    check_read_mesh("Medit .mesh", read_medit(base + ".mesh", regions, patches), e);
    assert(regions == (Names{{1, region_1}, {2, region_2}}));
    assert(patches == model_patch_names);

    Tr tr;
    std::ifstream in(base + ".mesh");
    const bool ok = CGAL::IO::read_MEDIT(in, tr);
    assert(ok && tr.is_valid());
    std::map<int, std::size_t> cells, facets;
    for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) ++cells[c->subdomain_index()];
    for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f)
    {
      const int label = f->first->surface_patch_index(f->second);
      const auto mf = tr.mirror_facet(*f);
      assert(mf.first->surface_patch_index(mf.second) == label); // both sides carry it
      if(label != 0) ++facets[label];
    }
    std::cout << "CGAL::IO::read_MEDIT: " << tr.number_of_vertices() << " vertices, " << tr.number_of_finite_cells()
              << " cells, " << facets.size() << " patch labels\n";
    assert(tr.number_of_vertices() == e.points);
    assert(cells == e.tets_per_region);
    assert(facets == e.triangles_per_label);
  }

  // VTU
  {
    std::vector<std::string> regions, patches;
    check_read_mesh("VTK .vtu", read_vtu(base + ".vtu", regions, patches), e);
    assert(regions == (std::vector<std::string>{"outside", region_1, region_2}));
    assert(patches.size() == FAULT + 2 && patches[0] == "none");
    for(int l = 1; l <= FAULT + 1; ++l) assert(patches[l] == model.patch(l - 1).name); // raw names, quote kept
  }

  // Gmsh
  {
    Names regions, patches;
    check_read_mesh("Gmsh .msh", read_gmsh(base + ".msh", regions, patches), e);
    assert(regions == (Names{{1, region_1}, {2, region_2}}));
    assert(patches == unique_patch_names);
  }

  // TetGen
  {
    Names regions, patches;
    check_read_mesh("TetGen .node/.ele/.face", read_tetgen(base, regions, patches), e);
    assert(regions == (Names{{1, region_1}, {2, region_2}}));
    assert(patches == model_patch_names);
  }

  // FLAC3D
  {
    std::map<std::string, std::vector<std::size_t> > zone_groups, face_groups;
    Read_mesh m = read_flac3d(base + ".f3grid", zone_groups, face_groups);
    const Names regions{{1, region_1}, {2, region_2}};
    assert(zone_groups.size() == 2 && face_groups.size() == unique_patch_names.size());
    for(const auto& r : regions)
      for(std::size_t z : zone_groups.at(r.second))
      {
        assert(m.tet_regions.at(z) == 0); // in one group only
        m.tet_regions[z] = r.first;
      }
    for(const auto& p : unique_patch_names)
      for(std::size_t f : face_groups.at(p.second))
      {
        assert(m.triangle_labels.at(f) == 0);
        m.triangle_labels[f] = p.first;
      }
    check_read_mesh("FLAC3D .f3grid", m, e);
  }

  // Abaqus: ELSETs per region, SURFACEs per patch side, NSETs per patch
  {
    Abaqus_file a = read_abaqus(base + ".inp");
    const std::string fault = CGAL::Bubble_mesh_3::IO::internal::replace_non_word_characters(long_fault_name);
    const std::map<std::string, int> elsets{{"Layer_1__sand_", 1}, {"R_2nd_layer", 2}};
    // surface name -> (label, +1: faces of the elements on the positive side, -1: negative side)
    const std::map<std::string, std::pair<int, int> > surfaces{
      {"west", {WEST + 1, 1}},      {"east", {EAST + 1, -1}},          {"sides", {SIDES_1 + 1, -1}},
      {"sides_2", {SIDES_2 + 1, -1}}, {"contact__A_", {CONTACT + 1, 1}}, {"contact__A__NEG", {CONTACT + 1, -1}},
      {fault.substr(0, 76), {FAULT + 1, 1}}, {fault.substr(0, 72) + "_NEG", {FAULT + 1, -1}}};
    std::set<std::string> all_names;
    for(const auto& s : a.elsets) all_names.insert(s.first);
    for(const auto& s : a.surfaces) all_names.insert(s.first);
    for(const auto& s : a.nsets) all_names.insert(s.first);
    std::set<std::string> upper;
    for(const std::string& n : all_names)
    {
      std::cout << "  Abaqus name " << n << "\n";
      assert(!n.empty() && n.size() <= 80 && std::isalpha(static_cast<unsigned char>(n[0])));
      for(char c : n) assert(std::isalnum(static_cast<unsigned char>(c)) || c == '_');
      std::string u = n;
      for(char& c : u) c = char(std::toupper(static_cast<unsigned char>(c)));
      assert(upper.insert(u).second); // unique regardless of case
    }
    assert(a.elsets.size() == elsets.size() && a.surfaces.size() == surfaces.size() && a.nsets.size() == 6);
    for(const auto& s : a.elsets)
      for(std::size_t t : s.second) a.mesh.tet_regions.at(t) = elsets.at(s.first);
    // each face side, turned into a triangle facing the positive region: C3D4 faces listed
    // S1 = 1-2-3, S2 = 1-4-2, S3 = 2-4-3, S4 = 3-4-1 have normals pointing into the element
    const int face_nodes[5][3] = {{0, 0, 0}, {0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
    Read_mesh positive = a.mesh, negative = a.mesh;
    Expected e_negative = e;
    e_negative.triangles_per_label.clear();
    for(const auto& s : a.surfaces)
    {
      const int label = surfaces.at(s.first).first, side = surfaces.at(s.first).second;
      const bool negative_surface = s.first.size() > 4 && s.first.substr(s.first.size() - 4) == "_NEG";
      for(const auto& ef : s.second)
      {
        const auto& tet = a.mesh.tets.at(ef.first);
        std::array<std::size_t, 3> t{{tet[face_nodes[ef.second][0]], tet[face_nodes[ef.second][1]],
                                      tet[face_nodes[ef.second][2]]}};
        if(side < 0) std::swap(t[1], t[2]);
        Read_mesh& target = negative_surface ? negative : positive;
        target.triangles.push_back(t);
        target.triangle_labels.push_back(label);
      }
      if(negative_surface) e_negative.triangles_per_label[label] = e.triangles_per_label.at(label);
    }
    check_read_mesh("Abaqus .inp (surfaces)", positive, e);
    check_read_mesh("Abaqus .inp (_NEG surfaces)", negative, e_negative);
    assert(e_negative.triangles_per_label.size() == 2); // the interface and the fault
    // node sets: the nodes of each patch's triangles
    assert(a.nsets.at("west_NODES").size() == 25 && a.nsets.at("contact__A__NODES").size() == 25);
    // the sides of a region: 5 rings of the 16 boundary nodes of a 5x5 grid
    assert(a.nsets.at("sides_NODES").size() == 80 && a.nsets.at("sides_2_NODES").size() == 80);
    assert(a.nsets.at(fault.substr(0, 70) + "_NODES").size() == 15);
  }

  // the same C3T3 written twice gives the same bytes
  for(const char* ext : {".mesh", ".vtu", ".msh", ".node", ".inp", ".f3grid"})
  {
    BIO::write_mesh(base + "_again" + ext, c3t3, model);
    assert(slurp(base + ext) == slurp(base + "_again" + ext));
  }
  assert(slurp(base + ".ele") == slurp(base + "_again.ele") && slurp(base + ".face") == slurp(base + "_again.face"));
  std::cout << "writing twice gives identical files\n";

  // the per-format entry points write what write_mesh writes
  BIO::write_medit(base + "_direct.mesh", c3t3, model);
  BIO::write_vtu(base + "_direct.vtu", c3t3, model);
  BIO::write_gmsh_msh(base + "_direct.msh", c3t3, model);
  BIO::write_tetgen(base + "_direct.node", c3t3, model);
  BIO::write_abaqus_inp(base + "_direct.inp", c3t3, model);
  BIO::write_flac3d_f3grid(base + "_direct.f3grid", c3t3, model);
  for(const char* ext : {".mesh", ".vtu", ".msh", ".node", ".ele", ".face", ".inp", ".f3grid"})
    assert(slurp(base + ext) == slurp(base + "_direct" + ext));
  std::cout << "write_medit, write_vtu, write_gmsh_msh, write_tetgen, write_abaqus_inp, write_flac3d_f3grid "
               "agree with write_mesh\n";

  // without a model: default names, normals toward the smaller region index
  {
    BIO::write_mesh(base + "_nomodel.msh", c3t3);
    Names regions, patches;
    Read_mesh m = read_gmsh(base + "_nomodel.msh", regions, patches);
    assert(regions == (Names{{1, "region_1"}, {2, "region_2"}}));
    assert(patches.at(WEST + 1) == "patch_0" && patches.at(FAULT + 1) == "patch_5");
    std::size_t toward_region_1 = 0, outward = 0, boundary = 0;
    for(std::size_t t = 0; t < m.triangles.size(); ++t)
    {
      const P3 &a = m.points[m.triangles[t][0]], &b = m.points[m.triangles[t][1]], &c = m.points[m.triangles[t][2]];
      const P3 n = cross(sub(b, a), sub(c, a));
      if(m.triangle_labels[t] == CONTACT + 1 && n[0] < 0) ++toward_region_1;
      if(m.triangle_labels[t] == WEST + 1 || m.triangle_labels[t] == EAST + 1)
      {
        ++boundary;
        if(n[0] * (a[0] - 1) > 0) ++outward;
      }
    }
    std::cout << "without a model: contact facets facing region 1: " << toward_region_1 << " of "
              << e.triangles_per_label.at(CONTACT + 1) << ", west/east facets facing out: " << outward << " of "
              << boundary << "\n";
    assert(toward_region_1 == e.triangles_per_label.at(CONTACT + 1) && outward == boundary);
  }

  // errors: unknown extension, no extension, a folder that does not exist
  std::cout << "errors:\n";
  expect_error("unknown extension", [&] { BIO::write_mesh(base + ".stl", c3t3, model); },
               {base + ".stl", "'.stl'", ".mesh", ".vtu", ".msh", ".node", ".inp", ".f3grid"});
  expect_error("no extension", [&] { BIO::write_mesh(out_dir + "/box", c3t3, model); },
               {out_dir + "/box", "no extension", ".f3grid"});
  expect_error("check before meshing", [&] { BIO::check_mesh_file_name("x.MSH2"); }, {"x.MSH2", ".msh"});
  BIO::check_mesh_file_name("UPPER.MSH"); // case does not matter
  const std::string missing = out_dir + "/no_such_folder/box";
  for(const char* ext : {".mesh", ".vtu", ".msh", ".node", ".inp", ".f3grid"})
  {
    expect_error(std::string("missing folder ") + ext, [&] { BIO::write_mesh(missing + ext, c3t3, model); },
                 {missing + ext});
    assert(!file_exists(missing + ext + ".tmp"));
  }
  expect_error("TetGen name", [&] { BIO::write_tetgen(base + ".ele", c3t3, model); }, {base + ".ele", ".node"});
  // an existing file is replaced only by a complete one: a failed write leaves it as it was
  {
    const std::string before = slurp(base + ".msh");
    const std::string dir_as_file = out_dir + "/a_folder.msh";
    mkdir(dir_as_file.c_str(), 0755);
    expect_error("target is a folder", [&] { BIO::write_mesh(dir_as_file, c3t3, model); }, {dir_as_file});
    assert(!file_exists(dir_as_file + ".tmp"));
    assert(slurp(base + ".msh") == before);
  }

  // what test_writers_consumers.sh checks the files against
  {
    std::ofstream js(base + "_expected.json");
    js << "{\n  \"points\": " << e.points << ",\n  \"tets\": " << e.tets() << ",\n  \"triangles\": " << e.triangles()
       << ",\n  \"regions\": {";
    const char* sep = "";
    for(const auto& r : e.tets_per_region)
    {
      js << sep << "\"" << r.first << "\": {\"name\": " << json_string(r.first == 1 ? region_1 : region_2)
         << ", \"tets\": " << r.second << "}";
      sep = ", ";
    }
    js << "},\n  \"patches\": {";
    sep = "";
    for(const auto& l : e.triangles_per_label)
    {
      js << sep << "\"" << l.first << "\": {\"name\": " << json_string(unique_patch_names.at(l.first))
         << ", \"triangles\": " << l.second << "}";
      sep = ", ";
    }
    js << "},\n  \"abaqus_elsets\": {\"1\": \"Layer_1__sand_\", \"2\": \"R_2nd_layer\"}\n}\n";
  }
  std::cout << "wrote " << base << ".{mesh,vtu,msh,node,ele,face,inp,f3grid} and " << base << "_expected.json\n";
  return EXIT_SUCCESS;
}
