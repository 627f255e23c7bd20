// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_CHART_TRIANGULATION_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_CHART_TRIANGULATION_H

// Triangulation of one chart from its fixed curve points: a 2D constrained
// Delaunay triangulation in the chart plane whose vertices are lifted back
// onto the input triangles of the chart. Interior points come from a size
// refinement (circumcentres of triangles too large for the sizing field),
// then move as surface bubbles under the cubic force law (distances in 3D,
// moves kept in the chart's domain and lifted onto the patch) with
// population control, and a last pass inserts circumcentres of triangles
// whose angles are still too small.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_charts.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_triangle_tree.h>
#include <CGAL/Bubble_mesh_3/internal/resample_curves.h>
#include <CGAL/Bubble_mesh_3/internal/vertex_angle.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <iterator>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

template <class Point_3>
double remesh_circumradius(const Point_3& a, const Point_3& b, const Point_3& c)
{
  const double la = std::sqrt(CGAL::to_double(CGAL::squared_distance(b, c)));
  const double lb = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, c)));
  const double lc = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
  const double area2 = std::sqrt(CGAL::to_double(CGAL::cross_product(b - a, c - a).squared_length()));
  if(!(area2 > 0.)) return std::numeric_limits<double>::infinity();
  return la * lb * lc / (2. * area2);
}

struct Remesh_chart_face_info
{
  int level = -1;
  double size = -1.; // the sizing field at the 3D centroid, once asked
  bool in_domain() const { return level % 2 == 1; }
};

template <class GeomTraits, class SizeFunction>
class Chart_triangulator
{
public:
  typedef typename GeomTraits::Point_2 Point_2;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef typename GeomTraits::Line_3 Line_3;
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, GeomTraits> Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<Remesh_chart_face_info, GeomTraits> Fbi;
  typedef CGAL::Constrained_triangulation_face_base_2<GeomTraits, Fbi> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<GeomTraits, Tds,
                                                     CGAL::No_constraint_intersection_requiring_constructions_tag> Cdt;
  typedef typename Cdt::Face_handle Face_handle;
  typedef typename Cdt::Vertex_handle Vertex_handle;
  typedef std::array<std::size_t, 3> Segment; // local a, local b, number of chart triangles on it
  typedef std::array<std::size_t, 3> Triangle;

  struct Parameters
  {
    double angle_bound = 25.;          // smallest angle aimed at (degrees)
    std::size_t relaxation_steps = 40; // bubble steps per round
    std::size_t population_rounds = 3; // rounds of relaxation and population control
    bool bubbles = true;               // false: size refinement only (for the isotropic method)
  };

  Chart_triangulator(const Geological_model_3<GeomTraits>& model, const Remesh_chart<GeomTraits>& chart,
                     const Remesh_triangle_tree<GeomTraits>& chart_tree,
                     const Remesh_triangle_tree<GeomTraits>& patch_tree, const SizeFunction& size,
                     const Parameters& parameters)
    : chart_(chart), chart_tree_(chart_tree), patch_tree_(patch_tree), size_(size), param_(parameters)
  {
    // the chart's input triangles in the plane, with their neighbours, for walking
    std::map<std::pair<std::size_t, std::size_t>, std::pair<std::size_t, int> > edges;
    pieces_.resize(chart.triangles.size());
    for(std::size_t i = 0; i < chart.triangles.size(); ++i)
    {
      const auto& tri = model.triangle(chart.triangles[i]);
      Piece& piece = pieces_[i];
      for(int k = 0; k < 3; ++k)
      {
        piece.p3[k] = model.point(tri[k]);
        piece.p2[k] = chart.to_2d(piece.p3[k]);
        piece.nb[k] = -1;
      }
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t a = tri[(k + 1) % 3], b = tri[(k + 2) % 3]; // the edge opposite vertex k
        const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
        auto it = edges.find(key);
        if(it == edges.end()) edges[key] = std::make_pair(i, k);
        else
        {
          piece.nb[k] = long(it->second.first);
          pieces_[it->second.first].nb[it->second.second] = long(i);
        }
      }
    }
  }

  // The fixed points (3D, on the input) and the constrained segments between
  // them; false if they do not make a valid planar domain (the chart is cut
  // again then).
  bool set_boundary(const std::vector<Point_3>& points, const std::vector<Segment>& segments)
  {
    fixed_count_ = points.size();
    pos3_ = points;
    pos2_.clear();
    for(const Point_3& p : points) pos2_.push_back(chart_.to_2d(p));
    radius_.assign(points.size(), 0.);
    segments_ = segments;
    for(const Segment& s : segments_)
      parity_[std::make_pair((std::min)(s[0], s[1]), (std::max)(s[0], s[1]))] = s[2] % 2;
    std::vector<Vertex_handle> vh(points.size());
    try
    {
      for(std::size_t i = 0; i < points.size(); ++i)
      {
        const std::size_t before = domain_.number_of_vertices();
        vh[i] = domain_.insert(pos2_[i]);
        if(domain_.number_of_vertices() == before) return false; // two points on one spot of the plane
        vh[i]->info() = i;
      }
      for(const Segment& s : segments_) domain_.insert_constraint(vh[s[0]], vh[s[1]]);
    }
    catch(const typename Cdt::Intersection_of_constraints_exception&)
    {
      return false;
    }
    std::size_t constrained = 0;
    for(auto e = domain_.finite_edges_begin(); e != domain_.finite_edges_end(); ++e)
      if(domain_.is_constrained(*e)) ++constrained;
    if(constrained != segments_.size()) return false; // a segment went through another point
    mark_domain(domain_);
    where3_.assign(points.size(), -1);
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      radius_[i] = 0.5 * size_(pos3_[i]);
      where3_[i] = long(chart_tree_.closest_point_and_local_triangle(pos3_[i]).second);
    }
    return true;
  }

  // Fills the chart; the new points come after the fixed ones.
  void run()
  {
    Cdt cdt = domain_;
    refine_sizes(cdt, 0.7);
    if(param_.bubbles)
    {
      for(std::size_t round = 0; round < param_.population_rounds; ++round)
      {
        relax(param_.relaxation_steps);
        const bool changed = control_population();
        cdt = domain_;
        insert_free_points(cdt);
        if(refine_sizes(cdt, 0.85)) continue;
        if(!changed && round > 0) break;
      }
      relax(param_.relaxation_steps / 2);
      cdt = domain_;
      insert_free_points(cdt);
      improve_angles(cdt);
    }
    triangles_.clear();
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if(f->info().in_domain())
        triangles_.push_back(Triangle{{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}});
  }

  std::size_t number_of_fixed_points() const { return fixed_count_; }
  const std::vector<Point_3>& points() const { return pos3_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }

private:
  bool toggles(const Cdt& cdt, Face_handle f, int i) const
  {
    if(!cdt.is_constrained(std::make_pair(f, i))) return false;
    const std::size_t a = f->vertex(cdt.cw(i))->info(), b = f->vertex(cdt.ccw(i))->info();
    const auto it = parity_.find(std::make_pair((std::min)(a, b), (std::max)(a, b)));
    return it != parity_.end() && it->second == 1;
  }

  // nesting level of every face: crossing a border segment (odd number of
  // chart triangles on it) changes the level; odd levels are in the chart
  void mark_domain(Cdt& cdt) const
  {
    for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().level = -1;
    std::deque<std::pair<Face_handle, int> > border;
    border.push_back(std::make_pair(cdt.infinite_face(), 0));
    while(!border.empty())
    {
      const Face_handle start = border.front().first;
      const int level = border.front().second;
      border.pop_front();
      if(start->info().level != -1) continue;
      std::deque<Face_handle> queue(1, start);
      start->info().level = level;
      while(!queue.empty())
      {
        const Face_handle f = queue.front();
        queue.pop_front();
        for(int i = 0; i < 3; ++i)
        {
          const Face_handle n = f->neighbor(i);
          if(n->info().level != -1) continue;
          if(toggles(cdt, f, i)) border.push_back(std::make_pair(n, level + 1));
          else
          {
            n->info().level = level;
            queue.push_back(n);
          }
        }
      }
    }
  }

  // Walks the chart's input triangles in the plane from `start` to the one
  // holding `q`; false if it leaves the chart (or wanders too long).
  bool walk(const Point_2& q, long& t, std::array<double, 3>& bary) const
  {
    if(t < 0) return false;
    for(int step = 0; step < 400; ++step)
    {
      const Piece& piece = pieces_[std::size_t(t)];
      const double area = signed_area(piece.p2[0], piece.p2[1], piece.p2[2]);
      if(!(area > 0.)) return false;
      int worst = -1;
      double lowest = 0.;
      for(int k = 0; k < 3; ++k)
      {
        bary[k] = signed_area(q, piece.p2[(k + 1) % 3], piece.p2[(k + 2) % 3]) / area;
        if(bary[k] < lowest) { lowest = bary[k]; worst = k; }
      }
      if(worst < 0 || lowest > -1e-12) return true;
      if(piece.nb[worst] < 0) return false;
      t = piece.nb[worst];
    }
    return false;
  }

  static double signed_area(const Point_2& a, const Point_2& b, const Point_2& c)
  {
    return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
  }

  // The point of the chart's input triangles above `q`: by walking from the
  // triangle `hint_triangle` (updated), else by a line query (the hit
  // closest to `hint`), else the closest point of the patch.
  Point_3 lift(const Point_2& q, const Point_3& hint, long& hint_triangle) const
  {
    std::array<double, 3> bary;
    long t = hint_triangle;
    if(walk(q, t, bary))
    {
      hint_triangle = t;
      const Piece& piece = pieces_[std::size_t(t)];
      for(double& b : bary) b = (std::max)(0., b);
      const double sum = bary[0] + bary[1] + bary[2];
      return piece.p3[0] + (piece.p3[1] - piece.p3[0]) * (bary[1] / sum) + (piece.p3[2] - piece.p3[0]) * (bary[2] / sum);
    }
    const Point_3 base = chart_.plane_point(q);
    const Line_3 line(base, chart_.normal);
    typedef typename Remesh_triangle_tree<GeomTraits>::Tree Tree;
    typedef typename Tree::template Intersection_and_primitive_id<Line_3>::Type Hit;
    hits_.clear();
    chart_tree_.tree().all_intersections(line, std::back_inserter(hits_));
    double best = std::numeric_limits<double>::infinity();
    Point_3 result = base;
    for(const Hit& h : hits_)
    {
      const Point_3* p = boost::get<Point_3>(&h.first);
      if(p == nullptr) continue;
      const double d = CGAL::to_double(CGAL::squared_distance(*p, hint));
      if(d < best)
      {
        best = d;
        result = *p;
        hint_triangle = long(chart_tree_.local_index(h.second));
      }
    }
    if(best < std::numeric_limits<double>::infinity()) return result;
    // off the projected input (a chord cut a corner): nearest point of the patch
    const Point_3 q3 = base + chart_.normal * CGAL::to_double((hint - base) * chart_.normal);
    const auto cp = chart_tree_.closest_point_and_local_triangle(q3);
    hint_triangle = long(cp.second);
    return patch_tree_.closest_point(q3);
  }

  // located in the chart, not on a segment or a point
  bool locate_inside(const Cdt& cdt, const Point_2& q, Face_handle& f) const
  {
    typename Cdt::Locate_type lt;
    int li;
    f = cdt.locate(q, lt, li, f);
    if(lt != Cdt::FACE || cdt.is_infinite(f) || !f->info().in_domain()) return false;
    return true;
  }

  // too close to a segment of the face or its neighbours (a skinny triangle would follow)
  bool near_segment(const Cdt& cdt, Face_handle f, const Point_2& q, double clearance) const
  {
    for(int k = -1; k < 3; ++k)
    {
      const Face_handle g = (k < 0) ? f : f->neighbor(k);
      if(cdt.is_infinite(g)) continue;
      for(int i = 0; i < 3; ++i)
        if(cdt.is_constrained(std::make_pair(g, i)))
        {
          const typename GeomTraits::Segment_2 s(g->vertex(cdt.cw(i))->point(), g->vertex(cdt.ccw(i))->point());
          if(CGAL::to_double(CGAL::squared_distance(q, s)) < clearance * clearance) return true;
        }
    }
    return false;
  }

  // inside the diametral circle of a segment of the face or its neighbours
  // (the first such segment is returned in `a`, `b`)
  bool encroaches(const Cdt& cdt, Face_handle f, const Point_2& q, Point_2* a = nullptr, Point_2* b = nullptr) const
  {
    for(int k = -1; k < 3; ++k)
    {
      const Face_handle g = (k < 0) ? f : f->neighbor(k);
      if(cdt.is_infinite(g)) continue;
      for(int i = 0; i < 3; ++i)
        if(cdt.is_constrained(std::make_pair(g, i)))
        {
          const Point_2& s = g->vertex(cdt.cw(i))->point();
          const Point_2& t = g->vertex(cdt.ccw(i))->point();
          if(CGAL::to_double((s - q) * (t - q)) < 0.)
          {
            if(a) *a = s;
            if(b) *b = t;
            return true;
          }
        }
    }
    return false;
  }

  std::size_t add_free_point(const Point_2& q, const Point_3& p, long triangle)
  {
    pos2_.push_back(q);
    pos3_.push_back(p);
    radius_.push_back(0.5 * size_(p));
    where3_.push_back(triangle);
    return pos3_.size() - 1;
  }

  void remove_last_point()
  {
    pos2_.pop_back();
    pos3_.pop_back();
    radius_.pop_back();
    where3_.pop_back();
  }

  bool insert_point(Cdt& cdt, const Point_2& q, std::size_t id, Face_handle hint)
  {
    Face_handle f = hint;
    if(!locate_inside(cdt, q, f)) return false;
    const Vertex_handle v = cdt.insert(q, f);
    v->info() = id;
    // the conflict zone never crosses a segment: the new faces are in the chart
    typename Cdt::Face_circulator fc = cdt.incident_faces(v), done = fc;
    do { fc->info().level = 1; } while(++fc != done);
    return true;
  }

  // bubbles become points of `cdt` (those that ended on a segment or outside are dropped)
  void insert_free_points(Cdt& cdt)
  {
    std::vector<std::size_t> kept;
    for(std::size_t i = fixed_count_; i < pos3_.size(); ++i)
    {
      Face_handle f = Face_handle();
      if(!locate_inside(cdt, pos2_[i], f)) continue;
      const double h2d = radius_[i]; // half the size: clearance to segments
      if(near_segment(cdt, f, pos2_[i], 0.25 * h2d)) continue;
      if(!insert_point(cdt, pos2_[i], fixed_count_ + kept.size(), f)) continue;
      kept.push_back(i);
    }
    compact(kept);
  }

  void compact(const std::vector<std::size_t>& kept)
  {
    std::vector<Point_2> p2(pos2_.begin(), pos2_.begin() + fixed_count_);
    std::vector<Point_3> p3(pos3_.begin(), pos3_.begin() + fixed_count_);
    std::vector<double> r(radius_.begin(), radius_.begin() + fixed_count_);
    std::vector<long> w(where3_.begin(), where3_.begin() + fixed_count_);
    for(std::size_t i : kept)
    {
      p2.push_back(pos2_[i]);
      p3.push_back(pos3_[i]);
      r.push_back(radius_[i]);
      w.push_back(where3_[i]);
    }
    pos2_.swap(p2);
    pos3_.swap(p3);
    radius_.swap(r);
    where3_.swap(w);
  }

  // Insert circumcentres (or centroids when the circumcentre leaves the
  // chart) of triangles whose 3D circumradius exceeds `factor` times the
  // local size, pass after pass. Returns whether anything was inserted.
  bool refine_sizes(Cdt& cdt, double factor)
  {
    bool any = false;
    for(int pass = 0; pass < 60; ++pass)
    {
      // circumcentre and centroid of each triangle too large for the field
      std::vector<std::pair<Point_2, Point_2> > candidates;
      for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      {
        if(!f->info().in_domain()) continue;
        const Point_3& a = pos3_[f->vertex(0)->info()];
        const Point_3& b = pos3_[f->vertex(1)->info()];
        const Point_3& c = pos3_[f->vertex(2)->info()];
        if(f->info().size < 0.) f->info().size = size_(CGAL::centroid(a, b, c));
        if(!(remesh_circumradius(a, b, c) > factor * f->info().size)) continue;
        const Point_2& p0 = f->vertex(0)->point();
        const Point_2& p1 = f->vertex(1)->point();
        const Point_2& p2 = f->vertex(2)->point();
        candidates.push_back(std::make_pair(CGAL::circumcenter(p0, p1, p2), CGAL::centroid(p0, p1, p2)));
      }
      if(candidates.empty()) break;
      std::size_t inserted = 0;
      for(const auto& cand : candidates)
      {
        Point_2 q = cand.first;
        Face_handle loc = Face_handle();
        if(!locate_inside(cdt, q, loc) || encroaches(cdt, loc, q))
        {
          // the circumcentre leaves the chart or crowds a segment: the centroid then
          q = cand.second;
          loc = Face_handle();
          if(!locate_inside(cdt, q, loc)) continue;
        }
        if(try_insert(cdt, q, loc, 0.3)) ++inserted;
      }
      if(inserted == 0) break;
      any = true;
    }
    return any;
  }

  // inserts `q` (located in `loc`) unless it falls closer than `spacing`
  // times the local size to a vertex of its triangle
  bool try_insert(Cdt& cdt, const Point_2& q, Face_handle loc, double spacing)
  {
    const Point_3 hint = CGAL::centroid(pos3_[loc->vertex(0)->info()], pos3_[loc->vertex(1)->info()],
                                        pos3_[loc->vertex(2)->info()]);
    long triangle = where3_[loc->vertex(0)->info()];
    const Point_3 p = lift(q, hint, triangle);
    const double h = size_(p);
    for(int i = 0; i < 3; ++i)
      if(CGAL::to_double(CGAL::squared_distance(pos3_[loc->vertex(i)->info()], p)) < spacing * spacing * h * h)
        return false;
    const std::size_t id = add_free_point(q, p, triangle);
    if(!insert_point(cdt, q, id, loc))
    {
      remove_last_point();
      return false;
    }
    return true;
  }

  // Surface bubbles: overdamped steps under the cubic law, 3D distances,
  // moves projected on the chart plane, kept in the chart, lifted onto it.
  // Neighbour lists are refreshed every few steps with a margin.
  void relax(std::size_t steps)
  {
    typedef CGAL::Search_traits_3<GeomTraits> Base;
    typedef typename CGAL::Pointer_property_map<Point_3>::const_type Pmap;
    typedef CGAL::Search_traits_adapter<std::size_t, Pmap, Base> Traits;
    typedef CGAL::Kd_tree<Traits> Tree;
    typedef CGAL::Fuzzy_sphere<Traits> Sphere;
    const std::size_t n = pos3_.size();
    if(n <= fixed_count_) return;
    std::vector<Face_handle> where(n, Face_handle());
    std::vector<std::vector<std::size_t> > near(n);
    for(std::size_t step = 0; step < steps; ++step)
    {
      if(step % 4 == 0)
      {
        if(step > 0)
          for(std::size_t i = fixed_count_; i < n; ++i) radius_[i] = 0.5 * size_(pos3_[i]);
        Pmap pmap = CGAL::make_property_map(static_cast<const std::vector<Point_3>&>(pos3_));
        std::vector<std::size_t> ids(n);
        for(std::size_t i = 0; i < n; ++i) ids[i] = i;
        Tree tree(ids.begin(), ids.end(), typename Tree::Splitter(), Traits(pmap));
        tree.build();
        for(std::size_t i = fixed_count_; i < n; ++i)
        {
          near[i].clear();
          tree.search(std::back_inserter(near[i]), Sphere(pos3_[i], 5. * radius_[i], 0., Traits(pmap)));
        }
      }
      std::vector<Vector_3> move(n, Vector_3(0, 0, 0));
      double largest = 0.;
      for(std::size_t i = fixed_count_; i < n; ++i)
      {
        Vector_3 force(0, 0, 0);
        for(std::size_t j : near[i])
        {
          if(j == i) continue;
          const Vector_3 d = pos3_[i] - pos3_[j];
          const double l = std::sqrt(CGAL::to_double(d.squared_length()));
          const double rs = radius_[i] + radius_[j];
          if(!(l > 1e-12 * rs) || l >= 1.5 * rs) continue;
          const double f = remesh_cubic_force(l / rs) * rs;
          force = force + d * (f / l);
        }
        Vector_3 m = force * 0.2;
        // tangential to the chart plane: the lift puts the point back on the surface
        m = chart_.e1 * CGAL::to_double(m * chart_.e1) + chart_.e2 * CGAL::to_double(m * chart_.e2);
        const double len = std::sqrt(CGAL::to_double(m.squared_length()));
        const double limit = 0.3 * radius_[i];
        if(len > limit) m = m * (limit / len);
        move[i] = m;
        largest = (std::max)(largest, (std::min)(len, limit) / radius_[i]);
      }
      for(std::size_t i = fixed_count_; i < n; ++i)
      {
        Vector_3 m = move[i];
        if(m == CGAL::NULL_VECTOR) continue;
        for(int tries = 0; tries < 3; ++tries, m = m * 0.5)
        {
          const Point_2 q(pos2_[i].x() + CGAL::to_double(m * chart_.e1), pos2_[i].y() + CGAL::to_double(m * chart_.e2));
          Face_handle f = where[i];
          if(!locate_inside(domain_, q, f)) continue;
          where[i] = f;
          pos2_[i] = q;
          pos3_[i] = lift(q, pos3_[i] + m, where3_[i]);
          break;
        }
      }
      if(largest < 0.01) break;
    }
    for(std::size_t i = fixed_count_; i < n; ++i) radius_[i] = 0.5 * size_(pos3_[i]);
  }

  // Overlap ratio (METHOD.md): about 6 for a bubble well packed on a
  // surface. Bubbles far above are removed, from the most crowded on.
  bool control_population()
  {
    typedef CGAL::Search_traits_3<GeomTraits> Base;
    typedef typename CGAL::Pointer_property_map<Point_3>::const_type Pmap;
    typedef CGAL::Search_traits_adapter<std::size_t, Pmap, Base> Traits;
    typedef CGAL::Kd_tree<Traits> Tree;
    typedef CGAL::Fuzzy_sphere<Traits> Sphere;
    const std::size_t n = pos3_.size();
    if(n <= fixed_count_) return false;
    Pmap pmap = CGAL::make_property_map(static_cast<const std::vector<Point_3>&>(pos3_));
    std::vector<std::size_t> ids(n);
    for(std::size_t i = 0; i < n; ++i) ids[i] = i;
    Tree tree(ids.begin(), ids.end(), typename Tree::Splitter(), Traits(pmap));
    tree.build();
    std::vector<double> ratio(n, 0.);
    std::vector<std::vector<std::size_t> > nbs(n);
    for(std::size_t i = fixed_count_; i < n; ++i)
    {
      tree.search(std::back_inserter(nbs[i]), Sphere(pos3_[i], 4. * radius_[i], 0., Traits(pmap)));
      for(std::size_t j : nbs[i])
      {
        if(j == i) continue;
        const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(pos3_[i], pos3_[j])));
        ratio[i] += (std::max)(0., 2. * radius_[i] + radius_[j] - l) / radius_[i];
      }
    }
    std::vector<std::size_t> order;
    for(std::size_t i = fixed_count_; i < n; ++i)
      if(ratio[i] > 8.) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ratio[a] > ratio[b]; });
    std::vector<char> removed(n, 0), touched(n, 0);
    bool changed = false;
    for(std::size_t i : order)
    {
      if(touched[i]) continue;
      removed[i] = 1;
      changed = true;
      for(std::size_t j : nbs[i]) touched[j] = 1;
    }
    std::vector<std::size_t> kept;
    for(std::size_t i = fixed_count_; i < n; ++i)
      if(!removed[i]) kept.push_back(i);
    compact(kept);
    return changed;
  }

  // Circumcentres of triangles with too small an angle, where they do not
  // encroach a segment (Ruppert's rule without splitting segments: curve
  // points are shared with the neighbouring patches and must not change).
  void improve_angles(Cdt& cdt)
  {
    for(int pass = 0; pass < 8; ++pass)
    {
      std::vector<std::pair<double, Point_2> > candidates;
      for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      {
        if(!f->info().in_domain()) continue;
        const Point_3& a = pos3_[f->vertex(0)->info()];
        const Point_3& b = pos3_[f->vertex(1)->info()];
        const Point_3& c = pos3_[f->vertex(2)->info()];
        const double angle = min_angle_degrees(a, b, c);
        if(angle >= param_.angle_bound + 2.) continue;
        // all three vertices fixed: nothing to gain from the circumcentre if it leaves the chart
        candidates.push_back(std::make_pair(angle, CGAL::circumcenter(f->vertex(0)->point(), f->vertex(1)->point(),
                                                                       f->vertex(2)->point())));
      }
      if(candidates.empty()) break;
      std::stable_sort(candidates.begin(), candidates.end(),
                       [](const std::pair<double, Point_2>& x, const std::pair<double, Point_2>& y) {
                         return x.first < y.first;
                       });
      std::size_t inserted = 0;
      for(const auto& cand : candidates)
      {
        Face_handle loc = Face_handle();
        if(!locate_inside(cdt, cand.second, loc)) continue;
        Point_2 sa, sb;
        if(encroaches(cdt, loc, cand.second, &sa, &sb))
        {
          // the segment cannot be split: put a point where it makes a good
          // triangle with the segment instead, on the circumcentre's side
          const double dx = sb.x() - sa.x(), dy = sb.y() - sa.y();
          const Point_2 m((sa.x() + sb.x()) / 2., (sa.y() + sb.y()) / 2.);
          double nx = -dy, ny = dx;
          if(nx * (cand.second.x() - m.x()) + ny * (cand.second.y() - m.y()) < 0.) { nx = -nx; ny = -ny; }
          const Point_2 apex(m.x() + 0.75 * nx, m.y() + 0.75 * ny); // height 0.75 |ab|
          loc = Face_handle();
          if(!locate_inside(cdt, apex, loc) || encroaches(cdt, loc, apex)) continue;
          if(try_insert(cdt, apex, loc, 0.2)) ++inserted;
          continue;
        }
        if(try_insert(cdt, cand.second, loc, 0.2)) ++inserted;
      }
      if(inserted == 0) break;
    }
  }

  struct Piece
  {
    std::array<Point_2, 3> p2;
    std::array<Point_3, 3> p3;
    std::array<long, 3> nb; // neighbour across the edge opposite each vertex, -1 at the chart border
  };

  std::vector<Piece> pieces_;
  std::vector<long> where3_; // input triangle (of the chart) under each point
  const Remesh_chart<GeomTraits>& chart_;
  const Remesh_triangle_tree<GeomTraits>& chart_tree_;
  const Remesh_triangle_tree<GeomTraits>& patch_tree_;
  const SizeFunction& size_;
  Parameters param_;
  Cdt domain_;
  std::size_t fixed_count_ = 0;
  std::vector<Point_2> pos2_;
  std::vector<Point_3> pos3_;
  std::vector<double> radius_;
  std::vector<Segment> segments_;
  std::map<std::pair<std::size_t, std::size_t>, int> parity_;
  std::vector<Triangle> triangles_;
  mutable std::vector<typename Remesh_triangle_tree<GeomTraits>::Tree::template Intersection_and_primitive_id<Line_3>::Type>
    hits_;
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_CHART_TRIANGULATION_H
