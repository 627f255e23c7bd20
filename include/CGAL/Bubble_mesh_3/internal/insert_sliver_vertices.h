// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_INSERT_SLIVER_VERTICES_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_INSERT_SLIVER_VERTICES_H

// Replaces a small cavity around a sliver by the star of a new interior vertex
// (the last step of `remove_slivers()`).
//
// Slivers whose four vertices lie on surfaces (across a thin layer, or between
// Steiner points of a recovered surface) have no vertex a perturbation may
// move. Here the sliver and one to three rings of its neighbours - across facets
// that are not in the complex, in the same region - form a cavity (for a
// sliver under 10 degrees that they leave above the bound, also the star of
// each of its edges, every vertex of which is on its boundary); a new
// vertex `p` strictly inside the cavity's kernel (every boundary facet sees it
// on its inner side, checked with the exact orientation predicate) is joined to
// the boundary facets. The boundary does not change, so complex facets, surface
// vertices and region volumes stay; the union of the new cells is the cavity.
// A cavity is taken only if its boundary is a sphere through all its vertices
// and it contains no complex facet or edge, and a position only if the new
// cells beat the destroyed ones (larger smallest angle, no more cells under
// the bound; with a flat cell among them, a larger smallest angle is enough).
//
// Cells with an edge on a complex facet whose smallest angle is under
// `forced_angle` are left alone: such a facet makes poor cells whatever is
// inserted next to it (the quality report counts them apart), and on models
// with many such facets trying them took longer than the rest of the pipeline
// (modelA1: 50 s for 8 % fewer cells under 10 degrees). Flat cells
// (`flat_cell_angle`) are tried all the same: few, and the needle only
// explains a thin cell, not one whose four vertices lie in one plane.
//
// The result is a valid triangulation but no longer a regular (Delaunay) one:
// the step runs last, and `remove_slivers()` checks the power test before any
// step that needs it.

#include <CGAL/Bubble_mesh_3/internal/perturb_interior_vertices.h>
#include <CGAL/Bubble_mesh_3/mesh_quality.h> // smallest_triangle_angle

#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// What the insertion did.
struct Insertion_statistics
{
  std::size_t number_of_passes = 0;
  std::size_t number_of_slivers_tried = 0;     // slivers looked at
  std::size_t number_of_slivers_forced = 0;    // left: an edge on a sharp complex facet (last pass)
  std::size_t number_of_vertices_inserted = 0; // accepted stars
  bool time_limit_reached = false;
};

// true if every finite facet passes the power test (the triangulation is
// regular): what removal and re-insertion of vertices need
template <class Tr>
bool is_regular_triangulation(const Tr& tr)
{
  typedef typename Tr::Cell_handle Cell_handle;
  const auto power_side = tr.geom_traits().power_side_of_oriented_power_sphere_3_object();
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    for(int i = 0; i < 4; ++i)
    {
      const auto n = c->neighbor(i);
      if(tr.is_infinite(n) || !(Cell_handle(c) < n)) continue;
      const auto v = n->vertex(n->index(Cell_handle(c)));
      if(power_side(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point(),
                    v->point()) == CGAL::ON_POSITIVE_SIDE)
        return false;
    }
  return true;
}

template <class C3T3>
class Sliver_vertex_inserter
{
  typedef typename C3T3::Triangulation            Tr;
  typedef typename Tr::Vertex_handle              Vertex_handle;
  typedef typename Tr::Cell_handle                Cell_handle;
  typedef typename Tr::Facet                      Facet;
  typedef typename Tr::Weighted_point             Weighted_point;
  typedef typename Tr::Bare_point                 Bare_point;
  typedef typename C3T3::Subdomain_index          Subdomain_index;
  typedef std::array<Vertex_handle, 4>            Cell_vertices;

public:
  Sliver_vertex_inserter(C3T3& c3t3, double sliver_bound, unsigned int number_of_random_positions, unsigned int seed)
    : c3t3_(c3t3), tr_(c3t3.triangulation()), bound_(sliver_bound), number_of_random_(number_of_random_positions),
      random_(seed)
  {}

  // At most `max_passes` passes over the cells under the bound, worst first,
  // until a pass inserts a star for fewer than one in 20 of the cells it
  // tried, or `time_limit` seconds are spent.
  Insertion_statistics operator()(std::size_t max_passes, double time_limit)
  {
    Insertion_statistics stats;
    if(tr_.dimension() != 3) return stats;
    // edges of sharp complex facets; vertices never go, so the set stays right
    for(auto f = c3t3_.facets_in_complex_begin(); f != c3t3_.facets_in_complex_end(); ++f)
    {
      Vec3 q[3];
      Vertex_handle t[3];
      for(int k = 0, j = 0; k < 4; ++k)
        if(k != f->second)
        {
          t[j] = f->first->vertex(k);
          q[j] = coordinates(t[j]);
          ++j;
        }
      if(!(smallest_triangle_angle(q[0], q[1], q[2]) < forced_angle)) continue;
      for(int k = 0; k < 3; ++k) sharp_edges_.insert(edge_key(t[k], t[(k + 1) % 3]));
    }
    CGAL::Real_timer timer;
    timer.start();
    for(std::size_t pass = 0; pass < max_passes; ++pass)
    {
      ++stats.number_of_passes;
      const std::size_t before = stats.number_of_vertices_inserted;
      stats.number_of_slivers_forced = 0;
      auto take = [&](double angle, const Cell_vertices& v) {
        if(angle < flat_cell_angle) return true;
        bool forced = false;
        for(int i = 0; i < 4 && !forced; ++i)
          for(int j = i + 1; j < 4 && !forced; ++j) forced = sharp_edges_.count(edge_key(v[i], v[j])) != 0;
        if(forced) ++stats.number_of_slivers_forced;
        return !forced;
      };
      auto work = [&](Cell_handle c, double angle) {
        if(improve(c, angle)) ++stats.number_of_vertices_inserted;
      };
      const std::size_t tried =
        for_each_sliver_worst_first(c3t3_, bound_, take, work, timer, time_limit, stats.time_limit_reached);
      stats.number_of_slivers_tried += tried;
      if(stats.time_limit_reached || !pass_paid(stats.number_of_vertices_inserted - before, tried, 20)) break;
    }
    return stats;
  }

private:
  Vec3 coordinates(Vertex_handle v) const { return vertex_coordinates(tr_, v); }
  static std::pair<Vertex_handle, Vertex_handle> edge_key(Vertex_handle a, Vertex_handle b)
  {
    return b < a ? std::make_pair(b, a) : std::make_pair(a, b);
  }

  struct Cavity
  {
    std::vector<Cell_handle> cells;
    std::vector<Facet> boundary; // facets of cavity cells whose neighbour is outside
    Cell_set_quality destroyed;
  };

  // The cavity of `rings` rings of neighbours around `c` in `region`, checked.
  bool make_cavity(Cell_handle c, const Subdomain_index& region, int rings, Cavity& cav) const
  {
    std::vector<Cell_handle> cells(1, c);
    std::unordered_set<Cell_handle> in;
    in.insert(c);
    std::size_t first = 0;
    for(int r = 0; r < rings; ++r)
    {
      const std::size_t end = cells.size();
      for(std::size_t k = first; k < end; ++k)
      {
        const Cell_handle h = cells[k];
        for(int i = 0; i < 4; ++i)
        {
          const Cell_handle n = h->neighbor(i);
          if(in.count(n) != 0 || c3t3_.is_in_complex(h, i) || tr_.is_infinite(n) ||
             !(c3t3_.subdomain_index(n) == region))
            continue;
          in.insert(n);
          cells.push_back(n);
        }
      }
      first = end;
    }
    return check_cavity(cells, cav);
  }

  // The cavity of the cells around edge (c, i, j), all in `region`, checked:
  // for a flat cell on a surface, the star of the quad's other diagonal, which
  // a point just off the diagonal's midpoint sees whole.
  bool make_edge_cavity(Cell_handle c, int i, int j, const Subdomain_index& region, Cavity& cav) const
  {
    std::vector<Cell_handle> cells;
    auto circ = tr_.incident_cells(c, i, j), done = circ;
    do
    {
      const Cell_handle h = circ;
      if(tr_.is_infinite(h) || !c3t3_.is_in_complex(h) || !(c3t3_.subdomain_index(h) == region)) return false;
      cells.push_back(h);
      ++circ;
    } while(circ != done);
    return check_cavity(cells, cav);
  }

  // `cav` from `cells`: false unless its boundary is a sphere through all its
  // vertices and it holds no complex facet or edge inside
  bool check_cavity(const std::vector<Cell_handle>& cells, Cavity& cav) const
  {
    cav = Cavity();
    cav.cells = cells;
    const std::unordered_set<Cell_handle> in(cells.begin(), cells.end());
    // boundary facets; facets between cavity cells must not be in the complex
    std::map<std::pair<Vertex_handle, Vertex_handle>, int> edge_uses;
    std::set<Vertex_handle> boundary_vertices, all_vertices;
    for(Cell_handle h : cav.cells)
    {
      cav.destroyed.add(cell_smallest_dihedral_angle(tr_, h), bound_);
      for(int i = 0; i < 4; ++i)
      {
        all_vertices.insert(h->vertex(i));
        if(in.count(h->neighbor(i)) != 0)
        {
          if(c3t3_.is_in_complex(h, i)) return false;
          continue;
        }
        cav.boundary.push_back(Facet(h, i));
        Vertex_handle t[3];
        for(int k = 0, j = 0; k < 4; ++k)
          if(k != i) t[j++] = h->vertex(k);
        for(int k = 0; k < 3; ++k)
        {
          boundary_vertices.insert(t[k]);
          Vertex_handle a = t[k], b = t[(k + 1) % 3];
          if(b < a) std::swap(a, b);
          ++edge_uses[std::make_pair(a, b)];
        }
      }
    }
    // a sphere through every vertex of the cavity: no vertex and no edge lost
    if(boundary_vertices.size() != all_vertices.size()) return false;
    for(const auto& eu : edge_uses)
      if(eu.second != 2) return false;
    if(long(boundary_vertices.size()) - long(edge_uses.size()) + long(cav.boundary.size()) != 2) return false;
    for(Cell_handle h : cav.cells)
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j)
        {
          Vertex_handle a = h->vertex(i), b = h->vertex(j);
          if(b < a) std::swap(a, b);
          if(edge_uses.count(std::make_pair(a, b)) == 0 && c3t3_.is_in_complex(a, b)) return false;
        }
    return true;
  }

  // quality of the star of `p` over the cavity's boundary; false if `p` is not
  // strictly inside its kernel
  bool star_quality(const Cavity& cav, const Bare_point& p, Cell_set_quality& made) const
  {
    const auto orientation = tr_.geom_traits().orientation_3_object();
    const auto point = tr_.geom_traits().construct_point_3_object();
    const Vec3 pc = to_vec3(p);
    made = Cell_set_quality();
    for(const Facet& f : cav.boundary)
    {
      Bare_point q[4];
      Vec3 qc[4];
      for(int k = 0; k < 4; ++k)
      {
        q[k] = k == f.second ? p : point(f.first->vertex(k)->point());
        qc[k] = k == f.second ? pc : coordinates(f.first->vertex(k));
      }
      if(orientation(q[0], q[1], q[2], q[3]) != CGAL::POSITIVE) return false;
      made.add(smallest_dihedral_angle(qc[0], qc[1], qc[2], qc[3]), bound_);
    }
    return true;
  }

  // Tries cavities of one, two (and three) rings around sliver `c` and a few
  // positions in each; inserts the best star if it beats the cells it replaces.
  // `angle` is the smallest dihedral angle of `c`, as the pass measured it.
  bool improve(Cell_handle c, double angle)
  {
    const Subdomain_index region = c3t3_.subdomain_index(c);
    Vec3 g = {{0., 0., 0.}};
    double longest = 0.;
    for(int i = 0; i < 4; ++i)
    {
      const Vec3 p = coordinates(c->vertex(i));
      for(int k = 0; k < 3; ++k) g[k] += 0.25 * p[k];
      for(int j = i + 1; j < 4; ++j)
      {
        const Vec3 d = sub(p, coordinates(c->vertex(j)));
        longest = (std::max)(longest, std::sqrt(dot(d, d)));
      }
    }
    Cavity best_cavity;
    Bare_point best_point;
    Cell_set_quality best_made;
    bool found = false;
    // the best star over `cav` among `positions`, the centroid of the
    // cavity's vertices, then seeded random points in a shrinking search
    // around the best so far
    auto search = [&](const Cavity& cav, std::vector<Vec3> positions, double floor) {
      {
        // summed in the order the boundary meets them (never by address, so
        // that runs agree to the last bit)
        std::unordered_set<Vertex_handle> seen;
        std::vector<Vertex_handle> vs;
        for(const Facet& f : cav.boundary)
          for(int k = 0; k < 4; ++k)
            if(k != f.second && seen.insert(f.first->vertex(k)).second) vs.push_back(f.first->vertex(k));
        Vec3 h = {{0., 0., 0.}};
        for(Vertex_handle v : vs)
        {
          const Vec3 p = coordinates(v);
          for(int k = 0; k < 3; ++k) h[k] += p[k] / double(vs.size());
        }
        positions.push_back(h);
      }
      Cell_set_quality made;
      Vec3 centre = positions.front();
      double local_best = -1.;
      auto consider = [&](const Vec3& x) {
        const Bare_point p(x[0], x[1], x[2]);
        if(!star_quality(cav, p, made)) return;
        if(made.min_angle > local_best) { local_best = made.min_angle; centre = x; }
        if(!made.replaces(cav.destroyed, angle_tolerance) || made.min_angle < floor) return;
        if(found && !(made.min_angle > best_made.min_angle)) return;
        found = true;
        best_made = made;
        best_point = p;
        best_cavity = cav;
      };
      for(const Vec3& x : positions) consider(x);
      double radius = 0.25 * longest;
      for(int round = 0; round < 3; ++round, radius *= 0.5)
        for(unsigned int k = 0; k < number_of_random_; ++k)
        {
          Vec3 d;
          do
          {
            d = {{random_.get_double(-1., 1.), random_.get_double(-1., 1.), random_.get_double(-1., 1.)}};
          } while(dot(d, d) > 1.);
          const Vec3 base = centre;
          consider({{base[0] + radius * d[0], base[1] + radius * d[1], base[2] + radius * d[2]}});
        }
    };
    // A flat cell on a surface: the star of one of its edges (the quad's
    // other diagonal), split by a point just off the edge's midpoint, on
    // either side of the cell's plane (the normal of its largest face)
    if(angle < flat_cell_angle)
    {
      Vec3 normal = {{0., 0., 0.}};
      double largest = 0.;
      for(int i = 0; i < 4; ++i)
      {
        const Vec3 p0 = coordinates(c->vertex((i + 1) % 4)), p1 = coordinates(c->vertex((i + 2) % 4)),
                   p2 = coordinates(c->vertex((i + 3) % 4));
        const Vec3 n = cross(sub(p1, p0), sub(p2, p0));
        const double area = std::sqrt(dot(n, n));
        if(area > largest) { largest = area; normal = {{n[0] / area, n[1] / area, n[2] / area}}; }
      }
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j)
        {
          Cavity cav;
          if(!make_edge_cavity(c, i, j, region, cav)) continue;
          const Vec3 p = coordinates(c->vertex(i)), q = coordinates(c->vertex(j));
          const Vec3 d = sub(q, p);
          const double length = std::sqrt(dot(d, d));
          std::vector<Vec3> positions;
          for(double t : {0.003, 0.01, 0.03, 0.1, 0.3})
            for(double side : {1., -1.})
            {
              const double o = side * t * length;
              positions.push_back({{0.5 * (p[0] + q[0]) + o * normal[0], 0.5 * (p[1] + q[1]) + o * normal[1],
                                    0.5 * (p[2] + q[2]) + o * normal[2]}});
            }
          search(cav, positions, 0.);
        }
    }
    // a third ring only for cells under the report's 10 degrees: few, and
    // the ones the headline counts
    const int max_rings = angle < forced_angle ? 3 : 2;
    for(int rings = 1; rings <= max_rings; ++rings)
    {
      // a larger cavity only when the smaller one did not reach the bound
      if(found && !(best_made.min_angle < bound_)) break;
      Cavity cav;
      if(!make_cavity(c, region, rings, cav)) continue;
      search(cav, std::vector<Vec3>(1, g), 0.);
    }
    // A cell under 10 degrees whose rings did not reach the bound (its four
    // vertices on surfaces, say, across a corner where a fault meets two
    // horizons): the star of one of its edges, split near the edge's middle.
    // The rings around such a cell often hold a vertex inside or a complex
    // facet, while an edge's star has every vertex on its boundary. Taken
    // only if its cells reach 10 degrees: a star that merely lifts 2 degrees
    // to 4 adds cells and leaves the count under 10 as it was (modelA5 with
    // any gain taken: 9,000 more cells, aspect-ratio median 2.256 -> 2.323).
    if(angle < forced_angle && !(angle < flat_cell_angle) && (!found || best_made.min_angle < bound_))
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j)
        {
          Cavity cav;
          if(!make_edge_cavity(c, i, j, region, cav)) continue;
          const Vec3 p = coordinates(c->vertex(i)), q = coordinates(c->vertex(j));
          search(cav, std::vector<Vec3>(1, Vec3{{0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])}}),
                 forced_angle);
        }
    if(!found) return false;

    for(Cell_handle h : best_cavity.cells) c3t3_.remove_from_complex(h);
    const Facet& f = best_cavity.boundary.front();
    const Vertex_handle nv = tr_.insert_in_hole(Weighted_point(best_point, 0), best_cavity.cells.begin(),
                                                best_cavity.cells.end(), f.first, f.second);
    c3t3_.set_dimension(nv, 3);
    c3t3_.set_index(nv, typename C3T3::Index(region));
    std::vector<Cell_handle> star;
    tr_.incident_cells(nv, std::back_inserter(star));
    for(Cell_handle h : star) label_new_cell(c3t3_, h, region);
    return true;
  }

  C3T3& c3t3_;
  Tr& tr_;
  double bound_;
  unsigned int number_of_random_;
  CGAL::Random random_;
  std::set<std::pair<Vertex_handle, Vertex_handle> > sharp_edges_;
  // the report's threshold: cells under 10 degrees at a facet with an angle under 10 are counted apart
  static constexpr double forced_angle = 10.;
  // a star must gain at least this (degrees) over what it replaces
  static constexpr double angle_tolerance = 1e-6;
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_INSERT_SLIVER_VERTICES_H
