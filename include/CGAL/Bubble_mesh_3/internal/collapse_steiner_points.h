// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_COLLAPSE_STEINER_POINTS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_COLLAPSE_STEINER_POINTS_H

// Collapse of Steiner points of the recovery (a step of `remove_slivers()`,
// before the flips).
//
// A conforming recovery cuts an input triangle with a needle angle into many
// small pieces, and every piece makes poor cells: on CloudSpin most of the
// cells under 10 degrees stand on such pieces. Once the cells are there, a
// Steiner point `v` can often go again: its edge to a neighbour `u` is
// collapsed (every cell around `v` not holding `u` takes `u` for `v`, the cells
// around the edge vanish). The surfaces stay where they are when `u` lies on
// every input triangle `v` lies on (`Surface_vertex_supports::may_collapse()`):
// the facets around `v` then become facets on the same triangles. Kept only if
// - the link condition holds (the result is a triangulation),
// - every changed cell is positively oriented by the exact predicate (the
//   new cells partition the old star, so region volumes stay),
// - a facet between two regions is still a complex facet, and no two complex
//   facets fall onto one,
// - the changed cells are no worse than the old star: smallest angle not
//   smaller, no more cells under the bound,
// - no moved complex facet becomes a cap (three points all but on one line, as
//   when `v` inside a triangle goes onto a Steiner point of an edge that holds
//   two more): such a facet has no area, its cells are flat, and neither flips
//   nor insertion may take a complex facet away. modelA5 with the surfaces
//   kept had 43 caps without this rule, and 1e-14 degree cells on them.
//   (Thin caps are left: an input triangle's needle makes those anyway.)
// Stars touching the infinite vertex are left alone.
//
// Like the flips, the result is no longer a regular triangulation.

#include <CGAL/Bubble_mesh_3/internal/perturb_interior_vertices.h>
#include <CGAL/Bubble_mesh_3/internal/vertex_angle.h> // angle_degrees

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// What the collapses did.
struct Collapse_statistics
{
  std::size_t number_of_passes = 0;
  std::size_t number_of_steiner_points_tried = 0;
  std::size_t number_of_collapses = 0;
  bool time_limit_reached = false;
};

template <class C3T3, class Supports>
class Steiner_point_collapser
{
  typedef typename C3T3::Triangulation       Tr;
  typedef typename Tr::Vertex_handle         Vertex_handle;
  typedef typename Tr::Cell_handle           Cell_handle;
  typedef typename Tr::Facet                 Facet;
  typedef typename Tr::Bare_point            Bare_point;
  typedef typename C3T3::Subdomain_index     Subdomain_index;
  typedef typename C3T3::Surface_patch_index Surface_patch_index;
  typedef std::array<Vertex_handle, 4>       Cell_vertices;
  typedef std::array<Vertex_handle, 3>       Triple;

public:
  // `floor`: no collapse makes a cell with a smaller angle than this (the mesh's smallest)
  Steiner_point_collapser(C3T3& c3t3, Supports& supports, double sliver_bound, double floor)
    : c3t3_(c3t3), tr_(c3t3.triangulation()), supports_(supports), bound_(sliver_bound), floor_(floor)
  {}

  // Passes over the Steiner points in their recorded order until one
  // collapses none (at most `max_passes`) or `time_limit` seconds are spent.
  Collapse_statistics operator()(std::size_t max_passes, double time_limit)
  {
    Collapse_statistics stats;
    if(tr_.dimension() != 3) return stats;
    CGAL::Real_timer timer;
    timer.start();
    const std::vector<Vertex_handle> points = supports_.steiner_points();
    for(std::size_t pass = 0; pass < max_passes && !stats.time_limit_reached; ++pass)
    {
      ++stats.number_of_passes;
      std::size_t changed = 0;
      for(Vertex_handle v : points)
      {
        if(!supports_.contains(v)) continue;
        if(timer.time() > time_limit) { stats.time_limit_reached = true; break; }
        ++stats.number_of_steiner_points_tried;
        if(collapse(v)) ++changed;
      }
      stats.number_of_collapses += changed;
      if(changed == 0) break;
    }
    return stats;
  }

private:
  // what a collapse compares: the smallest angle, the cells under the bound,
  // and the cells under 1 and 5 degrees
  struct Star_quality : Cell_set_quality
  {
    std::size_t flat[2] = {0, 0};
    void add(double angle, double bound)
    {
      Cell_set_quality::add(angle, bound);
      flat[0] += angle < 1. ? 1 : 0;
      flat[1] += angle < 5. ? 1 : 0;
    }
  };

  // the cells v's star becomes when v goes onto u
  struct Plan
  {
    Vertex_handle u;
    std::vector<Cell_vertices> cells;
    std::vector<Subdomain_index> labels;
    std::map<Triple, Surface_patch_index> complex_facets; // the new complex facets at u
    Star_quality made;
  };

  Bare_point point(Vertex_handle v) const { return tr_.geom_traits().construct_point_3_object()(v->point()); }

  // largest angle (degrees) of triangle t
  double largest_angle(const Triple& t) const
  {
    double largest = 0.;
    for(int i = 0; i < 3; ++i)
      largest = (std::max)(largest, angle_degrees(vertex_coordinates(tr_, t[i]), vertex_coordinates(tr_, t[(i + 1) % 3]),
                                                  vertex_coordinates(tr_, t[(i + 2) % 3])));
    return largest;
  }
  // `after` (a complex facet moved) has its three points all but on a line,
  // and `before` did not
  bool is_new_cap(const Triple& before, const Triple& after) const
  {
    const double a = largest_angle(after);
    return a > cap_angle && a > largest_angle(before);
  }

  Subdomain_index label(Cell_handle c) const { return c3t3_.is_in_complex(c) ? c3t3_.subdomain_index(c) : Subdomain_index(); }

  // Lk(v) and Lk(u) share only Lk(vu), vertices and edges: else the collapse
  // glues two parts of the triangulation together
  bool link_condition(Vertex_handle v, Vertex_handle u, const std::vector<Cell_handle>& star_v) const
  {
    std::vector<Cell_handle> star_u;
    tr_.incident_cells(u, std::back_inserter(star_u));
    std::set<Vertex_handle> link_vu_vertices;
    std::set<std::pair<Vertex_handle, Vertex_handle> > link_vu_edges;
    std::set<Vertex_handle> link_v;
    std::set<std::pair<Vertex_handle, Vertex_handle> > edges_v;
    auto edge = [](Vertex_handle a, Vertex_handle b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); };
    // the three vertices of c other than x, in cell order
    auto others = [](Cell_handle c, Vertex_handle x, Vertex_handle (&w)[3]) {
      int k = 0;
      for(int i = 0; i < 4; ++i)
        if(c->vertex(i) != x) w[k++] = c->vertex(i);
    };
    for(Cell_handle c : star_v)
    {
      Vertex_handle w[3];
      others(c, v, w);
      for(int i = 0; i < 3; ++i)
      {
        if(w[i] != u) link_v.insert(w[i]);
        if(w[i] != u && w[(i + 1) % 3] != u) edges_v.insert(edge(w[i], w[(i + 1) % 3]));
      }
      if(c->has_vertex(u))
      {
        Vertex_handle o[2];
        int m = 0;
        for(int i = 0; i < 3; ++i)
          if(w[i] != u) o[m++] = w[i];
        link_vu_vertices.insert(o[0]);
        link_vu_vertices.insert(o[1]);
        link_vu_edges.insert(edge(o[0], o[1]));
      }
    }
    for(Cell_handle c : star_u)
    {
      Vertex_handle w[3];
      others(c, u, w);
      for(int i = 0; i < 3; ++i)
      {
        if(w[i] == v) continue;
        if(link_v.count(w[i]) != 0 && link_vu_vertices.count(w[i]) == 0) return false;
        const Vertex_handle x = w[(i + 1) % 3];
        if(x == v) continue;
        const auto e = edge(w[i], x);
        if(edges_v.count(e) != 0 && link_vu_edges.count(e) == 0) return false;
      }
    }
    return true;
  }

  // The plan of collapsing v onto u, false when the collapse cannot be made or would
  // leave more than `max_under` cells under the bound (it could not be kept). The link
  // condition is left to the caller: it is the dearest check, and most plans fail on
  // quality first.
  bool plan(Vertex_handle v, Vertex_handle u, const std::vector<Cell_handle>& star,
            const std::map<Triple, Surface_patch_index>& complex_at_v, std::size_t max_under, Plan& p) const
  {
    p = Plan();
    p.u = u;
    // new complex facets: those at v moved onto u; the ones holding u vanish
    for(const auto& f : complex_at_v)
    {
      if(std::find(f.first.begin(), f.first.end(), u) != f.first.end()) continue;
      Triple t = f.first;
      std::replace(t.begin(), t.end(), v, u);
      // three points of one input edge (v inside a triangle, u and the two
      // others Steiner points of its edge): a facet of no area, whose cells
      // are flat for good - no flip or insertion may take a complex facet away
      if(is_new_cap(f.first, t)) return false;
      std::sort(t.begin(), t.end());
      if(!p.complex_facets.emplace(t, f.second).second) return false;
    }
    const auto orientation = tr_.geom_traits().orientation_3_object();
    const Bare_point up = point(u);
    // facets of the new cells that hold u: shared by two new cells, or glued
    // to the outer neighbour of a vanishing cell (its facet opposite v)
    std::map<Triple, std::pair<Subdomain_index, bool> > outer; // label of the cell outside, complex there
    for(Cell_handle c : star)
    {
      if(!c->has_vertex(u)) continue;
      const int iv = c->index(v);
      const Cell_handle n = c->neighbor(iv);
      outer.emplace(facet_key(c, iv), std::make_pair(label(n), c3t3_.is_in_complex(n, n->index(c))));
    }
    std::map<Triple, Subdomain_index> open; // facets holding u met once so far
    for(Cell_handle c : star)
    {
      if(c->has_vertex(u)) continue;
      Cell_vertices cv;
      Bare_point q[4];
      for(int i = 0; i < 4; ++i)
      {
        cv[i] = c->vertex(i) == v ? u : c->vertex(i);
        q[i] = cv[i] == u ? up : point(cv[i]);
      }
      if(orientation(q[0], q[1], q[2], q[3]) != CGAL::POSITIVE) return false;
      const Subdomain_index l = label(c);
      for(int i = 0; i < 4; ++i)
      {
        if(cv[i] == u) continue;
        const Triple t = sorted_triple(cv[(i + 1) % 4], cv[(i + 2) % 4], cv[(i + 3) % 4]);
        const bool is_complex = p.complex_facets.count(t) != 0;
        const auto o = outer.find(t);
        if(o != outer.end())
        {
          if(is_complex && o->second.second) return false; // two surfaces onto one facet
          if(!(o->second.first == l) && !is_complex && !o->second.second) return false;
          continue;
        }
        const auto m = open.find(t);
        if(m == open.end()) open.emplace(t, l);
        else
        {
          if(!(m->second == l) && !is_complex) return false;
          open.erase(m);
        }
      }
      p.cells.push_back(cv);
      p.labels.push_back(l);
      if(!(l == Subdomain_index()))
      {
        p.made.add(smallest_dihedral_angle(vertex_coordinates(tr_, cv[0]), vertex_coordinates(tr_, cv[1]),
                                           vertex_coordinates(tr_, cv[2]), vertex_coordinates(tr_, cv[3])),
                   bound_);
        if(p.made.under_bound > max_under) return false;
      }
    }
    return open.empty(); // else not a closed star: a facet lost its other side
  }

  bool collapse(Vertex_handle v)
  {
    std::vector<Cell_handle> star;
    tr_.incident_cells(v, std::back_inserter(star));
    Star_quality old_star;
    std::map<Triple, Surface_patch_index> complex_at_v;
    std::vector<Vertex_handle> candidates;
    for(Cell_handle c : star)
    {
      if(tr_.is_infinite(c)) return false;
      if(c3t3_.is_in_complex(c)) old_star.add(cell_smallest_dihedral_angle(tr_, c), bound_);
      const int iv = c->index(v);
      for(int i = 0; i < 4; ++i)
      {
        if(i == iv) continue;
        if(c3t3_.is_in_complex(c, i)) complex_at_v.emplace(facet_key(c, i), c3t3_.surface_patch_index(c, i));
        const Vertex_handle w = c->vertex(i);
        if(std::find(candidates.begin(), candidates.end(), w) == candidates.end() && supports_.may_collapse(v, w))
          candidates.push_back(w);
      }
    }
    Plan best, p;
    bool found = false;
    for(Vertex_handle u : candidates)
    {
      // a plan with more cells under the bound than the star, or than the best so far, is not kept
      const std::size_t max_under = found ? (std::min)(old_star.under_bound, best.made.under_bound) : old_star.under_bound;
      if(!plan(v, u, star, complex_at_v, max_under, p)) continue;
      // fewer cells under the bound and no more under 1 and 5 degrees, none
      // under the mesh's smallest angle; or as many, none worse than the
      // worst of the star
      const bool fewer = p.made.under_bound < old_star.under_bound && p.made.min_angle >= floor_ &&
                         p.made.flat[0] <= old_star.flat[0] && p.made.flat[1] <= old_star.flat[1];
      const bool no_worse = p.made.under_bound <= old_star.under_bound && p.made.min_angle >= old_star.min_angle;
      if(!fewer && !no_worse) continue;
      if(found && (p.made.under_bound > best.made.under_bound ||
                   (p.made.under_bound == best.made.under_bound && !(p.made.min_angle > best.made.min_angle))))
        continue;
      if(!link_condition(v, u, star)) continue;
      best = p;
      found = true;
    }
    if(!found) return false;
    apply(v, star, best);
    return true;
  }

  void apply(Vertex_handle v, const std::vector<Cell_handle>& star, const Plan& p)
  {
    // the complex facets at v go; the moved ones come back on the new cells
    for(Cell_handle c : star)
      for(int i = 0; i < 4; ++i)
        if(c->vertex(i) != v && c3t3_.is_in_complex(c, i)) c3t3_.remove_from_complex(Facet(c, i));
    replace_cells(c3t3_, star, p.cells, [&](std::size_t k) { return p.labels[k]; });
    for(const auto& f : p.complex_facets)
    {
      Cell_handle c;
      int i = -1, j = -1, k = -1;
      const bool found = tr_.is_facet(f.first[0], f.first[1], f.first[2], c, i, j, k);
      CGAL_assertion(found);
      if(found) c3t3_.add_to_complex(Facet(c, 6 - i - j - k), f.second);
    }
    tr_.tds().delete_vertex(v);
    supports_.erase(v);
  }

  C3T3& c3t3_;
  Tr& tr_;
  Supports& supports_;
  double bound_;
  double floor_;
  // a facet with a larger angle (degrees) is a cap, its points all but on a
  // line: its cells are flat (their smallest angles are at most its smaller two)
  static constexpr double cap_angle = 180. - flat_cell_angle;
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_COLLAPSE_STEINER_POINTS_H
