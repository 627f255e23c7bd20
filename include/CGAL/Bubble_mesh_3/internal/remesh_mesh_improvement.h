// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_MESH_IMPROVEMENT_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_MESH_IMPROVEMENT_H

// Clean-up of one re-meshed patch in 3D: the charts were triangulated in
// their planes, where a tilted chart looks squeezed; edge flips that raise
// the smaller angle of the two triangles (Delaunay in the surface) and
// vertex moves towards the centre of their neighbours, projected back onto
// the input patch and kept only when the worst angle around does not get
// worse, fix that and smooth the seams between charts; a vertex crowded
// into a poor triangle that neither cures is collapsed into a neighbour.
// Curve edges are never flipped and curve points never move.

#include <CGAL/Bubble_mesh_3/internal/remesh_chart_triangulation.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_triangle_tree.h>
#include <CGAL/Bubble_mesh_3/model_features.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <iterator>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

template <class Point_3>
typename Kernel_traits<Point_3>::Kernel::Vector_3 remesh_unit_normal(const Point_3& a, const Point_3& b,
                                                                      const Point_3& c)
{
  const auto n = CGAL::cross_product(b - a, c - a);
  const double l = std::sqrt(CGAL::to_double(n.squared_length()));
  return l > 0. ? n / l : n;
}

// Whether a triangle around a moving point, of unit normal `before` and
// `after` the move, may take it: it must face `star`, the side its patch
// faces around the point (the sum of the unit normals there), and turn by at
// most 60 degrees - unless it faced away before: a sliver turned over where
// the input patch is wrinkled may only turn back, never stay over (it would
// slide across its neighbours at a later move).
template <class Vector_3>
bool keeps_facing_star(const Vector_3& after, const Vector_3& before, const Vector_3& star)
{
  if(!(CGAL::to_double(after * star) > 0.)) return false;
  return !(CGAL::to_double(before * star) > 0.) || CGAL::to_double(after * before) > 0.5;
}

// Flips edges of `triangles` (indices into `points`) that are not in
// `constrained` while the smaller angle of the two triangles grows, the new
// triangles face the same way and the two old ones are nearly coplanar
// (`max_dihedral` degrees). Returns the number of flips.
template <class Point_3>
std::size_t flip_to_improve_angles(const std::vector<Point_3>& points, std::vector<std::array<std::size_t, 3> >& triangles,
                                   const Edge_set& constrained, double max_dihedral)
{
  typedef std::pair<std::size_t, std::size_t> Edge;
  std::unordered_map<Edge, std::vector<std::size_t>, Edge_key_hash> edge_tris;
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int k = 0; k < 3; ++k) edge_tris[edge_key(triangles[t][k], triangles[t][(k + 1) % 3])].push_back(t);
  std::deque<Edge> queue;
  std::vector<Edge> all;
  for(const auto& e : edge_tris)
    if(e.second.size() == 2 && !constrained.count(e.first)) all.push_back(e.first);
  std::sort(all.begin(), all.end()); // deterministic order
  queue.assign(all.begin(), all.end());
  const double cos_dihedral = std::cos(max_dihedral * 3.14159265358979323846 / 180.);
  std::size_t flips = 0;
  std::size_t budget = 50 * triangles.size() + 100;
  auto replace = [&](const Edge& e, std::size_t from, std::size_t to) {
    for(std::size_t& t : edge_tris[e])
      if(t == from) t = to;
  };
  while(!queue.empty() && budget-- > 0)
  {
    const Edge e = queue.front();
    queue.pop_front();
    if(constrained.count(e)) continue;
    const auto it = edge_tris.find(e);
    if(it == edge_tris.end() || it->second.size() != 2) continue;
    const std::size_t t1 = it->second[0], t2 = it->second[1];
    // t1 = (a, b, c) with the edge a->b, t2 = (b, a, d)
    int k1 = -1;
    for(int k = 0; k < 3; ++k)
      if(edge_key(triangles[t1][k], triangles[t1][(k + 1) % 3]) == e) k1 = k;
    const std::size_t a = triangles[t1][k1], b = triangles[t1][(k1 + 1) % 3], c = triangles[t1][(k1 + 2) % 3];
    int k2 = -1;
    for(int k = 0; k < 3; ++k)
      if(triangles[t2][k] == b && triangles[t2][(k + 1) % 3] == a) k2 = k;
    if(k2 < 0) continue; // inconsistent orientation: leave it
    const std::size_t d = triangles[t2][(k2 + 2) % 3];
    if(c == d || edge_tris.count(edge_key(c, d))) continue;
    const Point_3 &pa = points[a], &pb = points[b], &pc = points[c], &pd = points[d];
    const auto n1 = remesh_unit_normal(pa, pb, pc), n2 = remesh_unit_normal(pb, pa, pd);
    if(CGAL::to_double(n1 * n2) < cos_dihedral) continue;
    const double old_min = (std::min)(min_angle_degrees(pa, pb, pc), min_angle_degrees(pb, pa, pd));
    const double new_min = (std::min)(min_angle_degrees(pa, pd, pc), min_angle_degrees(pd, pb, pc));
    if(!(new_min > old_min + 1e-6)) continue;
    const auto ns = n1 + n2;
    const auto m1 = remesh_unit_normal(pa, pd, pc), m2 = remesh_unit_normal(pd, pb, pc);
    if(!(CGAL::to_double(m1 * ns) > 0.) || !(CGAL::to_double(m2 * ns) > 0.) || !(CGAL::to_double(m1 * m2) > 0.))
      continue;
    // flip: t1 = (a, d, c), t2 = (d, b, c)
    triangles[t1] = std::array<std::size_t, 3>{{a, d, c}};
    triangles[t2] = std::array<std::size_t, 3>{{d, b, c}};
    edge_tris.erase(e);
    replace(edge_key(b, c), t1, t2);
    replace(edge_key(a, d), t2, t1);
    edge_tris[edge_key(c, d)] = std::vector<std::size_t>{t1, t2};
    ++flips;
    for(const Edge& n : {edge_key(a, d), edge_key(d, b), edge_key(b, c), edge_key(c, a)})
      if(!constrained.count(n)) queue.push_back(n);
  }
  return flips;
}

// Moves free vertices to better places, projected onto the input patch:
// towards the centre of their neighbours, and for a vertex with a poor
// triangle around it also towards the apex that would make that triangle
// equilateral (the only cure next to a curve, whose points cannot move),
// then, still under `angle_goal`, by a compass search around the best. A
// move is kept when the smallest angle around the vertex reaches at least
// min(its old value, `angle_goal`) - and grows if it was under the goal -
// and no triangle turns over. Returns the number of moves.
template <class GeomTraits>
std::size_t smooth_free_vertices(std::vector<typename GeomTraits::Point_3>& points,
                                 const std::vector<std::array<std::size_t, 3> >& triangles,
                                 const std::vector<char>& fixed, const Remesh_triangle_tree<GeomTraits>& patch_tree,
                                 double angle_goal)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  std::unordered_map<std::size_t, std::vector<std::size_t> > incident;
  std::vector<std::size_t> vertices;
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(std::size_t v : triangles[t])
    {
      std::vector<std::size_t>& inc = incident[v];
      if(inc.empty()) vertices.push_back(v);
      inc.push_back(t);
    }
  std::sort(vertices.begin(), vertices.end());
  std::size_t moves = 0;
  std::vector<Vector_3> old_normals;
  std::vector<Point_3> candidates;
  for(std::size_t v : vertices)
  {
    if(fixed[v]) continue;
    const std::vector<std::size_t>& inc = incident[v];
    Vector_3 sum(0, 0, 0);
    std::size_t count = 0;
    double old_min = 180.;
    old_normals.clear();
    candidates.clear();
    for(std::size_t t : inc)
    {
      const auto& tri = triangles[t];
      for(std::size_t w : tri)
        if(w != v)
        {
          sum = sum + (points[w] - CGAL::ORIGIN);
          ++count;
        }
      const double a = min_angle_degrees(points[tri[0]], points[tri[1]], points[tri[2]]);
      old_min = (std::min)(old_min, a);
      old_normals.push_back(remesh_unit_normal(points[tri[0]], points[tri[1]], points[tri[2]]));
      if(a < angle_goal)
      {
        // the apex over the opposite edge that makes this triangle equilateral
        const int k = int(std::find(tri.begin(), tri.end(), v) - tri.begin());
        const Point_3& p = points[tri[(k + 1) % 3]];
        const Point_3& q = points[tri[(k + 2) % 3]];
        const Point_3 m = CGAL::midpoint(p, q);
        Vector_3 up = (points[v] - m) - (q - p) * (CGAL::to_double((points[v] - m) * (q - p)) /
                                                   CGAL::to_double((q - p).squared_length()));
        const double l = std::sqrt(CGAL::to_double(up.squared_length()));
        if(l > 0.)
        {
          const Point_3 apex = m + up * (0.8660254 * std::sqrt(CGAL::to_double((q - p).squared_length())) / l);
          candidates.push_back(apex);
          candidates.push_back(CGAL::midpoint(apex, points[v]));
        }
      }
    }
    if(count == 0) continue;
    const Point_3 centre = CGAL::ORIGIN + sum / double(count);
    candidates.push_back(centre);
    if(old_min < angle_goal) candidates.push_back(CGAL::midpoint(centre, points[v]));
    const Point_3 old = points[v];
    // the side of the patch the star around v faces (see keeps_facing_star())
    Vector_3 star(0, 0, 0);
    for(const Vector_3& n : old_normals) star = star + n;
    // the smallest angle around v at the patch point nearest to c, or -1 if a triangle turns over
    auto smallest_angle_at = [&](const Point_3& c) {
      points[v] = patch_tree.closest_point(c);
      double new_min = 180.;
      for(std::size_t i = 0; i < inc.size(); ++i)
      {
        const auto& tri = triangles[inc[i]];
        new_min = (std::min)(new_min, min_angle_degrees(points[tri[0]], points[tri[1]], points[tri[2]]));
        if(!keeps_facing_star(remesh_unit_normal(points[tri[0]], points[tri[1]], points[tri[2]]), old_normals[i], star))
          return -1.;
      }
      return new_min;
    };
    Point_3 best = old;
    double best_min = old_min;
    for(const Point_3& c : candidates)
    {
      const double new_min = smallest_angle_at(c);
      if(new_min < 0.) continue;
      // under the goal: only a real gain counts; above it, the centre is preferred
      const bool better = (old_min < angle_goal) ? (new_min > best_min + 1e-6)
                                                 : (best == old && new_min >= angle_goal);
      if(better)
      {
        best = points[v];
        best_min = new_min;
      }
    }
    if(best_min < angle_goal)
    {
      // Still under the goal: a compass search in the tangent plane, eight
      // directions, halving the step when none gains. The candidates above aim
      // at one triangle or at the centre; where the other triangles around v
      // hold it back (a free point crowded against a curve sample: one of
      // modelA2's two triangles under 25 degrees, 23.6 before), the best place
      // lies between them.
      Vector_3 normal = star;
      double shortest = std::numeric_limits<double>::infinity();
      for(std::size_t t : inc)
        for(std::size_t w : triangles[t])
          if(w != v) shortest = (std::min)(shortest, CGAL::to_double(CGAL::squared_distance(old, points[w])));
      const double nl = std::sqrt(CGAL::to_double(normal.squared_length()));
      if(nl > 0. && shortest > 0.)
      {
        normal = normal / nl;
        // a unit vector across the normal, from the axis it is least along
        const double ax = std::abs(CGAL::to_double(normal.x())), ay = std::abs(CGAL::to_double(normal.y())),
                     az = std::abs(CGAL::to_double(normal.z()));
        const Vector_3 axis = (ax <= ay && ax <= az) ? Vector_3(1, 0, 0) : (ay <= az ? Vector_3(0, 1, 0) : Vector_3(0, 0, 1));
        Vector_3 e1 = CGAL::cross_product(normal, axis);
        e1 = e1 / std::sqrt(CGAL::to_double(e1.squared_length()));
        const Vector_3 e2 = CGAL::cross_product(normal, e1);
        const double first = 0.25 * std::sqrt(shortest);
        int rounds = 0; // (each gains, but by as little as 1e-6 degrees)
        for(double step = first; step > first / 64. && rounds < 40; ++rounds)
        {
          bool gained = false;
          const Point_3 from = best;
          for(int k = 0; k < 8; ++k)
          {
            const double a = k * 0.78539816339744831;
            const double new_min = smallest_angle_at(from + (e1 * std::cos(a) + e2 * std::sin(a)) * step);
            if(new_min > best_min + 1e-6)
            {
              best = points[v];
              best_min = new_min;
              gained = true;
            }
          }
          if(!gained) step *= 0.5;
        }
      }
    }
    points[v] = best;
    if(!(best == old)) ++moves;
  }
  return moves;
}

// Collapses free vertices of triangles under `angle_bound` into one of their
// neighbours, where that raises the smallest angle around them. Where the
// sizes change fast (next to a thin layer's side, whose curves ask for edges
// three times shorter than the walls around), a bubble can be left crowded
// against a curve: too near its neighbours for any move to help, too near
// the curve for a flip to help. The edge from such a vertex `v` to a
// neighbour `w` is collapsed into `w`, which keeps its place (it may be a
// curve point) or, when it is free too, moves to the middle of the edge
// (`project`ed onto the patch: two free points too near each other). A
// collapse is kept when the two vertices share no neighbour but the two
// across their edge (the surface stays a disc around `w`), no triangle turns
// over, no new edge is longer than 1.5 times `size` at its middle, and the
// smallest angle of the triangles that change grows. Worst triangles first;
// returns the number of collapses.
template <class Point_3, class SizeFunction, class Projection>
std::size_t collapse_crowded_vertices(std::vector<Point_3>& points, std::vector<std::array<std::size_t, 3> >& triangles,
                                      const std::vector<char>& fixed, const SizeFunction& size,
                                      const Projection& project, double angle_bound)
{
  auto angle_of = [&](const std::array<std::size_t, 3>& t) {
    return min_angle_degrees(points[t[0]], points[t[1]], points[t[2]]);
  };
  std::vector<std::pair<double, std::size_t> > poor;
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const double a = angle_of(triangles[t]);
    if(a < angle_bound) poor.push_back(std::make_pair(a, t));
  }
  if(poor.empty()) return 0;
  std::sort(poor.begin(), poor.end());
  std::unordered_map<std::size_t, std::vector<std::size_t> > incident;
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(std::size_t v : triangles[t]) incident[v].push_back(t);
  std::vector<char> dead(triangles.size(), 0);
  auto neighbours = [&](std::size_t v) {
    std::vector<std::size_t> n;
    for(std::size_t t : incident[v])
      for(std::size_t u : triangles[t])
        if(u != v) n.push_back(u);
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
    return n;
  };
  auto contains = [&](std::size_t t, std::size_t u) {
    return std::find(triangles[t].begin(), triangles[t].end(), u) != triangles[t].end();
  };
  // smallest angle of the triangles around v and w after the collapse of v into w
  // placed at `at`, or -1 if the collapse is not allowed
  auto collapsed_min = [&](std::size_t v, std::size_t w, const Point_3& at) {
    double new_min = 180.;
    std::vector<std::size_t> changed = incident[v];
    if(!(at == points[w])) changed.insert(changed.end(), incident[w].begin(), incident[w].end());
    for(std::size_t t : changed)
    {
      if(contains(t, v) && contains(t, w)) continue; // goes away
      std::array<Point_3, 3> q;
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t u = triangles[t][k];
        q[k] = (u == v || u == w) ? at : points[u];
      }
      const auto old_normal = remesh_unit_normal(points[triangles[t][0]], points[triangles[t][1]], points[triangles[t][2]]);
      if(!(CGAL::to_double(remesh_unit_normal(q[0], q[1], q[2]) * old_normal) > 0.5)) return -1.;
      for(int k = 0; k < 3; ++k)
        if(!(q[k] == at) && CGAL::to_double(CGAL::squared_distance(q[k], at)) > 2.25 * CGAL::square(size(CGAL::midpoint(q[k], at))))
          return -1.;
      new_min = (std::min)(new_min, min_angle_degrees(q[0], q[1], q[2]));
    }
    return new_min;
  };
  std::size_t collapses = 0;
  for(const auto& bad : poor)
  {
    if(dead[bad.second] || !(angle_of(triangles[bad.second]) < angle_bound)) continue;
    double best_min = -1.;
    std::size_t best_v = 0, best_w = 0;
    Point_3 best_at;
    for(std::size_t v : triangles[bad.second])
    {
      if(fixed[v]) continue;
      double old_min_v = 180.;
      for(std::size_t t : incident[v]) old_min_v = (std::min)(old_min_v, angle_of(triangles[t]));
      const std::vector<std::size_t> nv = neighbours(v);
      for(std::size_t w : nv)
      {
        std::vector<std::size_t> across;
        for(std::size_t t : incident[v])
          if(contains(t, w))
            for(std::size_t u : triangles[t])
              if(u != v && u != w) across.push_back(u);
        if(across.size() != 2) continue;
        std::sort(across.begin(), across.end());
        const std::vector<std::size_t> nw = neighbours(w);
        std::vector<std::size_t> common;
        std::set_intersection(nv.begin(), nv.end(), nw.begin(), nw.end(), std::back_inserter(common));
        if(common != across) continue;
        std::vector<Point_3> places(1, points[w]);
        if(!fixed[w]) places.push_back(project(CGAL::midpoint(points[v], points[w])));
        for(const Point_3& at : places)
        {
          double old_min = old_min_v;
          if(!(at == points[w]))
            for(std::size_t t : incident[w]) old_min = (std::min)(old_min, angle_of(triangles[t]));
          const double new_min = collapsed_min(v, w, at);
          if(new_min > old_min + 1e-6 && new_min > best_min)
          {
            best_min = new_min;
            best_v = v;
            best_w = w;
            best_at = at;
          }
        }
      }
    }
    if(best_min < 0.) continue;
    const std::vector<std::size_t> inc = incident[best_v];
    for(std::size_t t : inc)
    {
      std::array<std::size_t, 3>& tri = triangles[t];
      if(contains(t, best_w))
      {
        dead[t] = 1;
        for(std::size_t u : tri)
          if(u != best_v)
          {
            std::vector<std::size_t>& l = incident[u];
            l.erase(std::remove(l.begin(), l.end(), t), l.end());
          }
        continue;
      }
      for(std::size_t& u : tri)
        if(u == best_v) u = best_w;
      incident[best_w].push_back(t);
    }
    incident[best_v].clear();
    points[best_w] = best_at;
    ++collapses;
  }
  std::size_t n = 0;
  for(std::size_t t = 0; t < triangles.size(); ++t)
    if(!dead[t]) triangles[n++] = triangles[t];
  triangles.resize(n);
  return collapses;
}


// Splits an edge of a triangle under `angle_bound` whose three points are
// fixed (curve samples), which no move, flip or collapse of free points can
// change: the longest of its edges that is not in `constrained`. The new free
// point, projected onto the patch, takes the best place `smooth_free_vertices()`
// finds between the four triangles around it, and the split is kept when
// none of them is under the bound. (Kept when they only gained a degree, the
// splits made needles of the new points: CloudSpin got 6 more triangles
// under 25.) `fixed` grows with the points. Returns the number of splits.
template <class GeomTraits>
std::size_t split_fixed_triangles(std::vector<typename GeomTraits::Point_3>& points,
                                  std::vector<std::array<std::size_t, 3> >& triangles, std::vector<char>& fixed,
                                  const Edge_set& constrained, const Remesh_triangle_tree<GeomTraits>& patch_tree,
                                  double angle_bound)
{
  typedef std::array<std::size_t, 3> Triangle;
  std::size_t splits = 0;
  for(std::size_t t1 = 0; t1 < triangles.size(); ++t1)
  {
    const Triangle tri = triangles[t1];
    if(!fixed[tri[0]] || !fixed[tri[1]] || !fixed[tri[2]]) continue;
    if(!(min_angle_degrees(points[tri[0]], points[tri[1]], points[tri[2]]) < angle_bound)) continue;
    // the edge a -> b opposite c: the longest one free to split
    int k = -1;
    double longest = 0.;
    for(int i = 0; i < 3; ++i)
    {
      const std::size_t a = tri[(i + 1) % 3], b = tri[(i + 2) % 3];
      const double l = CGAL::to_double(CGAL::squared_distance(points[a], points[b]));
      if(!constrained.count(edge_key(a, b)) && l > longest)
      {
        longest = l;
        k = i;
      }
    }
    if(k < 0) continue;
    const std::size_t c = tri[k], a = tri[(k + 1) % 3], b = tri[(k + 2) % 3];
    std::size_t t2 = triangles.size(), d = 0;
    for(std::size_t t = 0; t < triangles.size() && t2 == triangles.size(); ++t)
      for(int i = 0; i < 3; ++i)
        if(t != t1 && triangles[t][i] == b && triangles[t][(i + 1) % 3] == a)
        {
          t2 = t;
          d = triangles[t][(i + 2) % 3];
        }
    if(t2 == triangles.size()) continue;
    const std::size_t m = points.size();
    points.push_back(patch_tree.closest_point(CGAL::midpoint(points[a], points[b])));
    fixed.push_back(0);
    std::vector<Triangle> around{{{a, m, c}}, {{m, b, c}}, {{b, m, d}}, {{m, a, d}}};
    std::vector<char> only_m(points.size(), 1);
    only_m[m] = 0;
    for(int pass = 0; pass < 3; ++pass)
      if(smooth_free_vertices<GeomTraits>(points, around, only_m, patch_tree, 90.) == 0) break;
    double new_min = 180.;
    for(const Triangle& t : around)
      new_min = (std::min)(new_min, min_angle_degrees(points[t[0]], points[t[1]], points[t[2]]));
    if(!(new_min >= angle_bound))
    {
      points.pop_back();
      fixed.pop_back();
      continue;
    }
    triangles[t1] = around[0];
    triangles[t2] = around[2];
    triangles.push_back(around[1]);
    triangles.push_back(around[3]);
    ++splits;
  }
  return splits;
}
} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_MESH_IMPROVEMENT_H
