// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_FLIP_COCIRCULAR_DIAGONALS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_FLIP_COCIRCULAR_DIAGONALS_H

// Four coplanar, cocircular points (a quad of a structured grid) have two
// Delaunay triangulations. CGAL breaks the tie by a symbolic perturbation that
// depends on the points' lexicographic order only: the diagonal that avoids
// the largest of the four corners. Every quad of a grid then gets the same
// diagonal, and where the input's diagonals go the other way every input
// triangle is missing, and recovery would split each quad by a Steiner point.
//
// Here a missing input edge ac whose two input triangles abc and acd form a
// cocircular quad crossed by the triangulation edge bd gets bd replaced by ac:
// usually the 4-4 flip of the ring of four cells around bd (two on each side
// of the quad's plane; on the convex hull two of them are infinite), else
// the fans of cospherical cells on each side re-triangulated from a (see
// plan_cocircular_flip()). The new cells have the circumspheres of the old
// ones, so the triangulation stays Delaunay
// in the non-strict sense (is_valid() holds), but it is no longer the one
// CGAL's perturbation defines. What this means later:
//
// - removing a vertex whose star has both halves of a flipped quad on its
//   boundary is undefined behaviour: CGAL re-triangulates the hole with the
//   canonical triangulation of the link, which has the other diagonal, and
//   does not find the hole's boundary facets (an assertion in debug builds).
//   is_vertex_removal_safe() tells, exactly, whether a removal is safe; every
//   caller that removes vertices from a triangulation that may hold flipped
//   quads must ask it first;
// - inserting a point exactly on the circumsphere of a flipped cell lets the
//   perturbation decide its conflicts, and the conflict zone can then fail to
//   be star-shaped. is_star_shaped_conflict_zone() checks a zone exactly,
//   and find_strict_conflicts() gives one that always is (ties counted as no
//   conflict); a point strictly inside or outside every such sphere is
//   harmless.
//
// Hence the rules: a quad is flipped only if the vertices around it off its
// plane are infinite or model points - vertices nothing removes (interior
// points outside the model are removed by tetrahedralize_bubbles(), interior
// vertices moved by remove_slivers()); a Steiner point whose conflict zone is
// not star-shaped is inserted with the strict zone. A vertex inserted later
// strictly inside a flipped cell's circumsphere becomes adjacent to the quad:
// whatever may remove it (the perturbation of remove_slivers()) must ask
// is_vertex_removal_safe() first.

#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <map>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// what flip_cocircular_diagonals() found and did
struct Cocircular_flip_statistics
{
  std::size_t number_of_missing_edges = 0;     ///< input edges that were not triangulation edges
  std::size_t number_of_cocircular_quads = 0;  ///< ... of which the diagonal of a cocircular quad of input triangles
  std::size_t number_of_flips = 0;             ///< ... of which flipped
  std::size_t number_of_refused_apexes = 0;    ///< ... refused: an apex that may be removed later
  std::size_t number_of_refused_rings = 0;     ///< ... refused: the cells around the crossing edge do not allow it
};

/// a flip: the quad (a, b, c, d), ac the new diagonal, and the cells before and after
template <class Tr>
struct Cocircular_flip
{
  typedef std::array<typename Tr::Vertex_handle, 4> Cell_vertices; // positively oriented
  std::array<typename Tr::Vertex_handle, 4> quad;
  std::vector<Cell_vertices> old_cells, new_cells;
};

/*
Replaces the cells `old` by cells with the vertices `made` (each positively
oriented), which must fill the same region with the same boundary facets:
TDS operations only, vertex -> cell pointers kept valid.
*/
template <class Tr>
void replace_cells(Tr& tr, const std::vector<typename Tr::Cell_handle>& old,
                   const std::vector<std::array<typename Tr::Vertex_handle, 4> >& made)
{
  typedef typename Tr::Cell_handle   Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef std::array<Vertex_handle, 3> Triple;
  auto facet_key = [](Cell_handle c, int k) {
    Triple t = {{c->vertex((k + 1) & 3), c->vertex((k + 2) & 3), c->vertex((k + 3) & 3)}};
    std::sort(t.begin(), t.end());
    return t;
  };
  const std::unordered_set<Cell_handle> old_set(old.begin(), old.end());
  std::map<Triple, std::pair<Cell_handle, int> > outer;
  for(Cell_handle r : old)
    for(int k = 0; k < 4; ++k)
    {
      const Cell_handle n = r->neighbor(k);
      if(old_set.count(n) == 0) outer[facet_key(r, k)] = std::make_pair(n, n->index(r));
    }
  std::vector<Cell_handle> cells;
  for(const auto& v : made) cells.push_back(tr.tds().create_cell(v[0], v[1], v[2], v[3]));
  std::map<Triple, std::pair<Cell_handle, int> > inner;
  CGAL_assertion_code(std::size_t glued = 0;)
  for(Cell_handle m : cells)
    for(int k = 0; k < 4; ++k)
    {
      const Triple t = facet_key(m, k);
      auto o = outer.find(t);
      if(o != outer.end())
      {
        tr.tds().set_adjacency(m, k, o->second.first, o->second.second);
        CGAL_assertion_code(++glued;)
        continue;
      }
      auto in = inner.find(t);
      if(in == inner.end()) inner.emplace(t, std::make_pair(m, k));
      else
      {
        tr.tds().set_adjacency(m, k, in->second.first, in->second.second);
        inner.erase(in);
      }
    }
  CGAL_assertion(glued == outer.size() && inner.empty());
  for(Cell_handle r : old) tr.tds().delete_cell(r);
  for(Cell_handle m : cells)
    for(int k = 0; k < 4; ++k) m->vertex(k)->set_cell(m);
}

/*
Plans replacing the edge (c, i, j) = bd by ac, where a, b, c, d are coplanar
and cocircular, b and d on either side of ac. The ring of vertices around bd
is a, x1..xk, c, y1..ym: each side of the quad's plane holds a fan of cells
(b, d, s, s') between a and c. Each fan is replaced by the cone from a over
its facets that do not contain a: cells (a, b, s, s') and (a, d, s, s'),
the old cell (b, d, s, s') with d, respectively b, replaced by a (with more
than one apex, the cone from c or from an apex if that from a does not fit).

With one apex on a side (k = 1, the 4-4 flip when both sides have one) the
new cells (a,b,x,c) and (a,d,x,c) have the circumsphere of the old ones (the
sphere through the quad's circle and x), and the substitution keeps the
orientation: a lies on the same side of the lines bc and dc as d and b; this
holds for an infinite x too, whose cells' finite facets lie in the quad's
plane. With more apexes, they must all lie on the sphere through the circle
and x1 (then every new cell has it as circumsphere, and it is empty), be
finite, and every new cell must be positively oriented (exact): the cone
from a vertex of the region over its other boundary facets, all positive,
fills the region once. Returns false if no cone fits.
*/
template <class Tr>
bool plan_cocircular_flip(const Tr& tr, typename Tr::Cell_handle c, int i, int j, typename Tr::Vertex_handle va,
                          typename Tr::Vertex_handle vc, Cocircular_flip<Tr>& flip)
{
  typedef typename Tr::Cell_handle   Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Geom_traits::Point_3 Point_3;
  const auto& gt = tr.geom_traits();
  const auto point = [&](Vertex_handle v) -> Point_3 { return gt.construct_point_3_object()(tr.point(v)); };
  const Vertex_handle vb = c->vertex(i), vd = c->vertex(j);

  // the cells around bd in order, and the ring vertex each shares with the next
  std::vector<Cell_handle> ring;
  typename Tr::Cell_circulator cc = tr.incident_cells(c, i, j), done = cc;
  do ring.push_back(cc); while(++cc != done);
  const std::size_t n = ring.size();
  auto others = [&](Cell_handle x) {
    std::array<Vertex_handle, 2> o;
    int k = 0;
    for(int l = 0; l < 4; ++l)
      if(x->vertex(l) != vb && x->vertex(l) != vd) o[k++] = x->vertex(l);
    return o;
  };
  std::vector<Vertex_handle> shared(n); // shared[t]: between ring[t] and ring[t+1]
  for(std::size_t t = 0; t < n; ++t)
  {
    const auto o = others(ring[t]), p = others(ring[(t + 1) % n]);
    shared[t] = (o[0] == p[0] || o[0] == p[1]) ? o[0] : o[1];
  }
  // ring[t] lies between shared[t-1] and shared[t]; start at a
  const std::size_t ia = std::find(shared.begin(), shared.end(), va) - shared.begin();
  const std::size_t ic = std::find(shared.begin(), shared.end(), vc) - shared.begin();
  if(ia == n || ic == n) return false;

  flip.quad = {{va, vb, vc, vd}};
  flip.old_cells.clear();
  flip.new_cells.clear();
  for(Cell_handle x : ring) flip.old_cells.push_back({{x->vertex(0), x->vertex(1), x->vertex(2), x->vertex(3)}});

  // the two fans: from a to c, then from c to a
  for(int side = 0; side < 2; ++side)
  {
    const std::size_t from = side == 0 ? ia : ic, to = side == 0 ? ic : ia;
    std::vector<Vertex_handle> apexes;
    for(std::size_t t = (from + 1) % n; t != to; t = (t + 1) % n) apexes.push_back(shared[t]);
    if(apexes.empty()) return false; // a cell abcd: cannot be in a valid triangulation
    if(apexes.size() > 1)
    {
      const Point_3 pa = point(va), pb = point(vb), pd = point(vd);
      for(Vertex_handle x : apexes)
        if(tr.is_infinite(x)) return false;
      const Point_3 p1 = point(apexes.front());
      for(std::size_t k = 1; k < apexes.size(); ++k)
        if(gt.side_of_bounded_sphere_3_object()(pa, pb, pd, p1, point(apexes[k])) != CGAL::ON_BOUNDARY)
          return false;
    }
    std::vector<Cell_handle> fan; // the cells (b, d, s, s') of this side
    for(std::size_t t = (from + 1) % n;; t = (t + 1) % n)
    {
      fan.push_back(ring[t]);
      if(t == to) break;
    }
    // the cone from `apex` over the side's boundary facets that do not contain
    // it: the facets (b|d, s, s') of the fan's cells, and the two triangles
    // abc, acd (unless the apex is a or c)
    auto cone = [&](Vertex_handle apex, bool check) {
      std::vector<std::array<Vertex_handle, 4> > cells;
      for(Cell_handle x : fan)
        for(Vertex_handle replaced : {vd, vb})
        {
          if(x->has_vertex(apex)) continue; // the facet contains the apex, or it is the cell's own
          std::array<Vertex_handle, 4> v;
          for(int k = 0; k < 4; ++k) v[k] = x->vertex(k) == replaced ? apex : x->vertex(k);
          if(check && gt.orientation_3_object()(point(v[0]), point(v[1]), point(v[2]), point(v[3])) != CGAL::POSITIVE)
            return false;
          cells.push_back(v);
        }
      if(apex != va && apex != vc)
        for(Vertex_handle third : {vb, vd})
        {
          std::array<Vertex_handle, 4> v = {{apex, va, third, vc}};
          if(gt.orientation_3_object()(point(v[0]), point(v[1]), point(v[2]), point(v[3])) == CGAL::NEGATIVE)
            std::swap(v[2], v[3]);
          cells.push_back(v);
        }
      flip.new_cells.insert(flip.new_cells.end(), cells.begin(), cells.end());
      return true;
    };
    if(apexes.size() == 1) cone(va, false);
    else
    {
      bool done = false;
      for(Vertex_handle apex : {va, vc}) done = done || cone(apex, true);
      for(std::size_t k = 0; k < apexes.size() && !done; ++k) done = cone(apexes[k], true);
      if(!done) return false;
    }
  }
  return true;
}

/*
For every input edge ac that is not a triangulation edge, while two of its
input triangles abc and acd form a quad crossed by the triangulation edge bd:
if a, b, c, d are coplanar and cocircular (exact predicates), b and d on
either side of ac, the cells around bd are replaced by cells around ac (see
plan_cocircular_flip()). The two triangles may be of one patch or of two
(coplanar patches meeting along ac, or a fault lying on a horizon): the flip
only makes both triangles facets, whichever surfaces they bound, and patch
labels are given later from the input triangles themselves.

`vertex_of_point[p]` is the vertex of model point `p`; `triangles` the input
triangles (arrays of three point indices). With `input_apexes_only` (the
safe rule, see the top of this file), a quad whose ring has a vertex off its
plane that is neither infinite nor a model point is left alone. Edges are
taken in lexicographic order of their point indices, in passes repeated while
one flips (a flip can make a neighbouring one possible), so the result
depends on nothing else. The flips done are appended to `flips` if given.
*/
template <class Tr, class TriangleRange>
Cocircular_flip_statistics
flip_cocircular_diagonals(Tr& tr, const std::vector<typename Tr::Vertex_handle>& vertex_of_point,
                          const TriangleRange& triangles, bool input_apexes_only = true,
                          std::vector<Cocircular_flip<Tr> >* flips = nullptr)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle   Cell_handle;
  typedef typename Tr::Geom_traits   Gt;
  typedef typename Gt::Point_3       Point_3;

  Cocircular_flip_statistics stats;
  if(tr.dimension() != 3) return stats;
  const Gt& gt = tr.geom_traits();
  const auto point = [&](Vertex_handle v) -> Point_3 { return gt.construct_point_3_object()(tr.point(v)); };
  const auto coplanar = gt.coplanar_3_object();
  const auto in_circle = gt.coplanar_side_of_bounded_circle_3_object();
  const auto coplanar_orientation = gt.coplanar_orientation_3_object();

  // (input edge a < c, third point of one of its input triangles)
  std::vector<std::pair<std::array<std::size_t, 2>, std::size_t> > halves;
  for(const auto& t : triangles)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = t[k], c = t[(k + 1) % 3];
      halves.push_back(std::make_pair(std::array<std::size_t, 2>{{(std::min)(a, c), (std::max)(a, c)}}, t[(k + 2) % 3]));
    }
  std::sort(halves.begin(), halves.end());
  halves.erase(std::unique(halves.begin(), halves.end()), halves.end());

  const std::unordered_set<Vertex_handle> input_vertices(vertex_of_point.begin(), vertex_of_point.end());
  Cocircular_flip<Tr> flip;
  std::vector<Cell_handle> old;
  // a flip can make another possible (a quad next to it shares cells with
  // it), so passes are repeated while they flip; the statistics are those of
  // the last pass, plus all flips
  std::size_t total_flips = 0;
  for(int pass = 0; pass < 8; ++pass)
  {
    stats = Cocircular_flip_statistics();
    for(std::size_t first = 0; first < halves.size();)
    {
      std::size_t last = first;
      while(last < halves.size() && halves[last].first == halves[first].first) ++last;
      const Vertex_handle va = vertex_of_point[halves[first].first[0]], vc = vertex_of_point[halves[first].first[1]];
      Cell_handle c;
      int i, j;
      if(tr.is_edge(va, vc, c, i, j)) { first = last; continue; }
      ++stats.number_of_missing_edges;
      const Point_3 pa = point(va), pc = point(vc);
      bool found = false;
      for(std::size_t x = first; x < last && !found; ++x)
        for(std::size_t y = x + 1; y < last && !found; ++y)
        {
          const Vertex_handle vb = vertex_of_point[halves[x].second], vd = vertex_of_point[halves[y].second];
          const Point_3 pb = point(vb), pd = point(vd);
          if(!coplanar(pa, pb, pc, pd) || coplanar_orientation(pa, pc, pb, pd) != CGAL::NEGATIVE ||
             in_circle(pa, pb, pc, pd) != CGAL::ON_BOUNDARY)
            continue;
          // a convex cocircular quad: bd is the only edge that can cross ac in it
          found = true;
          ++stats.number_of_cocircular_quads;
          if(!tr.is_edge(vb, vd, c, i, j) || !plan_cocircular_flip(tr, c, i, j, va, vc, flip))
          {
            ++stats.number_of_refused_rings;
            continue;
          }
          bool apexes_stay = true;
          for(const auto& cell : flip.old_cells)
            for(Vertex_handle w : cell)
              if(input_apexes_only && !tr.is_infinite(w) && input_vertices.count(w) == 0) apexes_stay = false;
          if(!apexes_stay)
          {
            ++stats.number_of_refused_apexes;
            continue;
          }
          old.clear();
          typename Tr::Cell_circulator cc = tr.incident_cells(c, i, j), done = cc;
          do old.push_back(cc); while(++cc != done);
          replace_cells(tr, old, flip.new_cells);
          ++stats.number_of_flips;
          if(flips) flips->push_back(flip);
        }
      first = last;
    }
    total_flips += stats.number_of_flips;
    if(stats.number_of_flips == 0) break;
  }
  stats.number_of_flips = total_flips;
  return stats;
}

/*
Whether CGAL can remove `v` from `tr`: it fills the hole with the
triangulation of the link that its perturbation defines (a new, canonical
one), and needs every facet of the hole's boundary in it. Exact; true for
every vertex of a triangulation CGAL built. Checked on a small triangulation
of the link, so about as costly as the removal itself.
*/
template <class Tr>
bool is_vertex_removal_safe(const Tr& tr, typename Tr::Vertex_handle v)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle   Cell_handle;
  if(tr.dimension() != 3 || tr.is_infinite(v)) return false;
  std::vector<Cell_handle> star;
  tr.incident_cells(v, std::back_inserter(star));
  std::vector<Vertex_handle> link;
  for(Cell_handle c : star)
    for(int k = 0; k < 4; ++k)
      if(c->vertex(k) != v) link.push_back(c->vertex(k));
  std::sort(link.begin(), link.end());
  link.erase(std::unique(link.begin(), link.end()), link.end());

  Tr tmp;
  std::unordered_map<Vertex_handle, Vertex_handle> to_tmp;
  for(Vertex_handle x : link)
  {
    if(tr.is_infinite(x)) to_tmp[x] = tmp.infinite_vertex();
    else to_tmp[x] = tmp.insert(x->point());
  }
  if(tmp.dimension() != 3) return false;
  for(Cell_handle c : star)
  {
    const int k = c->index(v);
    Cell_handle t;
    int i0, i1, i2;
    if(!tmp.is_facet(to_tmp[c->vertex((k + 1) & 3)], to_tmp[c->vertex((k + 2) & 3)],
                     to_tmp[c->vertex((k + 3) & 3)], t, i0, i1, i2))
      return false;
  }
  return true;
}

/*
Whether the conflict zone `cells` of point `p` (as find_conflicts() gives it)
is star-shaped from `p`: every new cell, a boundary facet joined to `p`, is
positively oriented (exact). A zone of a triangulation CGAL built always is;
with flipped quads, one of a point exactly on a flipped cell's circumsphere
may not be, and insert_in_hole() would then corrupt the triangulation.
*/
template <class Tr>
bool is_star_shaped_conflict_zone(const Tr& tr, const typename Tr::Geom_traits::Point_3& p,
                                  const std::vector<typename Tr::Cell_handle>& cells)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Geom_traits::Point_3 Point_3;
  const auto& gt = tr.geom_traits();
  std::unordered_set<Cell_handle> zone(cells.begin(), cells.end());
  for(Cell_handle c : cells)
    for(int i = 0; i < 4; ++i)
    {
      if(zone.count(c->neighbor(i)) != 0) continue;
      // the new cell is c with vertex i replaced by p
      std::array<Point_3, 4> q;
      int infinite = -1;
      for(int k = 0; k < 4; ++k)
      {
        if(k == i) { q[k] = p; continue; }
        if(tr.is_infinite(c->vertex(k))) { infinite = k; continue; }
        q[k] = gt.construct_point_3_object()(tr.point(c->vertex(k)));
      }
      if(infinite < 0)
      {
        if(gt.orientation_3_object()(q[0], q[1], q[2], q[3]) != CGAL::POSITIVE) return false;
        continue;
      }
      // an infinite cell: its finite facet, with p, must face away from the
      // other finite vertices like the old one (p strictly outside the hull
      // facet it replaces a vertex of, or on the far side of it)
      const Cell_handle m = c->neighbor(infinite);
      const int mi = m->index(c);
      const Point_3 inner = gt.construct_point_3_object()(tr.point(m->vertex(mi)));
      q[infinite] = inner;
      if(gt.orientation_3_object()(q[0], q[1], q[2], q[3]) != CGAL::NEGATIVE) return false;
    }
  return true;
}

/*
The cells whose circumsphere strictly contains `p` (a tie is no conflict),
found from `start`, which must contain `p` (as locate() gives it), and the
facets of the zone's boundary (seen from inside). In a Delaunay
triangulation, also one CGAL's perturbation did not build, this zone is
star-shaped from `p` (across a boundary facet the two circumspheres differ,
and `p` has a smaller power to the inner one: it lies on the inner cell's
side of the facet), so insert_in_hole() with it is safe; use it when the
zone find_conflicts() gives is not. Empty if `p` is on `start`'s circumsphere.
*/
template <class Tr>
void find_strict_conflicts(const Tr& tr, const typename Tr::Weighted_point& p, typename Tr::Cell_handle start,
                           std::vector<typename Tr::Cell_handle>& zone, std::vector<typename Tr::Facet>& boundary)
{
  typedef typename Tr::Cell_handle Cell_handle;
  zone.clear();
  boundary.clear();
  std::unordered_set<Cell_handle> inside, outside;
  auto conflict = [&](Cell_handle c) {
    if(inside.count(c)) return true;
    if(outside.count(c)) return false;
    const bool in = tr.side_of_power_sphere(c, p, false) == CGAL::ON_BOUNDED_SIDE;
    (in ? inside : outside).insert(c);
    return in;
  };
  if(!conflict(start)) return;
  zone.push_back(start);
  for(std::size_t k = 0; k < zone.size(); ++k)
  {
    const Cell_handle c = zone[k];
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = c->neighbor(i);
      const bool known = inside.count(n) != 0;
      if(conflict(n))
      {
        if(!known) zone.push_back(n);
      }
      else
        boundary.push_back(typename Tr::Facet(c, i));
    }
  }
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_FLIP_COCIRCULAR_DIAGONALS_H
