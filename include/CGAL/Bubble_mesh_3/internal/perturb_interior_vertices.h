// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_PERTURB_INTERIOR_VERTICES_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_PERTURB_INTERIOR_VERTICES_H

// Moves interior vertices of slivers inside their region (the first step of
// `remove_slivers()`).
//
// A move is a removal and a re-insertion, so that the triangulation stays
// regular (the exuder needs it). Removing an interior vertex `v` only
// re-triangulates its star, whose boundary (the link) stays: no complex facet
// is lost. Inserting the new point `p` destroys the facets inside its conflict
// zone; so a candidate `p` is allowed only if no facet inside that zone is in
// the complex and every conflict cell is in `v`'s region - then the zone, and
// `p`, are inside the region, every complex facet survives, and the new cells
// (`p` joined to the zone's boundary) belong to the region. Candidates are
// compared exactly on what changes: the cells destroyed (old star and old
// conflict cells) against the cells made (new star and the surviving cells of
// the re-triangulated hole). The original position is always a candidate, and
// re-inserting it gives back the original triangulation (the regular
// triangulation of a point set is unique, CGAL breaking ties symbolically).
//
// Labels: new cells take the region; a new cell's facet takes the patch index
// its neighbour across the facet carries (that neighbour survived, so its
// label is right). Counts of the complex are kept by `add_to_complex` /
// `remove_from_complex` on the cells made and destroyed.

#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

typedef std::array<double, 3> Vec3;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

// Smallest dihedral angle (degrees) of a tetrahedron, with the atan2 form that
// stays accurate near 0 and 180 degrees (as `tetrahedron_quality()` does); a
// flat tetrahedron gives 0.
inline double smallest_dihedral_angle(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3)
{
  const Vec3* p[4] = {&p0, &p1, &p2, &p3};
  Vec3 n[4]; // area vector of the face opposite vertex k, all outward or all inward
  for(int k = 0; k < 4; ++k)
  {
    const Vec3& a = *p[(k + 1) % 4];
    const Vec3& b = *p[(k + 2) % 4];
    const Vec3& c = *p[(k + 3) % 4];
    n[k] = cross(sub(b, a), sub(c, a));
    // (k+1, k+2, k+3) turns the other way for odd k. The sign comes from
    // that parity, not from a side test, which is noise on a nearly flat
    // tetrahedron and then made all its angles 180 degrees; flipping all
    // four normals does not change an angle
    if(k % 2 == 1) n[k] = {{-n[k][0], -n[k][1], -n[k][2]}};
  }
  // the angle of pair k is atan2(s[k], c[k]), s[k] >= 0
  double s[6], c[6];
  bool degenerate = false;
  for(int i = 0, k = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j, ++k)
    {
      const Vec3 x = cross(n[i], n[j]);
      s[k] = std::sqrt(dot(x, x));
      c[k] = -dot(n[i], n[j]);
      degenerate = degenerate || !(s[k] > 0.);
    }
  // The sliver steps ask this for every cell they touch, and six atan2 a
  // cell were 5 % of a whole modelA5 run. With every s[k] > 0 the angles lie
  // in (0, 180), where a smaller angle has a larger cotangent c/s, so one
  // atan2 is enough. A flat or degenerate cell (some s[k] = 0) takes all six,
  // as the signs of zeros decide there.
  int best = 0;
  if(!degenerate)
  {
    for(int k = 1; k < 6; ++k)
      if(c[k] * s[best] > c[best] * s[k]) best = k;
    return std::atan2(s[best], c[best]) * 180. / CGAL_PI;
  }
  double smallest = 180.;
  for(int k = 0; k < 6; ++k) smallest = (std::min)(smallest, std::atan2(s[k], c[k]) * 180. / CGAL_PI);
  return smallest;
}

// six times the volume of a tetrahedron, unsigned
inline double six_volume(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3)
{
  return std::abs(dot(cross(sub(p1, p0), sub(p2, p0)), sub(p3, p0)));
}

// Aspect ratio of a tetrahedron: longest edge over shortest altitude (a
// regular tetrahedron gives sqrt(3/2)); a flat one gives infinity. The
// measure of `tetrahedron_quality()`, without its angles: the smoothing
// takes it for every cell it tries.
inline double aspect_ratio(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3)
{
  const Vec3* p[4] = {&p0, &p1, &p2, &p3};
  double longest2 = 0., largest_face2 = 0.;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
    {
      const Vec3 e = sub(*p[j], *p[i]);
      longest2 = (std::max)(longest2, dot(e, e));
    }
  for(int k = 0; k < 4; ++k)
  {
    const Vec3 n = cross(sub(*p[(k + 2) % 4], *p[(k + 1) % 4]), sub(*p[(k + 3) % 4], *p[(k + 1) % 4]));
    largest_face2 = (std::max)(largest_face2, dot(n, n)); // (2 area)^2
  }
  const double six_v = six_volume(p0, p1, p2, p3);
  if(!(six_v > 0.)) return std::numeric_limits<double>::infinity();
  // shortest altitude = 3 V / largest area = six_volume / (2 area)
  return std::sqrt(longest2) * std::sqrt(largest_face2) / six_v;
}

// Another pass of a cell or vertex sweep only while the last one paid: at
// least one change per `per` cells or vertices tried. On models whose
// surfaces force most slivers, later passes try many for a few changes.
inline bool pass_paid(std::size_t changed, std::size_t tried, std::size_t per)
{
  return changed > 0 && changed * per >= tried;
}

// coordinates of a (bare) point and of a vertex of a Mesh_3 triangulation
template <class Point>
Vec3 to_vec3(const Point& p)
{
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}
template <class Tr>
Vec3 vertex_coordinates(const Tr& tr, typename Tr::Vertex_handle v)
{
  return to_vec3(tr.geom_traits().construct_point_3_object()(v->point()));
}
template <class Tr>
double cell_smallest_dihedral_angle(const Tr& tr, typename Tr::Cell_handle c)
{
  return smallest_dihedral_angle(vertex_coordinates(tr, c->vertex(0)), vertex_coordinates(tr, c->vertex(1)),
                                 vertex_coordinates(tr, c->vertex(2)), vertex_coordinates(tr, c->vertex(3)));
}

// A cell whose smallest dihedral angle is under this (degrees) is flat: its
// four vertices all but in one plane (real models give 1e-14 degrees, an
// aspect ratio of 1e15), a zero Jacobian to a finite-element code. Such a
// cell lies on a surface more often than not, between two complex facets of
// one nearly cocircular quad and the quad's other diagonal. Flips and
// insertion take it away even at the price of more cells under the sliver
// bound (`Cell_set_quality::unflattens()`).
constexpr double flat_cell_angle = 0.01;

// Smallest dihedral angle and count of cells under a bound, over a set of
// cells; with the aspect ratios for the smoothing.
struct Cell_set_quality
{
  double min_angle = 180.;
  std::size_t under_bound = 0;
  double ratio_sum = 0.;
  std::size_t count = 0;

  void add(double angle, double bound)
  {
    min_angle = (std::min)(min_angle, angle);
    if(angle < bound) ++under_bound;
  }
  void add(double angle, double bound, double ratio)
  {
    add(angle, bound);
    ratio_sum += ratio;
    ++count;
  }
  double mean_ratio() const { return count ? ratio_sum / double(count) : 0.; }
  // a smoothing move: a lower mean aspect ratio, the smallest angle and the
  // count under the bound no worse (a worse largest ratio among the cells is
  // allowed: on the bundled model with re-meshed surfaces that takes the
  // median from 1.93 to 1.88 and the mesh's largest ratio from 7.3 to 6.3)
  bool smooths(const Cell_set_quality& o, double relative_gain) const
  {
    return mean_ratio() < o.mean_ratio() * (1. - relative_gain) &&
           min_angle >= o.min_angle && under_bound <= o.under_bound;
  }
  // strictly better: a larger smallest angle and no more cells under the bound
  bool improves_on(const Cell_set_quality& o, double tolerance) const
  {
    return min_angle > o.min_angle + tolerance && under_bound <= o.under_bound;
  }
  // `o` has a flat cell and this set's smallest angle is larger
  bool unflattens(const Cell_set_quality& o, double tolerance) const
  {
    return o.min_angle < flat_cell_angle && min_angle > o.min_angle + tolerance;
  }
  // the rule of the steps that replace cells (flips, insertion): better, or
  // a flat cell taken away whatever the count under the bound
  bool replaces(const Cell_set_quality& o, double tolerance) const
  {
    return improves_on(o, tolerance) || unflattens(o, tolerance);
  }
};

// A new cell: in `region` (outside the complex if that is the default
// index); a facet takes the label its neighbour across it carries (that
// neighbour survived, so its label is right).
template <class C3T3>
void label_new_cell(C3T3& c3t3, typename C3T3::Triangulation::Cell_handle c,
                    const typename C3T3::Subdomain_index& region)
{
  if(!(region == typename C3T3::Subdomain_index())) c3t3.add_to_complex(c, region);
  for(int i = 0; i < 4; ++i)
  {
    const auto m = c->neighbor(i);
    const int mi = m->index(c);
    if(!c3t3.is_in_complex(m, mi)) continue;
    c3t3.set_surface_patch_index(c, i, c3t3.surface_patch_index(m, mi));
    c->set_facet_surface_center(i, m->get_facet_surface_center(mi));
    c->set_facet_surface_center_index(i, m->get_facet_surface_center_index(mi));
  }
}

// the vertices of a facet, sorted: a key that is the same from both sides
template <class Vertex_handle>
std::array<Vertex_handle, 3> sorted_triple(Vertex_handle a, Vertex_handle b, Vertex_handle c)
{
  std::array<Vertex_handle, 3> t{{a, b, c}};
  std::sort(t.begin(), t.end());
  return t;
}
template <class Cell_handle>
auto facet_key(Cell_handle c, int i) -> std::array<decltype(c->vertex(0)), 3>
{
  return sorted_triple(c->vertex((i + 1) % 4), c->vertex((i + 2) % 4), c->vertex((i + 3) % 4));
}

// Replaces `old_cells` by new cells with the vertices `new_cells` (each
// positively oriented, together a partition of the old ones): the new cells
// are glued to the old cells' outer neighbours across facets with the same
// vertices and to each other, and labelled by `label_new_cell()` with
// `regions[k]`. Complex facets inside the old cells are the caller's.
template <class C3T3, class Region_of>
void replace_cells(C3T3& c3t3, const std::vector<typename C3T3::Triangulation::Cell_handle>& old_cells,
                   const std::vector<std::array<typename C3T3::Triangulation::Vertex_handle, 4> >& new_cells,
                   const Region_of& regions)
{
  typedef typename C3T3::Triangulation::Cell_handle   Cell_handle;
  typedef typename C3T3::Triangulation::Vertex_handle Vertex_handle;
  typedef std::array<Vertex_handle, 3>                Triple;
  auto& tds = c3t3.triangulation().tds();
  const std::unordered_set<Cell_handle> old(old_cells.begin(), old_cells.end());
  std::map<Triple, std::pair<Cell_handle, int> > outside; // facet -> (outer cell, its index)
  for(Cell_handle h : old_cells)
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = h->neighbor(i);
      if(old.count(n) == 0) outside[facet_key(h, i)] = std::make_pair(n, n->index(h));
    }
  for(Cell_handle h : old_cells)
  {
    c3t3.remove_from_complex(h);
    tds.delete_cell(h);
  }
  std::map<Triple, std::pair<Cell_handle, int> > inside;
  std::vector<Cell_handle> made;
  for(const auto& cv : new_cells)
  {
    const Cell_handle h = tds.create_cell(cv[0], cv[1], cv[2], cv[3]);
    made.push_back(h);
    for(int i = 0; i < 4; ++i)
    {
      cv[i]->set_cell(h);
      const Triple t = facet_key(h, i);
      const auto o = outside.find(t);
      if(o != outside.end())
      {
        tds.set_adjacency(h, i, o->second.first, o->second.second);
        continue;
      }
      const auto in = inside.find(t);
      if(in != inside.end())
      {
        tds.set_adjacency(h, i, in->second.first, in->second.second);
        inside.erase(in);
      }
      else inside.emplace(t, std::make_pair(h, i));
    }
  }
  CGAL_assertion(inside.empty());
  for(std::size_t k = 0; k < made.size(); ++k) label_new_cell(c3t3, made[k], regions(k));
}

// One pass over the cells of the complex under `bound`, worst first, for the
// steps that replace cells (flips, insertion): `take(angle, vertices)` says
// whether a sliver (its smallest dihedral angle, its vertices) is worked on,
// `work(cell, angle)` works on it. Cells die as the pass goes,
// vertices never: a sliver is kept as its vertices and looked up again when
// its turn comes. Returns the number of slivers worked on; stops when `timer`
// passes `time_limit`, and says so in `out_of_time`.
template <class C3T3, class Take, class Work>
std::size_t for_each_sliver_worst_first(C3T3& c3t3, double bound, const Take& take, const Work& work,
                                        const CGAL::Real_timer& timer, double time_limit, bool& out_of_time)
{
  typedef typename C3T3::Triangulation::Vertex_handle Vertex_handle;
  typedef typename C3T3::Triangulation::Cell_handle Cell_handle;
  typedef std::array<Vertex_handle, 4> Cell_vertices;
  const auto& tr = c3t3.triangulation();
  std::vector<std::pair<double, Cell_vertices> > slivers;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    const double a = cell_smallest_dihedral_angle(tr, c);
    if(!(a < bound)) continue;
    const Cell_vertices v = {{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
    if(take(a, v)) slivers.push_back(std::make_pair(a, v));
  }
  std::stable_sort(slivers.begin(), slivers.end(),
                   [](const std::pair<double, Cell_vertices>& a, const std::pair<double, Cell_vertices>& b) {
                     return a.first < b.first;
                   });
  std::size_t tried = 0;
  for(const auto& s : slivers)
  {
    if(timer.time() > time_limit)
    {
      out_of_time = true;
      break;
    }
    Cell_handle c;
    const Cell_vertices& v = s.second;
    if(!tr.is_cell(v[0], v[1], v[2], v[3], c) || !c3t3.is_in_complex(c)) continue;
    ++tried;
    work(c, s.first);
  }
  return tried;
}

/// What the perturbation did.
struct Perturbation_statistics
{
  std::size_t number_of_passes = 0;
  std::size_t number_of_vertices_tried = 0;   // vertices of slivers that could move
  std::size_t number_of_moves = 0;            // accepted moves
  std::size_t number_of_vertices_moved = 0;   // distinct vertices among them
  std::size_t number_of_candidates_rejected = 0; // would leave the region or break a complex facet
  bool skipped_nonzero_weights = false;       // not run: the triangulation has weights
  bool time_limit_reached = false;
};

template <class C3T3>
class Interior_vertex_perturber
{
  typedef typename C3T3::Triangulation            Tr;
  typedef typename Tr::Geom_traits                GT;
  typedef typename Tr::Vertex_handle              Vertex_handle;
  typedef typename Tr::Cell_handle                Cell_handle;
  typedef typename Tr::Facet                      Facet;
  typedef typename Tr::Locate_type                Locate_type;
  typedef typename Tr::Weighted_point             Weighted_point;
  typedef typename Tr::Bare_point                 Bare_point;
  typedef typename C3T3::Subdomain_index          Subdomain_index;
  typedef typename C3T3::Index                    Index;

public:
  Interior_vertex_perturber(C3T3& c3t3, double sliver_bound, double radius_factor,
                            unsigned int number_of_random_directions, unsigned int seed)
    : c3t3_(c3t3), tr_(c3t3.triangulation()), bound_(sliver_bound), radius_factor_(radius_factor),
      number_of_directions_(number_of_random_directions), random_(seed)
  {}

  // Smoothing passes over all interior vertices: each is moved towards the
  // optimal-Delaunay point of its star (the cells' circumcentres averaged
  // with their volumes as weights) or the centroid of its neighbours, or half
  // way, if that lowers the mean aspect ratio of the cells it changes with no
  // smaller angle and no more cells under the bound among them. Stops when a pass
  // moves under 1 % of the vertices it tried, or at `time_limit` seconds.
  Perturbation_statistics smooth(std::size_t max_passes, double time_limit)
  {
    Perturbation_statistics stats;
    if(!can_run(stats)) return stats;
    CGAL::Real_timer timer;
    timer.start();
    std::unordered_set<Vertex_handle> moved;
    for(std::size_t pass = 0; pass < max_passes && !stats.time_limit_reached; ++pass)
    {
      ++stats.number_of_passes;
      const std::size_t moves_before = stats.number_of_moves, tried_before = stats.number_of_vertices_tried;
      // triangulation order, the same from run to run; only the vertex being
      // moved is removed, so the other handles stay valid
      std::vector<Vertex_handle> order;
      for(auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v)
        if(c3t3_.in_dimension(v) == 3) order.push_back(v);
      for(Vertex_handle v : order)
      {
        if(timer.time() > time_limit)
        {
          stats.time_limit_reached = true;
          break;
        }
        Vertex_handle nv;
        if(smooth_vertex(v, stats, nv) > 0)
        {
          moved.erase(v);
          moved.insert(nv);
        }
      }
      if(!pass_paid(stats.number_of_moves - moves_before, stats.number_of_vertices_tried - tried_before, 100)) break;
    }
    stats.number_of_vertices_moved = moved.size();
    return stats;
  }

  // Runs at most `max_passes` passes over the vertices of slivers, stopping
  // early when a pass moves nothing or when `time_limit` seconds are spent.
  Perturbation_statistics operator()(std::size_t max_passes, double time_limit)
  {
    Perturbation_statistics stats;
    if(!can_run(stats)) return stats;

    CGAL::Real_timer timer;
    timer.start();
    std::unordered_set<Vertex_handle> moved;
    for(std::size_t pass = 0; pass < max_passes; ++pass)
    {
      ++stats.number_of_passes;
      const std::size_t moves_before = stats.number_of_moves;
      // vertices of slivers, worst sliver first; ties in triangulation order,
      // which is the same from run to run (never addresses). A sliver with
      // all its vertices on surfaces is worked on by the interior vertices
      // across its faces instead: moved towards it, one of them may take it
      // into its star.
      std::vector<std::pair<double, Vertex_handle> > queue;
      std::unordered_map<Vertex_handle, std::size_t> position;
      std::unordered_map<Vertex_handle, std::vector<Vec3> > targets;
      auto enqueue = [&](Vertex_handle v, double a) {
        auto ins = position.insert(std::make_pair(v, queue.size()));
        if(ins.second) queue.push_back(std::make_pair(a, v));
        else queue[ins.first->second].first = (std::min)(queue[ins.first->second].first, a);
      };
      for(auto c = c3t3_.cells_in_complex_begin(); c != c3t3_.cells_in_complex_end(); ++c)
      {
        const double a = cell_angle(c);
        if(!(a < bound_)) continue;
        bool has_interior_vertex = false;
        for(int i = 0; i < 4; ++i)
          if(c3t3_.in_dimension(c->vertex(i)) == 3)
          {
            enqueue(c->vertex(i), a);
            has_interior_vertex = true;
          }
        if(has_interior_vertex) continue;
        const Vec3 target = cell_circumcenter(c);
        for(int i = 0; i < 4; ++i)
        {
          if(c3t3_.is_in_complex(Cell_handle(c), i)) continue;
          const Cell_handle n = c->neighbor(i);
          const Vertex_handle u = n->vertex(n->index(Cell_handle(c)));
          if(tr_.is_infinite(u) || c3t3_.in_dimension(u) != 3) continue;
          enqueue(u, a);
          targets[u].push_back(target);
        }
      }
      std::stable_sort(queue.begin(), queue.end(),
                       [](const std::pair<double, Vertex_handle>& a, const std::pair<double, Vertex_handle>& b) {
                         return a.first < b.first;
                       });
      static const std::vector<Vec3> no_targets;
      for(const auto& entry : queue)
      {
        if(timer.time() > time_limit)
        {
          stats.time_limit_reached = true;
          break;
        }
        // each vertex is once in the queue, and only the vertex being moved is
        // removed, so the handle is still valid here
        auto t = targets.find(entry.second);
        Vertex_handle nv;
        const int result = move(entry.second, t == targets.end() ? no_targets : t->second, stats, nv);
        if(result > 0)
        {
          moved.erase(entry.second);
          moved.insert(nv);
        }
      }
      if(stats.time_limit_reached || stats.number_of_moves == moves_before) break;
    }
    stats.number_of_vertices_moved = moved.size();
    return stats;
  }

private:
  // 3D, and no weight that could hide a re-inserted point
  bool can_run(Perturbation_statistics& stats) const
  {
    if(tr_.dimension() != 3) return false;
    stats.skipped_nonzero_weights = has_hiding_weights();
    return !stats.skipped_nonzero_weights;
  }

  // with weights a re-insertion could hide a neighbour, which the cell bases
  // of Mesh_3 cannot give back; the surface recovery's tie-breaking weights
  // are non-negative and far below the squared edge lengths, so they hide
  // nothing (evaluate() still refuses a hidden point)
  bool has_hiding_weights() const
  {
    for(auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v)
    {
      const double w = CGAL::to_double(v->point().weight());
      if(w == 0.) continue;
      double shortest2 = std::numeric_limits<double>::infinity();
      std::vector<Vertex_handle> adjacent;
      tr_.finite_adjacent_vertices(v, std::back_inserter(adjacent));
      for(Vertex_handle a : adjacent)
        shortest2 = (std::min)(shortest2, CGAL::to_double(CGAL::squared_distance(
                                            tr_.geom_traits().construct_point_3_object()(v->point()),
                                            tr_.geom_traits().construct_point_3_object()(a->point()))));
      if(w < 0. || !(w <= std::ldexp(shortest2, -30))) return true;
    }
    return false;
  }

  Vec3 coordinates(const Bare_point& p) const { return to_vec3(p); }
  Vec3 coordinates(Vertex_handle v) const { return vertex_coordinates(tr_, v); }
  double cell_angle(Cell_handle c) const { return cell_smallest_dihedral_angle(tr_, c); }
  double cell_ratio(Cell_handle c) const
  {
    return aspect_ratio(coordinates(c->vertex(0)), coordinates(c->vertex(1)), coordinates(c->vertex(2)),
                        coordinates(c->vertex(3)));
  }
  Vec3 cell_circumcenter(Cell_handle c) const
  {
    const auto p = tr_.geom_traits().construct_circumcenter_3_object()(
      tr_.geom_traits().construct_point_3_object()(c->vertex(0)->point()),
      tr_.geom_traits().construct_point_3_object()(c->vertex(1)->point()),
      tr_.geom_traits().construct_point_3_object()(c->vertex(2)->point()),
      tr_.geom_traits().construct_point_3_object()(c->vertex(3)->point()));
    return coordinates(p);
  }
  // the smallest angle and (when `with_ratio`, else 0) the aspect ratio of the tetrahedron
  // made of point `p` and facet `f`
  std::pair<double, double> cone_measures(const Vec3& p, const Facet& f, bool with_ratio) const
  {
    Vec3 q[3];
    for(int k = 0, j = 0; k < 4; ++k)
      if(k != f.second) q[j++] = coordinates(f.first->vertex(k));
    return std::make_pair(smallest_dihedral_angle(p, q[0], q[1], q[2]), with_ratio ? aspect_ratio(p, q[0], q[1], q[2]) : 0.);
  }
  // the aspect ratio of a cell when the smoothing compares them (the perturbation does not)
  double cell_ratio_if(Cell_handle c, bool with_ratio) const { return with_ratio ? cell_ratio(c) : 0.; }

  // A vertex can move if it is a volume vertex, on no complex facet, and all
  // its cells are finite and in one region. Sets `region`.
  bool is_movable(Vertex_handle v, const std::vector<Cell_handle>& star, Subdomain_index& region) const
  {
    if(c3t3_.in_dimension(v) != 3 || star.empty()) return false;
    region = c3t3_.subdomain_index(star.front());
    if(region == Subdomain_index()) return false;
    for(Cell_handle c : star)
    {
      if(tr_.is_infinite(c) || !(c3t3_.subdomain_index(c) == region)) return false;
      const int iv = c->index(v);
      for(int i = 0; i < 4; ++i)
        if(i != iv && c3t3_.is_in_complex(c, i)) return false;
    }
    return true;
  }

  struct Candidate
  {
    Bare_point point;
    Cell_set_quality made;      // the new star and the hole cells outside the conflict zone
    Cell_set_quality destroyed; // the old star and the old cells inside the conflict zone
    std::vector<Cell_handle> conflict_cells;
    Facet boundary_facet;
    bool valid = false;
  };

  // What `evaluate()` measures and when it may stop early: the smoothing compares
  // aspect ratios; a perturbation candidate that cannot improve on what it replaces
  // (`Cell_set_quality::improves_on()`) is dropped before all its cells are measured.
  struct Evaluation_mode
  {
    bool ratios;
    bool stop_when_hopeless;
  };

  // Conflict zone of `p` in the triangulation without the vertex, checked
  // against the region and the complex, and the quality of what it makes.
  // `hopeless` is set (and `valid` left false) when `mode.stop_when_hopeless` dropped it.
  void evaluate(Candidate& cand, const Subdomain_index& region, Cell_handle hint,
                const std::vector<Cell_handle>& hole,
                const std::unordered_map<Cell_handle, std::pair<double, double> >& hole_measures,
                const Cell_set_quality& old_star, Evaluation_mode mode, bool& hopeless) const
  {
    cand.valid = false;
    hopeless = false;
    const Weighted_point wp(cand.point, 0);
    Locate_type lt;
    int li, lj;
    const Cell_handle c = tr_.locate(wp, lt, li, lj, hint);
    if(lt == Tr::VERTEX || lt == Tr::OUTSIDE_CONVEX_HULL || lt == Tr::OUTSIDE_AFFINE_HULL || tr_.is_infinite(c))
      return;
    // a point the weights of its neighbours would hide
    if(tr_.side_of_power_sphere(c, wp, true) != CGAL::ON_BOUNDED_SIDE) return;
    std::vector<Facet> boundary, internal;
    cand.conflict_cells.clear();
    tr_.find_conflicts(wp, c, std::back_inserter(boundary), std::back_inserter(cand.conflict_cells),
                       std::back_inserter(internal));
    if(boundary.empty()) return;
    for(Cell_handle cc : cand.conflict_cells)
      if(tr_.is_infinite(cc) || !(c3t3_.subdomain_index(cc) == region)) return;
    for(const Facet& f : internal)
      if(c3t3_.is_in_complex(f)) return;

    // only these cells differ between the original triangulation and the
    // one with `v` at `p`
    const Vec3 p = coordinates(cand.point);
    cand.made = Cell_set_quality();
    cand.destroyed = old_star;
    // what is destroyed first: it sets what the made cells must beat
    for(Cell_handle cc : cand.conflict_cells)
      if(hole_measures.count(cc) == 0) cand.destroyed.add(cell_angle(cc), bound_, cell_ratio_if(cc, mode.ratios));
    auto beaten = [&] {
      return mode.stop_when_hopeless && (!(cand.made.min_angle > cand.destroyed.min_angle + angle_tolerance) ||
                                         cand.made.under_bound > cand.destroyed.under_bound);
    };
    // (in this order: the smoothing's sums of ratios are compared to the last bit)
    for(const Facet& f : boundary)
    {
      const std::pair<double, double> m = cone_measures(p, f, mode.ratios);
      cand.made.add(m.first, bound_, m.second);
      if(beaten()) { hopeless = true; return; } // angles only fall and counts only grow
    }
    std::unordered_set<Cell_handle> in_conflict(cand.conflict_cells.begin(), cand.conflict_cells.end());
    for(Cell_handle h : hole)
      if(in_conflict.count(h) == 0) cand.made.add(hole_measures.at(h).first, bound_, hole_measures.at(h).second);
    cand.boundary_facet = boundary.front();
    cand.valid = true;
  }

  // Tries to move `v`, also towards `targets` (circumcentres of slivers next
  // to it); returns 1 if moved, 0 if put back, -1 if not movable.
  int move(Vertex_handle v, const std::vector<Vec3>& sliver_targets, Perturbation_statistics& stats,
           Vertex_handle& nv)
  {
    std::vector<Cell_handle> star;
    tr_.incident_cells(v, std::back_inserter(star));
    Subdomain_index region;
    if(!is_movable(v, star, region)) return -1;

    Cell_set_quality old_star;
    std::vector<std::pair<double, Cell_handle> > slivers;
    for(Cell_handle c : star)
    {
      const double a = cell_angle(c);
      old_star.add(a, bound_, 0.); // the perturbation compares angles only
      if(a < bound_) slivers.push_back(std::make_pair(a, c));
    }
    if(slivers.empty() && sliver_targets.empty()) return -1; // fixed meanwhile by another move
    ++stats.number_of_vertices_tried;
    std::stable_sort(slivers.begin(), slivers.end(),
                     [](const std::pair<double, Cell_handle>& a, const std::pair<double, Cell_handle>& b) {
                       return a.first < b.first;
                     });

    const Vec3 p0 = coordinates(v);
    std::vector<Vertex_handle> neighbours;
    tr_.finite_adjacent_vertices(v, std::back_inserter(neighbours));
    double shortest = std::numeric_limits<double>::infinity();
    Vec3 centroid = {{0., 0., 0.}};
    for(Vertex_handle w : neighbours)
    {
      const Vec3 q = coordinates(w);
      shortest = (std::min)(shortest, std::sqrt(dot(sub(q, p0), sub(q, p0))));
      for(int k = 0; k < 3; ++k) centroid[k] += q[k] / double(neighbours.size());
    }
    const double radius = radius_factor_ * shortest;
    if(!(radius > 0.)) return -1;

    // candidate positions, in a fixed order: away from each sliver's opposite
    // face (what raises that sliver's height), towards the centroid of the
    // neighbours (Laplacian), seeded random points of the ball
    std::vector<Vec3> targets;
    auto add_step = [&](const Vec3& direction, double length, double longest) {
      const double n = std::sqrt(dot(direction, direction));
      if(!(n > 0.)) return;
      const double s = (std::min)(length, longest) / n;
      targets.push_back({{p0[0] + s * direction[0], p0[1] + s * direction[1], p0[2] + s * direction[2]}});
    };
    for(std::size_t k = 0; k < slivers.size() && k < 4; ++k)
    {
      const Cell_handle c = slivers[k].second;
      const int iv = c->index(v);
      const Vec3 a = coordinates(c->vertex((iv + 1) % 4));
      const Vec3 b = coordinates(c->vertex((iv + 2) % 4));
      const Vec3 d = coordinates(c->vertex((iv + 3) % 4));
      Vec3 n = cross(sub(b, a), sub(d, a));
      if(dot(n, sub(p0, a)) < 0.) n = {{-n[0], -n[1], -n[2]}};
      for(double f : {1., 0.5, 0.25}) add_step(n, f * radius, radius);
    }
    for(std::size_t k = 0; k < sliver_targets.size() && k < 4; ++k)
    {
      // into the sliver's circumsphere, where the conflict zone takes it in
      const Vec3 d = sub(sliver_targets[k], p0);
      const double l = std::sqrt(dot(d, d));
      for(double f : {0.75, 0.5, 0.25}) add_step(d, (std::min)(f * l, 2. * radius), 2. * radius);
    }
    const Vec3 to_centroid = sub(centroid, p0);
    const double to_centroid_length = std::sqrt(dot(to_centroid, to_centroid));
    add_step(to_centroid, to_centroid_length, radius);
    add_step(to_centroid, 0.5 * to_centroid_length, radius);
    for(unsigned int k = 0; k < number_of_directions_; ++k)
    {
      Vec3 d;
      do
      {
        d = {{random_.get_double(-1., 1.), random_.get_double(-1., 1.), random_.get_double(-1., 1.)}};
      } while(dot(d, d) > 1. || dot(d, d) < 1e-6);
      add_step(d, radius * std::cbrt(random_.get_double(0., 1.)), radius);
    }

    return relocate(v, star, region, old_star, targets, false, stats, nv);
  }

  // Tries to move interior vertex `v` towards the optimal-Delaunay point of
  // its star or the centroid of its neighbours; returns 1 if moved, 0 if put
  // back, -1 if not movable.
  int smooth_vertex(Vertex_handle v, Perturbation_statistics& stats, Vertex_handle& nv)
  {
    std::vector<Cell_handle> star;
    tr_.incident_cells(v, std::back_inserter(star));
    Subdomain_index region;
    if(!is_movable(v, star, region)) return -1;
    ++stats.number_of_vertices_tried;
    Cell_set_quality old_star;
    Vec3 odt = {{0., 0., 0.}};
    double volume = 0.;
    for(Cell_handle c : star)
    {
      old_star.add(cell_angle(c), bound_, cell_ratio(c));
      const double w = six_volume(coordinates(c->vertex(0)), coordinates(c->vertex(1)), coordinates(c->vertex(2)),
                                  coordinates(c->vertex(3)));
      const Vec3 cc = cell_circumcenter(c);
      for(int k = 0; k < 3; ++k) odt[k] += w * cc[k];
      volume += w;
    }
    if(!(volume > 0.)) return -1;
    const Vec3 p0 = coordinates(v);
    const Vec3 step = {{odt[0] / volume - p0[0], odt[1] / volume - p0[1], odt[2] / volume - p0[2]}};
    std::vector<Vec3> targets;
    for(double f : {1., 0.5})
      targets.push_back({{p0[0] + f * step[0], p0[1] + f * step[1], p0[2] + f * step[2]}});
    // and to the centroid of its neighbours, or half way: where the star's
    // circumcentres scatter (cells at a surface) the optimal-Delaunay point
    // can be far off
    {
      std::vector<Vertex_handle> neighbours;
      tr_.finite_adjacent_vertices(v, std::back_inserter(neighbours));
      Vec3 centroid = {{0., 0., 0.}};
      for(Vertex_handle w : neighbours)
      {
        const Vec3 q = coordinates(w);
        for(int k = 0; k < 3; ++k) centroid[k] += q[k] / double(neighbours.size());
      }
      targets.push_back(centroid);
      targets.push_back({{0.5 * (centroid[0] + p0[0]), 0.5 * (centroid[1] + p0[1]), 0.5 * (centroid[2] + p0[2])}});
    }
    return relocate(v, star, region, old_star, targets, true, stats, nv);
  }

  // Takes `v` out and puts it back at the best of `targets` that is allowed
  // and gains (`smoothing`: Cell_set_quality::smooths(), else improves_on()),
  // or where it was. Returns 1 if moved, 0 if put back.
  int relocate(Vertex_handle v, const std::vector<Cell_handle>& star, const Subdomain_index& region,
               const Cell_set_quality& old_star, const std::vector<Vec3>& targets, bool smoothing,
               Perturbation_statistics& stats, Vertex_handle& nv)
  {
    // take `v` out; its star becomes the hole, re-triangulated in the region
    const Weighted_point original = v->point();
    const int dimension = c3t3_.in_dimension(v);
    const Index index = c3t3_.index(v);
    for(Cell_handle c : star) c3t3_.remove_from_complex(c);
    std::vector<Cell_handle> hole;
    tr_.remove_and_give_new_cells(v, std::back_inserter(hole));
    std::unordered_map<Cell_handle, std::pair<double, double> > hole_measures;
    for(Cell_handle c : hole)
    {
      label_new_cell(c3t3_, c, region);
      hole_measures[c] = std::make_pair(cell_angle(c), cell_ratio_if(c, smoothing));
    }

    // the original position: its conflict zone is the hole, and re-inserting
    // it gives back the original cells
    Candidate best;
    best.point = tr_.geom_traits().construct_point_3_object()(original);
    bool hopeless = false;
    evaluate(best, region, hole.front(), hole, hole_measures, old_star, Evaluation_mode{smoothing, false}, hopeless);
    CGAL_assertion(best.valid && best.conflict_cells.size() == hole.size());
    bool improved = false;
    Candidate cand;
    for(const Vec3& t : targets)
    {
      cand.point = Bare_point(t[0], t[1], t[2]);
      evaluate(cand, region, hole.front(), hole, hole_measures, old_star, Evaluation_mode{smoothing, !smoothing},
               hopeless);
      if(hopeless) continue; // could not have beaten what it replaces
      if(!cand.valid)
      {
        ++stats.number_of_candidates_rejected;
        continue;
      }
      // a move must beat what it replaces (so the global smallest angle never
      // drops and the count under the bound never grows)
      if(smoothing)
      {
        // among those, the lowest mean aspect ratio wins, the first one on ties
        if(!cand.made.smooths(cand.destroyed, ratio_gain)) continue;
        if(improved && !(cand.made.mean_ratio() < best.made.mean_ratio())) continue;
      }
      else
      {
        // among those, the best smallest angle wins, the first one on ties
        if(!cand.made.improves_on(cand.destroyed, angle_tolerance)) continue;
        if(improved && !(cand.made.min_angle > best.made.min_angle ||
                         (cand.made.min_angle == best.made.min_angle && cand.made.under_bound < best.made.under_bound)))
          continue;
      }
      std::swap(best, cand);
      improved = true;
    }

    for(Cell_handle c : best.conflict_cells) c3t3_.remove_from_complex(c);
    nv = tr_.insert_in_hole(Weighted_point(best.point, 0), best.conflict_cells.begin(), best.conflict_cells.end(),
                            best.boundary_facet.first, best.boundary_facet.second);
    c3t3_.set_dimension(nv, dimension);
    c3t3_.set_index(nv, index);
    std::vector<Cell_handle> new_star;
    tr_.incident_cells(nv, std::back_inserter(new_star));
    for(Cell_handle c : new_star) label_new_cell(c3t3_, c, region);
    if(!improved) return 0;
    ++stats.number_of_moves;
    return 1;
  }

  C3T3& c3t3_;
  Tr& tr_;
  double bound_;
  double radius_factor_;
  unsigned int number_of_directions_;
  CGAL::Random random_;
  // a move must gain at least this (degrees): no churn on rounding noise
  static constexpr double angle_tolerance = 1e-6;
  // a smoothing move must lower the mean aspect ratio by this share
  static constexpr double ratio_gain = 1e-4;
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_PERTURB_INTERIOR_VERTICES_H
