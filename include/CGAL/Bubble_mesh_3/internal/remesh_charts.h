// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_CHARTS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_CHARTS_H

// Charts: pieces of a patch that project one-to-one onto a plane, so that a
// patch can be triangulated with a 2D constrained Delaunay triangulation.
// Most patches of geological models are one chart (a fault, a box side, a
// gently bending horizon); a folded surface is cut into pieces whose normals
// stay within a cone, and the cuts (seams) are resampled like curves.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/model_features.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

template <class GeomTraits>
struct Remesh_chart
{
  typedef typename GeomTraits::Point_2 Point_2;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;

  std::size_t patch = 0;
  std::vector<std::size_t> triangles; // model triangle indices
  Vector_3 normal, e1, e2;            // (e1, e2, normal) right-handed
  Point_3 origin;

  Point_2 to_2d(const Point_3& p) const
  {
    const Vector_3 d = p - origin;
    return Point_2(CGAL::to_double(d * e1), CGAL::to_double(d * e2));
  }
  Point_3 plane_point(const Point_2& q) const { return origin + e1 * q.x() + e2 * q.y(); }
};

template <class GeomTraits>
typename GeomTraits::Vector_3 triangle_area_normal(const Geological_model_3<GeomTraits>& model, std::size_t t)
{
  const auto& tri = model.triangle(t);
  return 0.5 * CGAL::cross_product(model.point(tri[1]) - model.point(tri[0]), model.point(tri[2]) - model.point(tri[0]));
}

template <class Vector_3>
Vector_3 unit_vector(const Vector_3& v)
{
  const double l = std::sqrt(CGAL::to_double(v.squared_length()));
  return l > 0. ? v / l : v;
}

// normal (area weighted), origin (area centroid) and in-plane axes of a chart
template <class GeomTraits>
void set_chart_frame(const Geological_model_3<GeomTraits>& model, Remesh_chart<GeomTraits>& chart)
{
  typedef typename GeomTraits::Vector_3 Vector_3;
  Vector_3 n(0, 0, 0), c(0, 0, 0);
  double area = 0.;
  for(std::size_t t : chart.triangles)
  {
    const Vector_3 an = triangle_area_normal(model, t);
    const double a = std::sqrt(CGAL::to_double(an.squared_length()));
    n = n + an;
    const auto& tri = model.triangle(t);
    const Vector_3 g = ((model.point(tri[0]) - CGAL::ORIGIN) + (model.point(tri[1]) - CGAL::ORIGIN) +
                        (model.point(tri[2]) - CGAL::ORIGIN)) / 3.;
    c = c + g * a;
    area += a;
  }
  if(area > 0.) c = c / area;
  else
  {
    const auto& tri = model.triangle(chart.triangles.front());
    c = model.point(tri[0]) - CGAL::ORIGIN;
  }
  if(n.squared_length() == 0) n = Vector_3(0, 0, 1);
  chart.normal = unit_vector(n);
  chart.origin = CGAL::ORIGIN + c;
  const double ax = std::abs(CGAL::to_double(chart.normal.x())), ay = std::abs(CGAL::to_double(chart.normal.y())),
               az = std::abs(CGAL::to_double(chart.normal.z()));
  const Vector_3 axis = (ax <= ay && ax <= az) ? Vector_3(1, 0, 0) : (ay <= az ? Vector_3(0, 1, 0) : Vector_3(0, 0, 1));
  chart.e1 = unit_vector(CGAL::cross_product(chart.normal, axis));
  chart.e2 = CGAL::cross_product(chart.normal, chart.e1);
}

// Neighbours among `triangles` (of one patch) across edges with exactly two triangles.
template <class GeomTraits>
std::vector<std::vector<std::size_t> > patch_triangle_neighbors(const Geological_model_3<GeomTraits>& model,
                                                                 const std::vector<std::size_t>& triangles,
                                                                 const Edge_triangles_map& et)
{
  std::map<std::size_t, std::size_t> local;
  for(std::size_t i = 0; i < triangles.size(); ++i) local[triangles[i]] = i;
  std::vector<std::vector<std::size_t> > nbs(triangles.size());
  for(std::size_t i = 0; i < triangles.size(); ++i)
  {
    const auto& tri = model.triangle(triangles[i]);
    for(int k = 0; k < 3; ++k)
    {
      const std::vector<std::size_t>& ts = et.at(edge_key(tri[k], tri[(k + 1) % 3]));
      std::vector<std::size_t> same;
      for(std::size_t t : ts)
        if(t != triangles[i] && model.patch_of_triangle(t) == model.patch_of_triangle(triangles[i])) same.push_back(t);
      if(same.size() != 1 || ts.size() != 2) continue;
      const auto it = local.find(same[0]); // the neighbour may belong to another chart
      if(it != local.end()) nbs[i].push_back(it->second);
    }
  }
  return nbs;
}

// Region growing: a chart takes neighbouring triangles while their normal stays
// within `max_angle` of the chart's mean normal. Tiny triangles (needles,
// whose normals mean little) only need to face the same side.
template <class GeomTraits>
std::vector<std::vector<std::size_t> > grow_charts(const Geological_model_3<GeomTraits>& model,
                                                   const std::vector<std::size_t>& triangles,
                                                   const Edge_triangles_map& et, double max_angle_degrees)
{
  typedef typename GeomTraits::Vector_3 Vector_3;
  const std::size_t n = triangles.size();
  std::vector<std::vector<std::size_t> > charts;
  if(n == 0) return charts;
  const std::vector<std::vector<std::size_t> > nbs = patch_triangle_neighbors(model, triangles, et);
  std::vector<Vector_3> unit(n);
  std::vector<double> area(n);
  double total = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Vector_3 an = triangle_area_normal(model, triangles[i]);
    area[i] = std::sqrt(CGAL::to_double(an.squared_length()));
    unit[i] = unit_vector(an);
    total += area[i];
  }
  const double tiny = 1e-3 * total / double(n);
  const double cos_max = std::cos(max_angle_degrees * 3.14159265358979323846 / 180.);

  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return area[a] > area[b]; });
  std::vector<std::size_t> chart_of(n, std::size_t(-1));
  for(std::size_t seed : order)
  {
    if(chart_of[seed] != std::size_t(-1)) continue;
    const std::size_t id = charts.size();
    charts.push_back(std::vector<std::size_t>());
    Vector_3 sum = unit[seed] * area[seed];
    std::deque<std::size_t> queue(1, seed);
    chart_of[seed] = id;
    while(!queue.empty())
    {
      const std::size_t i = queue.front();
      queue.pop_front();
      charts[id].push_back(i);
      for(std::size_t j : nbs[i])
      {
        if(chart_of[j] != std::size_t(-1)) continue;
        const Vector_3 c = unit_vector(sum);
        const double d = CGAL::to_double(unit[j] * c);
        if(d >= cos_max || (area[j] < tiny && d > 0.2))
        {
          chart_of[j] = id;
          sum = sum + unit[j] * area[j];
          queue.push_back(j);
        }
      }
    }
  }
  // merge crumbs (a few tiny triangles) into the neighbour they share most with
  bool merged = true;
  while(merged)
  {
    merged = false;
    for(std::size_t c = 0; c < charts.size(); ++c)
    {
      if(charts[c].empty()) continue;
      double a = 0.;
      for(std::size_t i : charts[c]) a += area[i];
      if(a > 1e-3 * total || charts.size() == 1) continue;
      std::map<std::size_t, std::size_t> shared;
      for(std::size_t i : charts[c])
        for(std::size_t j : nbs[i])
          if(chart_of[j] != c) ++shared[chart_of[j]];
      std::size_t best = std::size_t(-1), count = 0;
      for(const auto& s : shared)
        if(s.second > count) { best = s.first; count = s.second; }
      if(best == std::size_t(-1)) continue;
      Vector_3 sum(0, 0, 0);
      for(std::size_t i : charts[best]) sum = sum + unit[i] * area[i];
      const Vector_3 nb = unit_vector(sum);
      bool ok = true;
      for(std::size_t i : charts[c])
        if(!(CGAL::to_double(unit[i] * nb) > 0.)) ok = false;
      if(!ok) continue;
      for(std::size_t i : charts[c])
      {
        chart_of[i] = best;
        charts[best].push_back(i);
      }
      charts[c].clear();
      merged = true;
    }
  }
  std::vector<std::vector<std::size_t> > result;
  for(std::vector<std::size_t>& c : charts)
  {
    if(c.empty()) continue;
    std::sort(c.begin(), c.end());
    std::vector<std::size_t> tris;
    for(std::size_t i : c) tris.push_back(triangles[i]);
    result.push_back(tris);
  }
  return result;
}

// Cuts a chart in two across its longest extent; each side may fall apart in
// several connected pieces, each a chart.
template <class GeomTraits>
std::vector<std::vector<std::size_t> > bisect_chart(const Geological_model_3<GeomTraits>& model,
                                                    const Remesh_chart<GeomTraits>& chart,
                                                    const Edge_triangles_map& et)
{
  const std::vector<std::size_t>& tris = chart.triangles;
  std::vector<std::vector<std::size_t> > result;
  if(tris.size() < 2) { result.push_back(tris); return result; }
  // principal axis of the centroids in the chart plane
  std::vector<std::pair<double, double> > c(tris.size());
  double mx = 0., my = 0.;
  for(std::size_t i = 0; i < tris.size(); ++i)
  {
    const auto& tri = model.triangle(tris[i]);
    const auto a = chart.to_2d(model.point(tri[0])), b = chart.to_2d(model.point(tri[1])),
               d = chart.to_2d(model.point(tri[2]));
    c[i] = std::make_pair((a.x() + b.x() + d.x()) / 3., (a.y() + b.y() + d.y()) / 3.);
    mx += c[i].first;
    my += c[i].second;
  }
  mx /= double(tris.size());
  my /= double(tris.size());
  double sxx = 0., sxy = 0., syy = 0.;
  for(const auto& p : c)
  {
    sxx += (p.first - mx) * (p.first - mx);
    sxy += (p.first - mx) * (p.second - my);
    syy += (p.second - my) * (p.second - my);
  }
  const double theta = 0.5 * std::atan2(2. * sxy, sxx - syy);
  const double ux = std::cos(theta), uy = std::sin(theta);
  std::vector<double> proj(tris.size());
  for(std::size_t i = 0; i < tris.size(); ++i) proj[i] = (c[i].first - mx) * ux + (c[i].second - my) * uy;
  std::vector<double> sorted = proj;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  std::vector<int> side(tris.size());
  for(std::size_t i = 0; i < tris.size(); ++i) side[i] = proj[i] < median ? 0 : 1;
  // connected pieces of each side
  const std::vector<std::vector<std::size_t> > nbs = patch_triangle_neighbors(model, tris, et);
  std::vector<std::size_t> comp(tris.size(), std::size_t(-1));
  for(std::size_t s = 0; s < tris.size(); ++s)
  {
    if(comp[s] != std::size_t(-1)) continue;
    const std::size_t id = result.size();
    result.push_back(std::vector<std::size_t>());
    std::deque<std::size_t> queue(1, s);
    comp[s] = id;
    while(!queue.empty())
    {
      const std::size_t i = queue.front();
      queue.pop_front();
      result[id].push_back(tris[i]);
      for(std::size_t j : nbs[i])
        if(comp[j] == std::size_t(-1) && side[j] == side[i])
        {
          comp[j] = id;
          queue.push_back(j);
        }
    }
    std::sort(result[id].begin(), result[id].end());
  }
  return result;
}

// A chart can be flattened when its triangles keep their orientation in the
// plane (up to crumbs) and its border and inner feature edges do not cross
// there.
typedef std::unordered_map<std::pair<std::size_t, std::size_t>, char, Edge_key_hash> Edge_set;

template <class GeomTraits>
bool is_valid_chart(const Geological_model_3<GeomTraits>& model, const Remesh_chart<GeomTraits>& chart,
                    const Edge_triangles_map& et, const Edge_set& feature_edges)
{
  typedef typename GeomTraits::Vector_3 Vector_3;
  // every triangle must keep its orientation in the plane: a fold, even a
  // small one next to a curve, would put the new triangles on the wrong side
  double total = 0.;
  std::vector<double> areas;
  for(std::size_t t : chart.triangles)
  {
    const Vector_3 an = triangle_area_normal(model, t);
    areas.push_back(std::sqrt(CGAL::to_double(an.squared_length())));
    total += areas.back();
  }
  for(std::size_t i = 0; i < chart.triangles.size(); ++i)
  {
    const Vector_3 an = triangle_area_normal(model, chart.triangles[i]);
    if(!(CGAL::to_double(an * chart.normal) > 0.) && areas[i] > 1e-12 * total) return false;
  }

  // edges to keep: border of the chart and edges of inner features; and
  // the net number of chart triangles running along each edge (a -> b for
  // a < b, minus b -> a), which says how the chart covers the plane there
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> count;
  std::map<std::pair<std::size_t, std::size_t>, long> net;
  for(std::size_t t : chart.triangles)
  {
    const auto& tri = model.triangle(t);
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = tri[k], b = tri[(k + 1) % 3];
      ++count[edge_key(a, b)];
      net[edge_key(a, b)] += (a < b) ? 1 : -1;
    }
  }
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, GeomTraits> Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<long, GeomTraits> Fbi;
  typedef CGAL::Constrained_triangulation_face_base_2<GeomTraits, Fbi> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<GeomTraits, Tds,
                                                     CGAL::No_constraint_intersection_requiring_constructions_tag> Cdt;
  typedef typename Cdt::Face_handle Face_handle;
  Cdt cdt;
  std::map<std::size_t, typename Cdt::Vertex_handle> vh;
  auto kept = [&](const std::pair<const std::pair<std::size_t, std::size_t>, std::size_t>& e) {
    return e.second != 2 || feature_edges.count(e.first) != 0 || net[e.first] != 0;
  };
  std::size_t expected = 0;
  try
  {
    for(const auto& e : count)
    {
      if(!kept(e)) continue;
      ++expected;
      for(std::size_t v : {e.first.first, e.first.second})
      {
        if(vh.count(v)) continue;
        const std::size_t before = cdt.number_of_vertices();
        typename Cdt::Vertex_handle h = cdt.insert(chart.to_2d(model.point(v)));
        if(cdt.number_of_vertices() == before) return false; // two points on one spot of the plane
        h->info() = v;
        vh[v] = h;
      }
    }
    for(const auto& e : count)
      if(kept(e)) cdt.insert_constraint(vh.at(e.first.first), vh.at(e.first.second));
  }
  catch(const typename Cdt::Intersection_of_constraints_exception&)
  {
    return false;
  }
  // a constraint through another chart point is split silently: count them
  std::size_t constrained = 0;
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if(cdt.is_constrained(*e)) ++constrained;
  if(constrained != expected) return false;

  // How many times the chart covers each face of the plane (its winding
  // number): 0 outside, and 1 inside when the chart projects one-to-one.
  // Two sheets of the chart can overlap in the plane without any border
  // crossing another (a horizon on both sides of a reverse fault, whose
  // two cut lines project side by side): the overlap is covered twice, and
  // the re-meshed triangles next to those borders would land on the wrong
  // side of them. A face lies left of its edges (ccw), so stepping across
  // the edge u -> v from the left to the right removes the chart triangles
  // running along u -> v. Crumbs (see above) may cover a speck twice.
  const long unset = std::numeric_limits<long>::min();
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = unset;
  std::deque<Face_handle> queue(1, cdt.infinite_face());
  cdt.infinite_face()->info() = 0;
  double wrong_area = 0., area_2d = 0.;
  while(!queue.empty())
  {
    const Face_handle f = queue.front();
    queue.pop_front();
    if(!cdt.is_infinite(f) && f->info() != 0 && f->info() != 1)
      wrong_area += std::abs(CGAL::to_double(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(),
                                                        f->vertex(2)->point())));
    for(int i = 0; i < 3; ++i)
    {
      const Face_handle g = f->neighbor(i);
      if(g->info() != unset) continue;
      long w = f->info();
      if(cdt.is_constrained(std::make_pair(f, i)))
      {
        const std::size_t u = f->vertex(cdt.ccw(i))->info(), v = f->vertex(cdt.cw(i))->info();
        const long n = net[edge_key(u, v)];
        w -= (u < v) ? n : -n;
      }
      g->info() = w;
      queue.push_back(g);
    }
  }
  for(std::size_t t : chart.triangles)
  {
    const auto& tri = model.triangle(t);
    area_2d += std::abs(CGAL::to_double(CGAL::area(chart.to_2d(model.point(tri[0])), chart.to_2d(model.point(tri[1])),
                                                   chart.to_2d(model.point(tri[2])))));
  }
  return wrong_area <= 1e-9 * area_2d;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_CHARTS_H
