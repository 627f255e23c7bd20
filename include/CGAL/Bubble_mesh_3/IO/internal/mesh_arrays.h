// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_INTERNAL_MESH_ARRAYS_H
#define CGAL_BUBBLE_MESH_3_IO_INTERNAL_MESH_ARRAYS_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Handle_hash_function.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

/*
The complex as plain arrays, shared by all mesh writers so that each of them
only formats. Conventions (every writer keeps them):
- tetrahedra are positively oriented: orientation(p0,p1,p2,p3) == POSITIVE,
  i.e. p3 lies on the side (p1-p0)x(p2-p0) points to;
- each complex facet appears once; its normal (p1-p0)x(p2-p0) points into
  the positive region of its patch;
- labels are the C3T3's: region >= 1, patch label = patch index + 1.
*/
struct Mesh_arrays
{
  static constexpr std::size_t no_tet = std::size_t(-1);

  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 4> > tets;
  std::vector<int> tet_regions;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<int> triangle_labels;
  /// [0]: the tet on the positive side of the triangle, [1]: on the negative side (or no_tet)
  std::vector<std::array<std::size_t, 2> > triangle_tets;

  /// names given by the caller: region_names[r], patch_names[k] for patch index k
  std::vector<std::string> region_names;
  std::vector<std::string> patch_names;

  /// how the triangles were oriented: by the regions on their two sides, by
  /// the model's triangles (patches inside a region), or, with no model to
  /// ask, toward the smaller region index
  std::size_t oriented_by_regions = 0;
  std::size_t oriented_by_geometry = 0;
  std::size_t oriented_by_default = 0;

  std::string region_name(int r) const
  {
    if(r >= 0 && std::size_t(r) < region_names.size() && !region_names[r].empty())
      return region_names[r];
    return "region_" + std::to_string(r);
  }

  /// the name of the patch with label `label` (patch index `label - 1`)
  std::string patch_name(int label) const
  {
    const int k = label - 1;
    if(k >= 0 && std::size_t(k) < patch_names.size() && !patch_names[k].empty())
      return patch_names[k];
    return "patch_" + std::to_string(k);
  }

  /// the region labels that occur, in increasing order
  std::vector<int> regions_present() const { return sorted_unique(tet_regions); }
  /// the patch labels that occur, in increasing order
  std::vector<int> labels_present() const { return sorted_unique(triangle_labels); }

  /// the tets of each region, in increasing order
  std::map<int, std::vector<std::size_t> > tets_by_region() const { return group(tet_regions); }
  /// the triangles of each patch label, in increasing order
  std::map<int, std::vector<std::size_t> > triangles_by_label() const { return group(triangle_labels); }

  /// bounding box (xmin,ymin,zmin,xmax,ymax,zmax) of the given point indices
  template <class IndexRange>
  std::array<double, 6> bounding_box(const IndexRange& indices) const
  {
    std::array<double, 6> b{{0, 0, 0, 0, 0, 0}};
    bool first = true;
    for(std::size_t i : indices)
    {
      for(int d = 0; d < 3; ++d)
      {
        b[d] = first ? points[i][d] : (std::min)(b[d], points[i][d]);
        b[d + 3] = first ? points[i][d] : (std::max)(b[d + 3], points[i][d]);
      }
      first = false;
    }
    return b;
  }

private:
  static std::map<int, std::vector<std::size_t> > group(const std::vector<int>& labels)
  {
    std::map<int, std::vector<std::size_t> > g;
    for(std::size_t i = 0; i < labels.size(); ++i) g[labels[i]].push_back(i);
    return g;
  }

  static std::vector<int> sorted_unique(std::vector<int> v)
  {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  }
};

/// what the writers know about patches besides the complex: names and sides
struct Mesh_labels
{
  struct Patch
  {
    std::string name;
    int positive_region = -1; ///< -1: unknown
    int negative_region = -1;
  };
  std::vector<std::string> region_names; ///< [r]; [0] is the outside
  std::vector<Patch> patches;            ///< [k] for patch index k

  /// +1 if the triangle (a,b,c) of patch k has the model's orientation there,
  /// -1 if the opposite one, 0 if unknown; empty: always unknown
  std::function<int(std::size_t k, const std::array<double, 3>& a, const std::array<double, 3>& b,
                    const std::array<double, 3>& c)> orientation;
};

// Finds the model triangle under a mesh facet: the facet lies on one input
// triangle, so the triangle closest to its centroid (at distance ~0) is it.
template <class GeomTraits>
class Model_orientation
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;

public:
  explicit Model_orientation(const Geological_model_3<GeomTraits>& model)
  {
    for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    {
      const auto& tri = model.triangle(t);
      triangles_.push_back(K::Triangle_3(convert(model.point(tri[0])), convert(model.point(tri[1])),
                                         convert(model.point(tri[2]))));
      patch_.push_back(model.patch_of_triangle(t));
    }
  }

  int operator()(std::size_t k, const std::array<double, 3>& a, const std::array<double, 3>& b,
                 const std::array<double, 3>& c)
  {
    if(triangles_.empty()) return 0;
    if(!tree_) // built on first need only: most facets are oriented by their regions
    {
      tree_ = std::make_shared<Tree>(triangles_.begin(), triangles_.end());
      tree_->accelerate_distance_queries();
    }
    const K::Point_3 pa(a[0], a[1], a[2]), pb(b[0], b[1], b[2]), pc(c[0], c[1], c[2]);
    const K::Point_3 centroid = CGAL::centroid(pa, pb, pc);
    const std::size_t t = std::size_t(tree_->closest_point_and_primitive(centroid).second - triangles_.begin());
    if(patch_[t] != k) return 0;
    const double d = CGAL::cross_product(pb - pa, pc - pa) * triangles_[t].supporting_plane().orthogonal_vector();
    return d > 0 ? 1 : (d < 0 ? -1 : 0);
  }

private:
  template <class P>
  static K::Point_3 convert(const P& p)
  {
    return K::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  std::vector<K::Triangle_3> triangles_;
  std::vector<std::size_t> patch_;
  std::shared_ptr<Tree> tree_;
};

/// names, sides and orientation from a geological model
template <class GeomTraits>
Mesh_labels labels_from_model(const Geological_model_3<GeomTraits>& model)
{
  Mesh_labels labels;
  for(const auto& r : model.regions()) labels.region_names.push_back(r.name);
  for(const auto& p : model.patches())
  {
    Mesh_labels::Patch q;
    q.name = p.name;
    q.positive_region = int(p.positive_region);
    q.negative_region = int(p.negative_region);
    labels.patches.push_back(q);
  }
  labels.orientation = Model_orientation<GeomTraits>(model);
  return labels;
}

// For a positively oriented cell, the vertices of face i in an order whose
// normal points into the cell: (i+1,i+2,i+3) does so for odd i only.
inline std::array<int, 3> inward_face(int i)
{
  if(i % 2 == 1) return {{(i + 1) % 4, (i + 2) % 4, (i + 3) % 4}};
  return {{(i + 1) % 4, (i + 3) % 4, (i + 2) % 4}};
}

/// extracts the cells and facets in the complex of `c3t3` (see Mesh_arrays for the conventions)
template <class C3T3>
Mesh_arrays extract_mesh_arrays(const C3T3& c3t3, const Mesh_labels& labels)
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;

  const Tr& tr = c3t3.triangulation();
  auto cp = tr.geom_traits().construct_point_3_object();

  Mesh_arrays m;
  m.region_names = labels.region_names;
  for(const auto& p : labels.patches) m.patch_names.push_back(p.name);

  // vertices numbered in order of first use: deterministic, and neighbours stay close
  std::unordered_map<Vertex_handle, std::size_t, CGAL::Handle_hash_function> vertex_index;
  auto index = [&](Vertex_handle v) {
    auto ins = vertex_index.emplace(v, m.points.size());
    if(ins.second)
    {
      const auto& p = cp(tr.point(v));
      m.points.push_back({{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}});
    }
    return ins.first->second;
  };

  std::unordered_map<Cell_handle, std::size_t, CGAL::Handle_hash_function> tet_index;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    const Cell_handle ch = c;
    tet_index.emplace(ch, m.tets.size());
    m.tets.push_back({{index(ch->vertex(0)), index(ch->vertex(1)), index(ch->vertex(2)), index(ch->vertex(3))}});
    m.tet_regions.push_back(int(c3t3.subdomain_index(ch)));
  }

  auto region_of = [&](Cell_handle c) { return c3t3.is_in_complex(c) ? int(c3t3.subdomain_index(c)) : 0; };
  auto tet_of = [&](Cell_handle c) {
    auto it = tet_index.find(c);
    return it == tet_index.end() ? Mesh_arrays::no_tet : it->second;
  };

  Mesh_labels::Patch unknown;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    const Cell_handle c = f->first;
    const int i = f->second;
    const auto mirror = tr.mirror_facet(*f);
    const int label = int(c3t3.surface_patch_index(*f));
    const std::size_t k = std::size_t(label - 1);
    const Mesh_labels::Patch& patch = (label >= 1 && k < labels.patches.size()) ? labels.patches[k] : unknown;

    const std::array<int, 3> face = inward_face(i);
    std::array<std::size_t, 3> t{{index(c->vertex(face[0])), index(c->vertex(face[1])), index(c->vertex(face[2]))}};

    // is c (the side the inward normal points to) on the positive side of the patch?
    const int rc = region_of(c), rm = region_of(mirror.first);
    int c_positive = 0;
    if(rc != rm && patch.positive_region >= 0)
    {
      if(rc == patch.positive_region && rm == patch.negative_region) c_positive = 1;
      else if(rm == patch.positive_region && rc == patch.negative_region) c_positive = -1;
      if(c_positive != 0) ++m.oriented_by_regions;
    }
    if(c_positive == 0 && labels.orientation)
    {
      c_positive = labels.orientation(k, m.points[t[0]], m.points[t[1]], m.points[t[2]]);
      if(c_positive != 0) ++m.oriented_by_geometry;
    }
    if(c_positive == 0)
    {
      // nothing to ask: the normal points to the smaller region index, so
      // outward on the boundary of the mesh
      c_positive = rc <= rm ? 1 : -1;
      ++m.oriented_by_default;
    }

    std::array<std::size_t, 2> sides{{tet_of(c), tet_of(mirror.first)}};
    if(c_positive < 0)
    {
      std::swap(t[1], t[2]);
      std::swap(sides[0], sides[1]);
    }
    m.triangles.push_back(t);
    m.triangle_labels.push_back(label);
    m.triangle_tets.push_back(sides);
  }
  return m;
}

/// extracts the complex with names and orientation taken from `model`
template <class C3T3, class GeomTraits>
Mesh_arrays extract_mesh_arrays(const C3T3& c3t3, const Geological_model_3<GeomTraits>& model)
{
  return extract_mesh_arrays(c3t3, labels_from_model(model));
}

/// writes `x` in the shortest form that reads back to the same double (locale-free)
inline void write_double(std::ostream& os, double x)
{
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), x);
  os.write(buf, r.ptr - buf);
}

/// `s` with every character not in [A-Za-z0-9_] replaced by '_'
inline std::string replace_non_word_characters(const std::string& s)
{
  std::string r = s;
  for(char& ch : r)
  {
    const unsigned char u = static_cast<unsigned char>(ch);
    if(!((u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') || u == '_')) ch = '_';
  }
  return r;
}

/// `s` fit for a double-quoted name on one line: '"' becomes '\'', control characters ' '
inline std::string quotable(const std::string& s)
{
  std::string r = s;
  for(char& ch : r)
  {
    if(ch == '"') ch = '\'';
    else if(static_cast<unsigned char>(ch) < 32) ch = ' ';
  }
  return r;
}

// Keeps names unique within one namespace of a file format (a region's and a
// patch's groups, Abaqus sets): a name already given gets "_2", "_3", ...,
// shortened first if the format limits the length.
class Unique_names
{
public:
  explicit Unique_names(bool ignore_case = false, std::size_t max_length = std::string::npos)
    : ignore_case_(ignore_case), max_length_(max_length)
  {}

  std::string operator()(const std::string& name)
  {
    for(int n = 1;; ++n)
    {
      const std::string suffix = n == 1 ? std::string() : "_" + std::to_string(n);
      std::string candidate = name.substr(0, max_length_ == std::string::npos ? std::string::npos
                                                                               : max_length_ - suffix.size()) + suffix;
      if(taken_.insert(key(candidate)).second) return candidate;
    }
  }

private:
  std::string key(std::string s) const
  {
    if(ignore_case_)
      for(char& ch : s) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    return s;
  }

  bool ignore_case_;
  std::size_t max_length_;
  std::set<std::string> taken_;
};

} // namespace internal
} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_INTERNAL_MESH_ARRAYS_H
