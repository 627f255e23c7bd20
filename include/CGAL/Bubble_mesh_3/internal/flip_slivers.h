// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_FLIP_SLIVERS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_FLIP_SLIVERS_H

// Flips around slivers (a step of `remove_slivers()`, before and after the
// insertion of new vertices).
//
// A sliver whose four vertices lie on surfaces - two on the top and two on the
// bottom of a thin layer, nearly in one plane - has no vertex a perturbation
// may move, and a new vertex inside a thin layer makes flat cells of its own.
// Such a sliver often goes with a change of connectivity alone, as in TetGen's
// and Gmsh's mesh optimisation:
// - a 2-3 flip replaces two cells sharing a facet by three around the edge
//   joining their apices;
// - an edge removal replaces the n cells around an edge (n = 3..max_ring) by
//   2(n - 2) cells: a triangulation of the ring of the edge's link, each
//   triangle joined to both ends of the edge; the triangulation maximising
//   the smallest dihedral angle is found by dynamic programming over the ring
//   (Shewchuk, "Two discrete optimization algorithms for the topological
//   improvement of tetrahedral meshes", 2002; n = 3 is the 3-2 flip).
// Only cells of one region, across facets that are not in the complex, and
// edges that are neither complex edges nor on a complex facet, are touched:
// the boundary of the replaced cells stays, so complex facets, complex edges,
// vertices and region volumes stay. Every new cell is checked positively
// oriented with the exact predicate, which makes the new cells an exact
// partition of the old ones. A change is kept only if it beats the cells it
// replaces (larger smallest angle, no more cells under the bound; around a
// flat cell, a larger smallest angle is enough).
//
// The result is a valid triangulation but no longer a regular one, like the
// insertion's.

#include <CGAL/Bubble_mesh_3/internal/perturb_interior_vertices.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// What the flips did.
struct Flip_statistics
{
  std::size_t number_of_passes = 0;
  std::size_t number_of_slivers_tried = 0;
  std::size_t number_of_2_3_flips = 0;
  std::size_t number_of_edge_removals = 0;
  bool time_limit_reached = false;
};

template <class C3T3>
class Sliver_flipper
{
  typedef typename C3T3::Triangulation   Tr;
  typedef typename Tr::Vertex_handle     Vertex_handle;
  typedef typename Tr::Cell_handle       Cell_handle;
  typedef typename Tr::Bare_point        Bare_point;
  typedef typename C3T3::Subdomain_index Subdomain_index;
  typedef std::array<Vertex_handle, 4>   Cell_vertices;

public:
  Sliver_flipper(C3T3& c3t3, double sliver_bound) : c3t3_(c3t3), tr_(c3t3.triangulation()), bound_(sliver_bound) {}

  // At most `max_passes` passes over the cells under the bound, worst first,
  // until a pass changes nothing or `time_limit` seconds are spent.
  Flip_statistics operator()(std::size_t max_passes, double time_limit)
  {
    Flip_statistics stats;
    if(tr_.dimension() != 3) return stats;
    CGAL::Real_timer timer;
    timer.start();
    for(std::size_t pass = 0; pass < max_passes; ++pass)
    {
      ++stats.number_of_passes;
      std::size_t changed = 0;
      auto work = [&](Cell_handle c, double) {
        const int kind = improve(c);
        if(kind == 1) ++stats.number_of_2_3_flips;
        if(kind == 2) ++stats.number_of_edge_removals;
        if(kind != 0) ++changed;
      };
      const std::size_t tried = for_each_sliver_worst_first(
        c3t3_, bound_, [](double, const Cell_vertices&) { return true; }, work, timer, time_limit, stats.time_limit_reached);
      stats.number_of_slivers_tried += tried;
      if(stats.time_limit_reached || !pass_paid(changed, tried, 20)) break;
    }
    return stats;
  }

private:
  // a replacement of `old_cells` by `new_cells`, each new cell positively oriented
  struct Change
  {
    std::vector<Cell_handle> old_cells;
    std::vector<Cell_vertices> new_cells;
    Cell_set_quality made;
  };

  Vec3 coordinates(Vertex_handle v) const { return vertex_coordinates(tr_, v); }
  Bare_point point(Vertex_handle v) const { return tr_.geom_traits().construct_point_3_object()(v->point()); }

  // the cell (a, b, c, d) if positively oriented; false if flat or inverted
  bool positive(Vertex_handle a, Vertex_handle b, Vertex_handle c, Vertex_handle d, Cell_vertices& out) const
  {
    const CGAL::Orientation o = tr_.geom_traits().orientation_3_object()(point(a), point(b), point(c), point(d));
    if(o != CGAL::POSITIVE) return false;
    out = {{a, b, c, d}};
    return true;
  }

  double angle(const Cell_vertices& v) const
  {
    return smallest_dihedral_angle(coordinates(v[0]), coordinates(v[1]), coordinates(v[2]), coordinates(v[3]));
  }

  bool flippable_facet(Cell_handle c, int i, const Subdomain_index& region) const
  {
    const Cell_handle n = c->neighbor(i);
    return !c3t3_.is_in_complex(c, i) && !tr_.is_infinite(n) && c3t3_.is_in_complex(n) &&
           c3t3_.subdomain_index(n) == region;
  }

  // 2-3 flip of facet i of c
  bool flip_2_3(Cell_handle c, int i, const Subdomain_index& region, Change& ch) const
  {
    if(!flippable_facet(c, i, region)) return false;
    const Cell_handle n = c->neighbor(i);
    const Vertex_handle p = c->vertex(i), q = n->vertex(n->index(c));
    ch = Change();
    ch.old_cells = {c, n};
    // the facet's vertices in either turning order: each new cell is tried
    // both ways round below
    Vertex_handle f[3];
    for(int k = 0; k < 3; ++k) f[k] = c->vertex(Tr::vertex_triple_index(i, k));
    for(int k = 0; k < 3; ++k)
    {
      Cell_vertices cv;
      if(!positive(f[k], f[(k + 1) % 3], p, q, cv) && !positive(f[(k + 1) % 3], f[k], p, q, cv)) return false;
      ch.new_cells.push_back(cv);
    }
    // the three cells must turn the same way around pq: each positive
    // ordering must agree with the ring's
    const bool first = ch.new_cells[0][0] == f[0];
    for(int k = 0; k < 3; ++k)
      if((ch.new_cells[k][0] == f[k]) != first) return false;
    for(const Cell_vertices& cv : ch.new_cells) ch.made.add(angle(cv), bound_);
    return true;
  }

  // removal of edge (c, i, j): the best triangulation of its ring
  bool remove_edge(Cell_handle c, int i, int j, const Subdomain_index& region, Change& ch) const
  {
    const Vertex_handle a = c->vertex(i), b = c->vertex(j);
    if(c3t3_.is_in_complex(a, b)) return false;
    // the ring: cells around ab in circulator order, with their facets
    // containing ab not in the complex and all in the region
    std::vector<Cell_handle> cells;
    auto circ = tr_.incident_cells(c, i, j), done = circ;
    do
    {
      const Cell_handle h = circ;
      if(tr_.is_infinite(h) || !c3t3_.is_in_complex(h) || !(c3t3_.subdomain_index(h) == region)) return false;
      cells.push_back(h);
      if(cells.size() > max_ring) return false;
      ++circ;
    } while(circ != done);
    const std::size_t n = cells.size();
    if(n < 3) return false;
    // ring vertices: cells[k] = (a, b, r[k], r[k+1]) up to order
    std::vector<Vertex_handle> r(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      const Cell_handle h = cells[k], next = cells[(k + 1) % n];
      // the facet between h and next contains a, b and r[k+1]
      const int m = h->index(next);
      if(c3t3_.is_in_complex(h, m)) return false;
      Vertex_handle shared;
      for(int t = 0; t < 4; ++t)
        if(t != m && h->vertex(t) != a && h->vertex(t) != b) shared = h->vertex(t);
      r[(k + 1) % n] = shared;
    }
    const auto orientation = tr_.geom_traits().orientation_3_object();
    std::vector<Bare_point> rp(n);
    std::vector<Vec3> rc(n);
    for(std::size_t k = 0; k < n; ++k) { rp[k] = point(r[k]); rc[k] = coordinates(r[k]); }
    const Bare_point ap = point(a), bp = point(b);
    const Vec3 ac = coordinates(a), bc = coordinates(b);
    // the ring turns one way around ab: triangles (r_x, r_y, r_z) with
    // x < y < z are oriented alike, so each gives the cells (r_x, r_y, r_z, a)
    // and (r_y, r_x, r_z, b), or both reversed. Which: the existing cell
    // (r0, r1, a, b) is negative when the ring turns counterclockwise seen
    // from a, and then (r_x, r_y, r_z, a) is positive
    const CGAL::Orientation o = orientation(rp[0], rp[1], ap, bp);
    if(o == CGAL::COPLANAR) return false;
    const bool forward = o == CGAL::NEGATIVE;
    // quality of triangle (x, y, z), x < y < z: min over its two cells, -1
    // if one is not positive. Each triangle is met once by the programme below.
    auto triangle = [&](std::size_t x, std::size_t y, std::size_t z) -> double {
      const std::size_t u = forward ? x : y, w = forward ? y : x; // (u, w, z, a) and (w, u, z, b)
      if(orientation(rp[u], rp[w], rp[z], ap) != CGAL::POSITIVE ||
         orientation(rp[w], rp[u], rp[z], bp) != CGAL::POSITIVE)
        return -1.;
      return (std::min)(smallest_dihedral_angle(rc[u], rc[w], rc[z], ac), smallest_dihedral_angle(rc[w], rc[u], rc[z], bc));
    };
    // best[x][z]: best smallest angle over triangulations of r_x .. r_z
    std::vector<std::vector<double> > best(n, std::vector<double>(n, -1.));
    std::vector<std::vector<std::size_t> > split(n, std::vector<std::size_t>(n, 0));
    for(std::size_t x = 0; x + 1 < n; ++x) best[x][x + 1] = 180.;
    for(std::size_t len = 2; len < n; ++len)
      for(std::size_t x = 0; x + len < n; ++x)
      {
        const std::size_t z = x + len;
        for(std::size_t y = x + 1; y < z; ++y)
        {
          if(best[x][y] < 0. || best[y][z] < 0.) continue;
          const double t = triangle(x, y, z);
          if(t < 0.) continue;
          const double q = (std::min)({best[x][y], best[y][z], t});
          if(q > best[x][z]) { best[x][z] = q; split[x][z] = y; }
        }
      }
    if(best[0][n - 1] < 0.) return false;
    ch = Change();
    ch.old_cells = cells;
    std::vector<std::pair<std::size_t, std::size_t> > todo(1, std::make_pair(std::size_t(0), n - 1));
    while(!todo.empty())
    {
      const std::size_t x = todo.back().first, z = todo.back().second;
      todo.pop_back();
      if(z < x + 2) continue;
      const std::size_t y = split[x][z];
      const std::size_t u = forward ? x : y, w = forward ? y : x;
      ch.new_cells.push_back(Cell_vertices{{r[u], r[w], r[z], a}});
      ch.new_cells.push_back(Cell_vertices{{r[w], r[u], r[z], b}});
      todo.push_back(std::make_pair(x, y));
      todo.push_back(std::make_pair(y, z));
    }
    for(const Cell_vertices& cv : ch.new_cells) ch.made.add(angle(cv), bound_);
    return true;
  }

  // the best change among the 2-3 flips of c's facets and the removals of its
  // edges; 0 if none improves, 1 for a 2-3 flip, 2 for an edge removal
  int improve(Cell_handle c)
  {
    const Subdomain_index region = c3t3_.subdomain_index(c);
    Change best, ch;
    int kind = 0;
    auto consider = [&](int k) {
      Cell_set_quality destroyed;
      for(Cell_handle h : ch.old_cells) destroyed.add(cell_smallest_dihedral_angle(tr_, h), bound_);
      if(!ch.made.replaces(destroyed, angle_tolerance)) return;
      if(kind != 0 && !(ch.made.min_angle > best.made.min_angle)) return;
      best = ch;
      kind = k;
    };
    for(int i = 0; i < 4; ++i)
      if(flip_2_3(c, i, region, ch)) consider(1);
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(remove_edge(c, i, j, region, ch)) consider(2);
    if(kind != 0) replace(best, region);
    return kind;
  }

  void replace(const Change& ch, const Subdomain_index& region)
  {
    replace_cells(c3t3_, ch.old_cells, ch.new_cells, [&](std::size_t) { return region; });
  }

  C3T3& c3t3_;
  Tr& tr_;
  double bound_;
  // largest ring of an edge removal: the dynamic programming is cubic in it,
  // and larger rings rarely triangulate better
  static constexpr std::size_t max_ring = 7;
  // a change must gain at least this (degrees) over what it replaces
  static constexpr double angle_tolerance = 1e-6;
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_FLIP_SLIVERS_H
