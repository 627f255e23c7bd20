// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_VALIDATE_GEOLOGICAL_MODEL_H
#define CGAL_BUBBLE_MESH_3_VALIDATE_GEOLOGICAL_MODEL_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/centred_coordinates.h>
#include <CGAL/Bubble_mesh_3/internal/union_find.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal_np {
enum maximum_number_of_reported_elements_t { maximum_number_of_reported_elements };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgBubbleMesh3Ref
/// how many offending elements an error message lists (the count is always given)
inline Named_function_parameters<std::size_t, internal_np::maximum_number_of_reported_elements_t>
maximum_number_of_reported_elements(std::size_t n)
{
  return Named_function_parameters<std::size_t, internal_np::maximum_number_of_reported_elements_t>(n);
}

template <class T, class Tag, class Base>
Named_function_parameters<std::size_t, internal_np::maximum_number_of_reported_elements_t,
                          Named_function_parameters<T, Tag, Base> >
maximum_number_of_reported_elements(std::size_t n, const Named_function_parameters<T, Tag, Base>& np)
{
  return Named_function_parameters<std::size_t, internal_np::maximum_number_of_reported_elements_t,
                                   Named_function_parameters<T, Tag, Base> >(n, np);
}

} // namespace parameters

namespace internal {

template <class Point>
std::string point_to_string(const Point& p)
{
  std::ostringstream os;
  os.precision(12);
  os << '(' << CGAL::to_double(p.x()) << ", " << CGAL::to_double(p.y()) << ", " << CGAL::to_double(p.z()) << ')';
  return os.str();
}

// The offending elements of one class of problem: counts them all, keeps the first few lines.
class Problem_class
{
public:
  explicit Problem_class(std::size_t limit) : limit_(limit) {}
  void add(const std::string& line)
  {
    ++count_;
    if(lines_.size() < limit_) lines_.push_back(line);
  }
  bool empty() const { return count_ == 0; }
  std::size_t count() const { return count_; }
  // `headline` is completed with the count, e.g. "3 edges are used by one triangle only"
  std::string message(const std::string& headline) const
  {
    std::string m = headline;
    for(const std::string& l : lines_) m += "\n  " + l;
    if(count_ > lines_.size())
      m += "\n  ... and " + std::to_string(count_ - lines_.size()) + " more";
    return m;
  }

private:
  std::size_t limit_;
  std::size_t count_ = 0;
  std::vector<std::string> lines_;
};

// "1 edge", "3 edges"
inline std::string count_of(std::size_t n, const char* one, const char* many)
{
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

template <class GeomTraits>
class Geological_model_validator
{
  typedef Geological_model_3<GeomTraits>   Model;
  typedef typename GeomTraits::Point_3     Point_3;
  typedef typename GeomTraits::Triangle_3  Triangle_3;
  typedef typename GeomTraits::Segment_3   Segment_3;
  typedef CGAL::Surface_mesh<Point_3>      Mesh;
  typedef CGAL::Side_of_triangle_mesh<Mesh, GeomTraits> Side_of_mesh;

  // one side of a triangle that bounds a region, oriented outward as seen from the region
  struct Side
  {
    std::size_t region;
    std::size_t triangle;
    std::array<std::size_t, 3> v;
  };

  // one use of an (undirected) edge by a side
  struct Edge_use
  {
    std::size_t region, a, b; // a < b
    std::size_t side;
    bool forward;             // the side runs a -> b
    bool operator<(const Edge_use& o) const
    { return std::tie(region, a, b, side) < std::tie(o.region, o.a, o.b, o.side); }
    bool same_edge(const Edge_use& o) const { return region == o.region && a == o.a && b == o.b; }
  };

public:
  Geological_model_validator(const Model& model, std::size_t limit, bool stop_at_first, bool verbose)
    : m_(model), limit_(std::max<std::size_t>(limit, 1)), stop_at_first_(stop_at_first), verbose_(verbose)
  {}

  // runs the checks in order, cheap first; returns the problem messages, one per class found
  std::vector<std::string> run()
  {
    timer_.start();
    const bool basics = check_basics();
    report_time("coordinates and indices");
    if(!basics || done()) return problems_;
    const bool nondegenerate = check_degenerate_triangles();
    if(done()) return problems_;
    const bool distinct = check_duplicate_triangles();
    report_time("degenerate and duplicate triangles");
    if(!nondegenerate || !distinct || done()) return problems_;
    const bool regions = check_region_boundaries();
    report_time("region boundaries");
    if(done()) return problems_;
    if(regions)
    {
      check_surfaces_inside_regions();
      report_time("surfaces inside regions");
      if(done()) return problems_;
    }
    check_intersections();
    report_time("intersections");
    return problems_;
  }

private:
  bool done() const { return stop_at_first_ && !problems_.empty(); }

  void report_time(const char* what)
  {
    if(verbose_)
      std::cerr << "validate_geological_model: " << what << ": " << timer_.time() << " s\n";
    timer_.reset();
  }

  // "triangle 12 of patch 3 'Fault'"
  std::string triangle_label(std::size_t t) const
  {
    return "triangle " + std::to_string(t) + " of " + m_.patch_label(m_.patch_of_triangle(t));
  }

  std::string vertex_label(std::size_t v) const
  {
    return "vertex " + std::to_string(v) + " " + point_to_string(m_.point(v));
  }

  std::string edge_label(std::size_t a, std::size_t b) const
  {
    return "edge " + std::to_string(a) + "-" + std::to_string(b) + " " +
           point_to_string(m_.point(a)) + "-" + point_to_string(m_.point(b));
  }

  std::string at(std::size_t t) const { return m_.where(m_.triangle_source(t)); }

  // where triangle t comes from, shortened to "line N" when it is in the same file as triangle ref
  std::string also_at(std::size_t t, std::size_t ref) const
  {
    const auto& s = m_.triangle_source(t);
    const auto& r = m_.triangle_source(ref);
    if(s.line != 0 && s.file == r.file && !at(ref).empty()) return " (line " + std::to_string(s.line) + ")";
    const std::string w = at(t);
    return w.empty() ? w : " (" + w.substr(0, w.size() - 2) + ")";
  }

  // ---- 1. coordinates, indices, non-empty -------------------------------------------------

  bool check_basics()
  {
    bool ok = true;
    if(m_.number_of_regions() == 0 || m_.number_of_triangles() == 0)
    {
      std::string what = m_.number_of_regions() == 0 ? "no region" : "no triangle";
      if(m_.number_of_regions() == 0 && m_.number_of_triangles() == 0) what = "no region and no triangle";
      problems_.push_back(m_.where(typename Model::Source()) + "the geological model is empty: it has " + what);
      ok = false;
      if(done()) return false;
    }

    Problem_class nonfinite(limit_);
    for(std::size_t i = 0; i < m_.number_of_points(); ++i)
    {
      const Point_3& p = m_.point(i);
      if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
         !std::isfinite(CGAL::to_double(p.z())))
        nonfinite.add(m_.where(m_.point_source(i)) + "vertex " + std::to_string(i) + " has coordinates " +
                      point_to_string(p));
    }
    if(!nonfinite.empty())
    {
      problems_.push_back(nonfinite.message("coordinates that are not finite numbers: " +
                                            count_of(nonfinite.count(), "vertex", "vertices")));
      ok = false;
      if(done()) return false;
    }

    // the builders check indices, but set_triangle() and set_patch_regions() do not
    Problem_class ids(limit_);
    const std::size_t nr = m_.number_of_regions();
    for(std::size_t p = 0; p < m_.number_of_patches(); ++p)
    {
      const auto& patch = m_.patch(p);
      for(std::size_t r : {patch.positive_region, patch.negative_region})
        if(r > nr)
          ids.add(m_.patch_label(p) + " refers to region " + std::to_string(r) + " which does not exist (" +
                  std::to_string(nr) + " regions)");
      if(patch.positive_region == 0 && patch.negative_region == 0)
        ids.add(m_.patch_label(p) + " has the outside (region 0) on both sides: it belongs to no region");
    }
    for(std::size_t t = 0; t < m_.number_of_triangles(); ++t)
    {
      if(m_.patch_of_triangle(t) >= m_.number_of_patches())
        ids.add(at(t) + "triangle " + std::to_string(t) + " refers to patch " +
                std::to_string(m_.patch_of_triangle(t)) + " which does not exist (" +
                std::to_string(m_.number_of_patches()) + " patches)");
      else
        for(std::size_t v : m_.triangle(t))
          if(v >= m_.number_of_points())
            ids.add(at(t) + triangle_label(t) + " refers to vertex " + std::to_string(v) +
                    " which does not exist (" + std::to_string(m_.number_of_points()) + " points)");
    }
    if(!ids.empty())
    {
      problems_.push_back(ids.message("unknown or invalid indices: " + count_of(ids.count(), "reference", "references")));
      ok = false;
    }
    return ok;
  }

  // ---- 2. degenerate and duplicate triangles --------------------------------------------

  bool check_degenerate_triangles()
  {
    Problem_class degenerate(limit_);
    const auto collinear = GeomTraits().collinear_3_object();
    for(std::size_t t = 0; t < m_.number_of_triangles(); ++t)
    {
      const auto& tri = m_.triangle(t);
      if(tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      {
        const std::size_t v = (tri[0] == tri[1] || tri[0] == tri[2]) ? tri[0] : tri[1];
        degenerate.add(at(t) + triangle_label(t) + " uses " + vertex_label(v) + " twice");
      }
      else if(collinear(m_.point(tri[0]), m_.point(tri[1]), m_.point(tri[2])))
        degenerate.add(at(t) + triangle_label(t) + " has zero area: " + vertex_label(tri[0]) + ", " +
                       vertex_label(tri[1]) + " and " + vertex_label(tri[2]) + " are collinear");
    }
    if(degenerate.empty()) return true;
    problems_.push_back(degenerate.message("degenerate triangles: " + count_of(degenerate.count(), "triangle has", "triangles have") +
                                           " a repeated vertex or zero area"));
    return false;
  }

  bool check_duplicate_triangles()
  {
    typedef std::pair<std::array<std::size_t, 3>, std::size_t> Key;
    std::vector<Key> keys(m_.number_of_triangles());
    for(std::size_t t = 0; t < keys.size(); ++t)
    {
      keys[t].first = m_.triangle(t);
      std::sort(keys[t].first.begin(), keys[t].first.end());
      keys[t].second = t;
    }
    std::sort(keys.begin(), keys.end());
    Problem_class duplicates(limit_);
    for(std::size_t i = 1; i < keys.size(); ++i)
      if(keys[i].first == keys[i - 1].first)
      {
        const std::size_t t0 = keys[i - 1].second, t1 = keys[i].second;
        const auto& v = keys[i].first;
        std::string line = at(t1) + triangle_label(t1) + " duplicates " + triangle_label(t0) + also_at(t0, t1);
        line += ": both have vertices " + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " +
                std::to_string(v[2]);
        duplicates.add(line);
      }
    if(duplicates.empty()) return true;
    problems_.push_back(duplicates.message(
        "duplicate triangles: " + count_of(duplicates.count(), "triangle repeats", "triangles repeat") +
        " another one (an interface triangle must appear once, in the patch between its two regions)"));
    return false;
  }

  // ---- 3. region boundaries ---------------------------------------------------------------

  void build_sides()
  {
    sides_.clear();
    for(std::size_t t = 0; t < m_.number_of_triangles(); ++t)
    {
      const auto& patch = m_.patch(m_.patch_of_triangle(t));
      if(patch.is_inside_region()) continue;
      const auto& tri = m_.triangle(t);
      // the normal points out of the negative region and into the positive one
      if(patch.negative_region != 0) sides_.push_back(Side{patch.negative_region, t, tri});
      if(patch.positive_region != 0)
        sides_.push_back(Side{patch.positive_region, t, std::array<std::size_t, 3>{{tri[0], tri[2], tri[1]}}});
    }
    std::stable_sort(sides_.begin(), sides_.end(),
                     [](const Side& a, const Side& b) { return a.region < b.region; });
  }

  std::size_t corner_of(std::size_t side, std::size_t vertex) const
  {
    const auto& v = sides_[side].v;
    return 3 * side + (v[0] == vertex ? 0 : (v[1] == vertex ? 1 : 2));
  }

  bool check_region_boundaries()
  {
    build_sides();
    const std::size_t nr = m_.number_of_regions();

    Problem_class empty(limit_);
    {
      std::vector<bool> has_side(nr + 1, false);
      for(const Side& s : sides_) has_side[s.region] = true;
      for(std::size_t r = 1; r <= nr; ++r)
        if(!has_side[r])
          empty.add(m_.region_label(r) + " has no boundary: no patch has it on exactly one side");
    }
    if(!empty.empty())
    {
      problems_.push_back(empty.message("regions without boundary: " + count_of(empty.count(), "region", "regions")));
      return false;
    }

    std::vector<Edge_use> uses;
    uses.reserve(3 * sides_.size());
    for(std::size_t s = 0; s < sides_.size(); ++s)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t a = sides_[s].v[k], b = sides_[s].v[(k + 1) % 3];
        uses.push_back(Edge_use{sides_[s].region, (std::min)(a, b), (std::max)(a, b), s, a < b});
      }
    std::sort(uses.begin(), uses.end());

    Problem_class open(limit_), nonmanifold_edge(limit_), orientation(limit_);
    std::vector<std::size_t> corner_parent(3 * sides_.size());
    std::iota(corner_parent.begin(), corner_parent.end(), std::size_t(0));
    side_parent_.resize(sides_.size());
    std::iota(side_parent_.begin(), side_parent_.end(), std::size_t(0));

    for(std::size_t i = 0; i < uses.size();)
    {
      std::size_t j = i + 1;
      while(j < uses.size() && uses[j].same_edge(uses[i])) ++j;
      const Edge_use& e = uses[i];
      const std::size_t t0 = sides_[e.side].triangle;
      if(j - i == 1)
        open.add(at(t0) + m_.region_label(e.region) + ": " + edge_label(e.a, e.b) + " of " + triangle_label(t0) +
                 " has no neighbour across it");
      else if(j - i > 2)
      {
        std::string line = at(t0) + m_.region_label(e.region) + ": " + edge_label(e.a, e.b) + " is shared by " +
                           std::to_string(j - i) + " triangles:";
        for(std::size_t k = i; k < j; ++k) line += (k == i ? " " : ", ") + triangle_label(sides_[uses[k].side].triangle);
        nonmanifold_edge.add(line);
      }
      else
      {
        const Edge_use& f = uses[i + 1];
        if(e.forward == f.forward)
          orientation.add(at(t0) + m_.region_label(e.region) + ": " + triangle_label(t0) + " and " +
                          triangle_label(sides_[f.side].triangle) + " both run along " + edge_label(e.a, e.b) +
                          " in the same direction");
        uf_union(corner_parent, corner_of(e.side, e.a), corner_of(f.side, e.a));
        uf_union(corner_parent, corner_of(e.side, e.b), corner_of(f.side, e.b));
        uf_union(side_parent_, e.side, f.side);
      }
      i = j;
    }

    if(!open.empty())
    {
      problems_.push_back(open.message("region boundaries are not closed: " + count_of(open.count(), "edge is", "edges are") +
                                       " used by one boundary triangle only"));
      return false;
    }
    if(!nonmanifold_edge.empty())
    {
      problems_.push_back(nonmanifold_edge.message(
          "region boundaries are not manifold: " + count_of(nonmanifold_edge.count(), "edge is", "edges are") +
          " shared by more than two boundary triangles of the same region"));
      return false;
    }

    // closed and edge-manifold: the triangles around a vertex form cycles; more than one is a pinch
    {
      // one pass per region (sides are sorted by region): a corner whose fan differs from the
      // first fan seen at its vertex marks a pinch
      const std::size_t none = std::size_t(-1);
      std::vector<std::size_t> seen_in(m_.number_of_points(), none), first_fan(m_.number_of_points());
      std::vector<std::size_t> pinched_in(m_.number_of_points(), none);
      Problem_class pinched(limit_);
      for(std::size_t s0 = 0; s0 < sides_.size();)
      {
        const std::size_t r = sides_[s0].region;
        std::size_t s1 = s0;
        std::vector<std::size_t> pinched_vertices;
        for(; s1 < sides_.size() && sides_[s1].region == r; ++s1)
          for(std::size_t k = 0; k < 3; ++k)
          {
            const std::size_t v = sides_[s1].v[k];
            const std::size_t fan = uf_find(corner_parent, 3 * s1 + k);
            if(seen_in[v] != r)
            {
              seen_in[v] = r;
              first_fan[v] = fan;
            }
            else if(fan != first_fan[v] && pinched_in[v] != r)
            {
              pinched_in[v] = r;
              pinched_vertices.push_back(v);
            }
          }
        for(std::size_t v : pinched_vertices)
        {
          if(pinched.count() >= limit_)
          {
            pinched.add(std::string()); // counted, not shown
            continue;
          }
          // rare: list the fans at v with one triangle each
          std::vector<std::pair<std::size_t, std::size_t> > fans; // fan, side
          for(std::size_t s = s0; s < s1; ++s)
            for(std::size_t k = 0; k < 3; ++k)
              if(sides_[s].v[k] == v) fans.emplace_back(uf_find(corner_parent, 3 * s + k), s);
          std::sort(fans.begin(), fans.end());
          std::string examples;
          std::size_t count = 0;
          for(std::size_t i = 0; i < fans.size(); ++i)
            if(i == 0 || fans[i].first != fans[i - 1].first)
              examples += (count++ == 0 ? "" : " and ") + triangle_label(sides_[fans[i].second].triangle);
          pinched.add(at(sides_[fans.front().second].triangle) + m_.region_label(r) + ": " + vertex_label(v) +
                      " joins " + std::to_string(count) + " separate fans of boundary triangles (" + examples + ")");
        }
        s0 = s1;
      }
      if(!pinched.empty())
      {
        problems_.push_back(pinched.message("region boundaries are not manifold: " +
                                            count_of(pinched.count(), "vertex is", "vertices are") +
                                            " pinched (their boundary triangles form several fans)"));
        return false;
      }
    }

    if(!orientation.empty())
    {
      problems_.push_back(orientation.message(
          "region boundaries are not consistently oriented: " + count_of(orientation.count(), "edge is", "edges are") +
          " run in the same direction by both their triangles (seen from the region; a triangle "
          "(a,b,c) has normal (b-a)x(c-a) pointing to the positive region of its patch)"));
      return false;
    }

    const std::vector<double> volumes = region_volumes(m_);
    Problem_class nonpositive(limit_);
    for(std::size_t r = 1; r <= nr; ++r)
      if(!(volumes[r] > 0.))
      {
        // name the patches, so that one sees which one has its regions the wrong way round
        std::vector<std::size_t> patches;
        for(const Side& s : sides_)
          if(s.region == r) patches.push_back(m_.patch_of_triangle(s.triangle));
        std::sort(patches.begin(), patches.end());
        patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
        std::ostringstream os;
        os << m_.region_label(r) << " has volume " << volumes[r]
           << ": its boundary faces inward (the region is on the wrong side of its patches:";
        for(std::size_t k = 0; k < patches.size() && k < limit_; ++k)
        {
          const auto& patch = m_.patch(patches[k]);
          os << (k == 0 ? " " : ", ") << m_.patch_label(patches[k]) << " has it as "
             << (patch.positive_region == r ? "positive" : "negative") << " region";
        }
        if(patches.size() > limit_) os << ", ...";
        os << ")";
        nonpositive.add(m_.where(typename Model::Source()) + os.str());
      }
    if(!nonpositive.empty())
    {
      problems_.push_back(nonpositive.message("regions with non-positive volume: " +
                                              count_of(nonpositive.count(), "region", "regions")));
      return false;
    }

    return check_nesting();
  }

  // The signed volume of a set of sides, relative to the point `o` (the centre of the model's
  // box, so that far-off coordinates lose no digits), and their bounding box.
  std::pair<double, Bbox_3> volume_and_box(const std::vector<std::size_t>& side_ids,
                                           const internal::Centred_point& o) const
  {
    double vol = 0.;
    Bbox_3 box;
    for(std::size_t s : side_ids)
    {
      const Side& side = sides_[s];
      for(int k = 0; k < 3; ++k) box += m_.point(side.v[k]).bbox();
      vol += internal::signed_volume(internal::centred(m_.point(side.v[0]), o), internal::centred(m_.point(side.v[1]), o),
                                     internal::centred(m_.point(side.v[2]), o));
    }
    return std::make_pair(vol, box);
  }

  std::unique_ptr<Mesh> make_mesh(const std::vector<std::size_t>& side_ids) const
  {
    std::vector<std::size_t> index(m_.number_of_points(), std::size_t(-1));
    std::vector<Point_3> points;
    std::vector<std::array<std::size_t, 3> > faces;
    for(std::size_t s : side_ids)
    {
      std::array<std::size_t, 3> f;
      for(int k = 0; k < 3; ++k)
      {
        std::size_t& i = index[sides_[s].v[k]];
        if(i == std::size_t(-1))
        {
          i = points.size();
          points.push_back(m_.point(sides_[s].v[k]));
        }
        f[k] = i;
      }
      faces.push_back(f);
    }
    std::unique_ptr<Mesh> mesh(new Mesh());
    Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, *mesh);
    return mesh;
  }

  // A region bounded by several closed surfaces (a body with a cavity, or in pieces): each
  // surface must face outward where it is not enclosed by the others, inward where it is.
  bool check_nesting()
  {
    // components of each region's boundary, in order of their first side
    std::vector<std::vector<std::size_t> > components;
    {
      std::vector<std::size_t> component_of_root(sides_.size(), std::size_t(-1));
      for(std::size_t s = 0; s < sides_.size(); ++s)
      {
        const std::size_t root = uf_find(side_parent_, s);
        if(component_of_root[root] == std::size_t(-1))
        {
          component_of_root[root] = components.size();
          components.emplace_back();
        }
        components[component_of_root[root]].push_back(s);
      }
    }
    Problem_class wrong(limit_);
    for(std::size_t c0 = 0; c0 < components.size();)
    {
      const std::size_t r = sides_[components[c0].front()].region;
      std::size_t c1 = c0 + 1;
      while(c1 < components.size() && sides_[components[c1].front()].region == r) ++c1;
      if(c1 - c0 > 1)
      {
        const internal::Centred_point o = internal::box_centre(m_);
        std::vector<double> volume;
        std::vector<Bbox_3> box;
        for(std::size_t c = c0; c < c1; ++c)
        {
          const std::pair<double, Bbox_3> vb = volume_and_box(components[c], o);
          volume.push_back(vb.first);
          box.push_back(vb.second);
        }
        // point location in a component, built only for the components whose box holds a query
        std::vector<std::unique_ptr<Mesh> > meshes(c1 - c0);
        std::vector<std::unique_ptr<Side_of_mesh> > side_of(c1 - c0);
        auto side = [&](std::size_t d, const Point_3& p) {
          if(!CGAL::do_overlap(box[d - c0], p.bbox())) return ON_UNBOUNDED_SIDE;
          if(!side_of[d - c0])
          {
            meshes[d - c0] = make_mesh(components[d]);
            side_of[d - c0].reset(new Side_of_mesh(*meshes[d - c0]));
          }
          return (*side_of[d - c0])(p);
        };
        for(std::size_t c = c0; c < c1; ++c)
        {
          // winding number of the other surfaces at a vertex of this one
          int winding = 0;
          std::size_t tested = std::size_t(-1);
          for(std::size_t s : components[c])
          {
            const std::size_t v = sides_[s].v[0];
            int w = 0;
            bool on_boundary = false;
            for(std::size_t d = c0; d < c1 && !on_boundary; ++d)
            {
              if(d == c) continue;
              const Bounded_side bs = side(d, m_.point(v));
              if(bs == ON_BOUNDARY) on_boundary = true; // a contact; the intersection check reports it
              else if(bs == ON_BOUNDED_SIDE) w += volume[d - c0] > 0. ? 1 : -1;
            }
            if(!on_boundary)
            {
              winding = w;
              tested = v;
              break;
            }
          }
          if(tested == std::size_t(-1)) continue;
          const bool outward = volume[c - c0] > 0.;
          if((outward && winding != 0) || (!outward && winding != 1))
          {
            const std::size_t t = sides_[components[c].front()].triangle;
            std::ostringstream os;
            os << at(t) << m_.region_label(r) << ": the boundary surface through " << triangle_label(t) << " ("
               << components[c].size() << " triangles, signed volume " << volume[c - c0] << ") faces "
               << (outward ? "outward" : "inward") << " but lies "
               << (winding == 0 ? "outside the region's other boundary surfaces"
                                : "inside the region's other boundary surfaces")
               << " (tested at " << vertex_label(tested) << ")";
            wrong.add(os.str());
          }
        }
      }
      c0 = c1;
    }
    if(wrong.empty()) return true;
    problems_.push_back(wrong.message(
        "region boundaries are wrongly nested: " + count_of(wrong.count(), "closed surface faces the wrong way for where it lies",
                                                          "closed surfaces face the wrong way for where they lie") +
        " (an outer surface must face outward, the surface of "
        "a cavity inward)"));
    return false;
  }

  // ---- 4. surfaces inside regions ---------------------------------------------------------

  void check_surfaces_inside_regions()
  {
    const std::size_t nr = m_.number_of_regions();
    std::vector<std::vector<std::size_t> > inside_triangles(nr + 1);
    for(std::size_t t = 0; t < m_.number_of_triangles(); ++t)
    {
      const auto& patch = m_.patch(m_.patch_of_triangle(t));
      if(patch.is_inside_region()) inside_triangles[patch.positive_region].push_back(t);
    }
    Problem_class outside(limit_);
    std::vector<int> on_boundary(m_.number_of_points(), -1); // region whose boundary was marked
    std::vector<bool> tested(m_.number_of_points(), false);
    for(std::size_t r = 1; r <= nr; ++r)
    {
      if(inside_triangles[r].empty()) continue;
      std::vector<std::size_t> boundary;
      for(std::size_t s = 0; s < sides_.size(); ++s)
        if(sides_[s].region == r)
        {
          boundary.push_back(s);
          for(std::size_t v : sides_[s].v) on_boundary[v] = int(r);
        }
      std::unique_ptr<Mesh> mesh = make_mesh(boundary);
      Side_of_mesh side_of(*mesh);
      std::fill(tested.begin(), tested.end(), false);
      for(std::size_t t : inside_triangles[r])
        for(std::size_t v : m_.triangle(t))
        {
          if(on_boundary[v] == int(r) || tested[v]) continue;
          tested[v] = true;
          if(side_of(m_.point(v)) == ON_UNBOUNDED_SIDE)
            outside.add(at(t) + m_.patch_label(m_.patch_of_triangle(t)) + " lies inside " + m_.region_label(r) +
                        " but its " + vertex_label(v) + " (of triangle " + std::to_string(t) +
                        ") is outside that region");
        }
    }
    if(!outside.empty())
      problems_.push_back(outside.message("surfaces inside a region leave it: " + count_of(outside.count(), "vertex lies", "vertices lie") +
                                          " outside the region"));
  }

  // ---- 5. intersections -------------------------------------------------------------------

  // true when triangles s and t meet elsewhere than in their common vertices and edge
  bool do_improperly_intersect(std::size_t s, std::size_t t) const
  {
    const auto& a = m_.triangle(s);
    const auto& b = m_.triangle(t);
    int shared = 0;
    int ia[3], ib[3]; // positions of the shared vertices in a and b
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        if(a[i] == b[j])
        {
          ia[shared] = i;
          ib[shared] = j;
          ++shared;
        }
    const GeomTraits gt;
    auto P = [this](std::size_t v) -> const Point_3& { return m_.point(v); };
    if(shared == 0)
      return gt.do_intersect_3_object()(Triangle_3(P(a[0]), P(a[1]), P(a[2])), Triangle_3(P(b[0]), P(b[1]), P(b[2])));
    if(shared == 1)
    {
      // Both triangles are convex and contain the common vertex, so any other common point x
      // makes a segment [v,x] common: its far end lies on the opposite edge of one of them.
      const std::size_t a1 = a[(ia[0] + 1) % 3], a2 = a[(ia[0] + 2) % 3];
      const std::size_t b1 = b[(ib[0] + 1) % 3], b2 = b[(ib[0] + 2) % 3];
      // quick exit, the common case: one triangle lies strictly on one side of the other's plane
      const auto orientation = gt.orientation_3_object();
      const Orientation o1 = orientation(P(a[0]), P(a[1]), P(a[2]), P(b1));
      if(o1 != COPLANAR && o1 == orientation(P(a[0]), P(a[1]), P(a[2]), P(b2))) return false;
      const Orientation o2 = orientation(P(b[0]), P(b[1]), P(b[2]), P(a1));
      if(o2 != COPLANAR && o2 == orientation(P(b[0]), P(b[1]), P(b[2]), P(a2))) return false;
      const auto do_intersect = gt.do_intersect_3_object();
      return do_intersect(Segment_3(P(a1), P(a2)), Triangle_3(P(b[0]), P(b[1]), P(b[2]))) ||
             do_intersect(Segment_3(P(b1), P(b2)), Triangle_3(P(a[0]), P(a[1]), P(a[2])));
    }
    if(shared == 2)
    {
      // two planes through a common edge meet only along its line: only a fold-over overlaps
      const std::size_t p = a[ia[0]], q = a[ia[1]];
      const std::size_t c = a[3 - ia[0] - ia[1]], d = b[3 - ib[0] - ib[1]];
      if(gt.orientation_3_object()(P(p), P(q), P(c), P(d)) != COPLANAR) return false;
      return gt.coplanar_orientation_3_object()(P(p), P(q), P(c), P(d)) == POSITIVE;
    }
    return true; // same vertices: reported by the duplicate check already
  }

  bool are_coplanar(std::size_t s, std::size_t t) const
  {
    const auto orientation = GeomTraits().orientation_3_object();
    const auto& a = m_.triangle(s);
    for(std::size_t v : m_.triangle(t))
      if(orientation(m_.point(a[0]), m_.point(a[1]), m_.point(a[2]), m_.point(v)) != COPLANAR) return false;
    return true;
  }

  std::string contact_point(std::size_t s, std::size_t t) const
  {
    // exact constructions on the (double) coordinates: a touching contact is found too
    typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
    auto to_exact = [](const Point_3& p) {
      return EK::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    };
    auto tri = [&](std::size_t i) {
      const auto& v = m_.triangle(i);
      return EK::Triangle_3(to_exact(m_.point(v[0])), to_exact(m_.point(v[1])), to_exact(m_.point(v[2])));
    };
    const auto result = CGAL::intersection(tri(s), tri(t));
    if(!result) return "?";
    std::vector<EK::Point_3> pts;
    if(const EK::Point_3* p = boost::get<EK::Point_3>(&*result)) pts.push_back(*p);
    else if(const EK::Segment_3* g = boost::get<EK::Segment_3>(&*result)) { pts.push_back(g->source()); pts.push_back(g->target()); }
    else if(const EK::Triangle_3* r = boost::get<EK::Triangle_3>(&*result)) for(int i = 0; i < 3; ++i) pts.push_back(r->vertex(i));
    else if(const std::vector<EK::Point_3>* v = boost::get<std::vector<EK::Point_3> >(&*result)) pts = *v;
    if(pts.empty()) return "?";
    double c[3] = {0., 0., 0.};
    for(const EK::Point_3& p : pts)
    {
      c[0] += CGAL::to_double(p.x()) / double(pts.size());
      c[1] += CGAL::to_double(p.y()) / double(pts.size());
      c[2] += CGAL::to_double(p.z()) / double(pts.size());
    }
    return point_to_string(EK::Point_3(c[0], c[1], c[2]));
  }

  void check_intersections()
  {
    typedef CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t> Box;
    std::vector<Box> boxes;
    boxes.reserve(m_.number_of_triangles());
    for(std::size_t t = 0; t < m_.number_of_triangles(); ++t)
    {
      const auto& v = m_.triangle(t);
      boxes.push_back(Box(m_.point(v[0]).bbox() + m_.point(v[1]).bbox() + m_.point(v[2]).bbox(), t));
    }
    std::vector<std::pair<std::size_t, std::size_t> > bad;
    auto callback = [&](const Box& x, const Box& y) {
      if(do_improperly_intersect(x.info(), y.info()))
        bad.emplace_back((std::min)(x.info(), y.info()), (std::max)(x.info(), y.info()));
    };
    // the cutoff under which the segment tree scans directly: PMP's self-intersection test uses 2000 too
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(boxes.begin(), boxes.end(), callback, std::ptrdiff_t(2000));
    if(bad.empty()) return;
    std::sort(bad.begin(), bad.end());
    Problem_class crossing(limit_);
    for(std::size_t i = 0; i < bad.size(); ++i)
    {
      const std::size_t s = bad[i].first, t = bad[i].second;
      std::string line = at(s) + triangle_label(s) + " and " + triangle_label(t) + also_at(t, s);
      // the contact point is an exact construction: only for the lines shown
      if(i < limit_) line += (are_coplanar(s, t) ? " overlap near " : " intersect near ") + contact_point(s, t);
      crossing.add(line);
    }
    problems_.push_back(crossing.message(
        "surfaces intersect: " + count_of(crossing.count(), "pair", "pairs") +
        " of triangles meet elsewhere than in a common edge or vertex (crossing, overlapping or "
        "self-intersecting surfaces, or a vertex lying on another surface)"));
  }

  const Model& m_;
  std::size_t limit_;
  bool stop_at_first_;
  bool verbose_;
  Real_timer timer_;
  std::vector<std::string> problems_;
  std::vector<Side> sides_;
  std::vector<std::size_t> side_parent_;
};

template <class GeomTraits, class NamedParameters>
std::vector<std::string> geological_model_problems(const Geological_model_3<GeomTraits>& model,
                                                   const NamedParameters& np, bool stop_at_first)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::size_t limit = choose_parameter(
      get_parameter(np, Bubble_mesh_3::internal_np::maximum_number_of_reported_elements), std::size_t(10));
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  Geological_model_validator<GeomTraits> validator(model, limit, stop_at_first, verbose);
  return validator.run();
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Lists the problems that make `model` an invalid geological model, one message
per class of problem, in the order the checks run (see
`validate_geological_model()`). A class whose failure would make the later
checks meaningless (bad indices, degenerate or duplicate triangles, a region
boundary that is not a closed, manifold, outward oriented surface) ends the
list. The list is empty when the model is valid.

\param model the model to check
\param np the named parameters of `validate_geological_model()`
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<std::string> geological_model_problems(const Geological_model_3<GeomTraits>& model,
                                                   const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::geological_model_problems(model, np, false);
}

/*!
\ingroup PkgBubbleMesh3Ref

Checks that `model` is a valid geological model and throws
`Geological_model_error` on the first class of problem found. The message
gives the number of offending elements and lists the first few, each with
where it comes from (`file:line: ` when the model was read from a file),
the region or patch name, the triangle or vertex index and coordinates.

The checks, in this order (cheap first):
- there is a region and a triangle; coordinates are finite; every index
  (vertex of a triangle, patch of a triangle, region of a patch) exists;
  no patch has the outside on both sides;
- no triangle is degenerate (a repeated vertex, or three collinear points
  by the kernel's exact predicate) and no two triangles have the same three
  vertices;
- every region is bounded (some patch has it on exactly one side); its
  boundary triangles form a closed surface (every edge used twice), an edge
  and vertex manifold one, consistently oriented (outward as seen from the
  region), of positive volume; when it has several closed components, each
  faces outward where the others do not enclose it and inward (a cavity)
  where they do;
- every surface inside a region (a patch with the region on both sides) has
  all its vertices inside or on the boundary of that region;
- no two triangles meet except in a common edge or a common vertex
  (crossing, overlapping, self-intersecting surfaces, and T-junctions),
  found by box intersection and the kernel's exact predicates.

\cgalNamedParamsBegin
  \cgalParamNBegin{maximum_number_of_reported_elements}
    \cgalParamDescription{how many offending elements the message lists; the count is always given}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{10}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{print the time of each check to `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{false}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
void validate_geological_model(const Geological_model_3<GeomTraits>& model,
                               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  const std::vector<std::string> problems = internal::geological_model_problems(model, np, true);
  if(!problems.empty()) throw Geological_model_error(problems.front());
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_VALIDATE_GEOLOGICAL_MODEL_H
