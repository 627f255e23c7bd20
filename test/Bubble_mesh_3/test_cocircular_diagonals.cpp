// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Flips of cocircular quads (internal/flip_cocircular_diagonals.h): grid
// surfaces whose diagonals go against CGAL's symbolic perturbation get their
// input triangles as triangulation facets; the triangulation stays valid, and
// the two hazards of a triangulation that is not the canonical one (a point
// exactly on a flipped cell's circumsphere, the removal of a vertex next to a
// flipped quad) are detected by the checks meant to guard them.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Mesh_complex_3.h>
#include <CGAL/Bubble_mesh_3/internal/flip_cocircular_diagonals.h>

#include <CGAL/Random.h>

#include "tilted_grid_box.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K>          Model;
typedef CGAL::Bubble_mesh_3::Mesh_complex_triangulation_3<K> Tr;
typedef Tr::Weighted_point                                  Weighted_point;
typedef Tr::Vertex_handle                                   Vertex_handle;
typedef Tr::Cell_handle                                     Cell_handle;
namespace internal = CGAL::Bubble_mesh_3::internal;

namespace {

Model make_grid_box(int nx, int ny, const std::vector<double>& levels)
{
  return make_tilted_grid_box<Model>(nx, ny, levels);
}

std::vector<std::array<std::size_t, 3> > triangles_of(const Model& m)
{
  std::vector<std::array<std::size_t, 3> > t;
  for(std::size_t i = 0; i < m.number_of_triangles(); ++i)
    t.push_back({{m.triangle(i)[0], m.triangle(i)[1], m.triangle(i)[2]}});
  return t;
}

std::size_t number_of_triangles_present(const Tr& tr, const std::vector<Vertex_handle>& vh,
                                        const std::vector<std::array<std::size_t, 3> >& triangles)
{
  std::size_t n = 0;
  for(const auto& t : triangles)
  {
    Cell_handle c;
    int i, j, k;
    if(tr.is_facet(vh[t[0]], vh[t[1]], vh[t[2]], c, i, j, k)) ++n;
  }
  return n;
}

// 1. the grid box: the rectangles' triangles are all missing before; a flip
// makes both triangles of its quad facets. Not all can be flipped: where the
// grid is symmetric about the quad's mid-plane, the vertices above it come in
// cospherical pairs, and the prism they make with the quad has its other two
// quads' diagonals (fixed by cells outside) in a cycle with ac - then no
// triangulation of it has ac (Schoenhardt's twisted prism), and recovery
// keeps its Steiner point.
void test_grid_box()
{
  const int nx = 6, ny = 4;
  const Model m = make_grid_box(nx, ny, {0., 1.5, 2.25, 3.75});
  const auto triangles = triangles_of(m);
  // the rectangles: the four surfaces, and the walls x = 0 and x = nx
  const std::size_t rectangle_triangles = 2 * (4 * nx * ny + 2 * 3 * ny);
  Tr tr;
  std::vector<Vertex_handle> vh;
  for(const Point& p : m.points()) vh.push_back(tr.insert(Weighted_point(p)));
  const std::size_t before = number_of_triangles_present(tr, vh, triangles);
  std::vector<internal::Cocircular_flip<Tr> > flipped;
  const internal::Cocircular_flip_statistics s = internal::flip_cocircular_diagonals(tr, vh, triangles, true, &flipped);
  const std::size_t after = number_of_triangles_present(tr, vh, triangles);
  std::cout << "grid box: " << triangles.size() << " input triangles, " << before << " facets before, " << after
            << " after; " << s.number_of_flips << " flips; left: " << s.number_of_missing_edges << " missing edges, "
            << s.number_of_cocircular_quads << " cocircular quads, " << s.number_of_refused_rings
            << " refused (ring), " << s.number_of_refused_apexes << " refused (apex)" << std::endl;
  assert(tr.is_valid());
  assert(before == triangles.size() - rectangle_triangles); // only the parallelograms' (Delaunay) triangles
  assert(s.number_of_flips == flipped.size());
  assert(after == before + 2 * s.number_of_flips);          // each flip gives both triangles of its quad
  assert(s.number_of_flips >= 2 * 3 * ny);                   // at least the walls x = 0 and x = nx
  assert(s.number_of_refused_apexes == 0);                   // no interior points: every apex is a model point
  assert(s.number_of_missing_edges == s.number_of_refused_rings);

  // the same flips whatever the order of insertion
  Tr tr2;
  std::vector<Vertex_handle> vh2(m.number_of_points());
  for(std::size_t i = m.number_of_points(); i-- > 0;) vh2[i] = tr2.insert(Weighted_point(m.point(i)));
  const internal::Cocircular_flip_statistics s2 = internal::flip_cocircular_diagonals(tr2, vh2, triangles);
  assert(s2.number_of_flips == s.number_of_flips && number_of_triangles_present(tr2, vh2, triangles) == after);

  // an apex that is not a model point (an interior point above a quad) refuses that flip
  Tr tr3;
  std::vector<Vertex_handle> vh3;
  for(const Point& p : m.points()) vh3.push_back(tr3.insert(Weighted_point(p)));
  tr3.insert(Weighted_point(Point(2.5, 1.5, 0.25)));
  const internal::Cocircular_flip_statistics s3 = internal::flip_cocircular_diagonals(tr3, vh3, triangles);
  assert(s3.number_of_refused_apexes >= 1 && s3.number_of_flips < s.number_of_flips);
  assert(tr3.is_valid());

  // removing model points that are safe to remove keeps the triangulation valid
  std::size_t removed = 0;
  for(std::size_t i = 0; i < vh.size(); i += 7)
    if(internal::is_vertex_removal_safe(tr, vh[i]))
    {
      tr.remove(vh[i]);
      ++removed;
    }
  assert(removed > 0 && tr.is_valid());
}

// 2. a point exactly on a flipped cell's circumsphere, and the removal of an
// apex of a flipped quad. The quad (0,0,0) (6,0,0) (6,8,0) (0,8,0) lies on the
// circle of centre (3,4,0) and radius 5; the apex above is on the sphere of
// centre (3,4,12) and radius 13, the one below on that of centre (3,4,0) and
// radius 5: both spheres have many points with integer coordinates.
void test_cospherical_points()
{
  std::vector<Point> above_sphere, below_sphere;
  for(int a = -13; a <= 13; ++a)
    for(int b = -13; b <= 13; ++b)
      for(int c = -13; c <= 13; ++c)
      {
        if(a * a + b * b + c * c == 169) above_sphere.push_back(Point(3 + a, 4 + b, 12 + c));
        if(a * a + b * b + c * c == 25) below_sphere.push_back(Point(3 + a, 4 + b, c));
      }
  const std::vector<Point> quad = {Point(0, 0, 0), Point(6, 0, 0), Point(6, 8, 0), Point(0, 8, 0)};
  const std::vector<std::array<std::size_t, 3> > triangles = {{{0, 1, 2}}, {{0, 2, 3}}};

  std::size_t flips = 0, not_star = 0, inserted = 0, unsafe = 0, removed = 0;
  for(int seed = 0; seed < 40; ++seed)
  {
    CGAL::Random rng(seed);
    Tr tr;
    std::vector<Vertex_handle> vh;
    for(const Point& p : quad) vh.push_back(tr.insert(Weighted_point(p)));
    std::vector<Point> up, down;
    for(const Point& p : above_sphere) if(p.z() > 0) up.push_back(p);
    for(const Point& p : below_sphere) if(p.z() < 0) down.push_back(p);
    const Vertex_handle e = tr.insert(Weighted_point(up[rng.get_int(0, int(up.size()))]));
    const Vertex_handle f = tr.insert(Weighted_point(down[rng.get_int(0, int(down.size()))]));
    for(int k = 0; k < 6; ++k)
      tr.insert(Weighted_point(Point(rng.get_double(-30, 36), rng.get_double(-30, 38), rng.get_double(-40, 60))));
    // a box around everything: the points below are inserted inside the convex
    // hull, as Steiner points are
    for(int k = 0; k < 8; ++k)
      tr.insert(Weighted_point(Point(k & 1 ? 100 : -100, k & 2 ? 100 : -100, k & 4 ? 100 : -100)));
    // the apexes are not model points: flip anyway (input_apexes_only false)
    std::vector<internal::Cocircular_flip<Tr> > flipped;
    const auto s = internal::flip_cocircular_diagonals(tr, vh, triangles, false, &flipped);
    assert(tr.is_valid());
    if(s.number_of_flips == 0) continue;
    ++flips;
    Cell_handle c;
    int i, j;
    assert(tr.is_edge(vh[0], vh[2], c, i, j) && !tr.is_edge(vh[1], vh[3], c, i, j));

    // removing an apex of the flipped quad (adjacent to its four corners) is
    // what CGAL cannot do: its canonical triangulation of the link has bd
    for(Vertex_handle apex : {e, f})
    {
      bool adjacent = true;
      for(Vertex_handle q : vh) adjacent = adjacent && tr.is_edge(apex, q, c, i, j);
      const bool safe = internal::is_vertex_removal_safe(tr, apex);
      if(adjacent) assert(!safe);
      if(!safe) ++unsafe;
    }

    // points exactly on the spheres, in the quad's plane on and off its circle
    std::vector<Point> more = above_sphere;
    more.insert(more.end(), below_sphere.begin(), below_sphere.end());
    for(int k = 0; k < 20; ++k) more.push_back(Point(rng.get_int(-3, 10), rng.get_int(-2, 11), 0));
    std::mt19937 shuffle(seed);
    std::shuffle(more.begin(), more.end(), shuffle);
    for(const Point& p : more)
    {
      const Weighted_point wp(p);
      Tr::Locate_type lt;
      int li, lj;
      const Cell_handle loc = tr.locate(wp, lt, li, lj);
      if(lt == Tr::VERTEX) continue;
      std::vector<Cell_handle> zone;
      std::vector<Tr::Facet> boundary;
      tr.find_conflicts(wp, loc, std::back_inserter(boundary), std::back_inserter(zone), CGAL::Emptyset_iterator());
      if(!internal::is_star_shaped_conflict_zone(tr, p, zone))
      {
        // inserting with this zone would corrupt the triangulation: ties as no conflict
        ++not_star;
        internal::find_strict_conflicts(tr, wp, loc, zone, boundary);
        assert(!zone.empty() && internal::is_star_shaped_conflict_zone(tr, p, zone));
      }
      tr.insert_in_hole(wp, zone.begin(), zone.end(), boundary.front().first, boundary.front().second);
      ++inserted;
      assert(tr.is_valid());
    }
    // then every vertex removal the check allows keeps it valid
    std::vector<Vertex_handle> all;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) all.push_back(v);
    for(std::size_t k = 0; k < all.size(); k += 3)
      if(internal::is_vertex_removal_safe(tr, all[k]))
      {
        tr.remove(all[k]);
        ++removed;
      }
    assert(tr.is_valid());
  }
  std::cout << "cospherical points: " << flips << " configurations flipped, " << inserted << " points inserted, "
            << not_star << " conflict zones not star-shaped (inserted with the strict zone), " << unsafe
            << " apexes unsafe to remove, " << removed << " vertices removed" << std::endl;
  assert(flips >= 20);
  assert(not_star > 0); // the hazard is real, and guarded
  assert(unsafe > 0);
  assert(removed > 0);
}

} // namespace

int main()
{
  test_grid_box();
  test_cospherical_points();
  std::cout << "test_cocircular_diagonals: OK" << std::endl;
  return EXIT_SUCCESS;
}
