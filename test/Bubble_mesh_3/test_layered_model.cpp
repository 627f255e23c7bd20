// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// The synthetic layered model: closed, consistently oriented regions whose
// volumes fill the box, shared interfaces, a small fault inside a region that
// touches nothing else, well-shaped triangles, determinism, scaling, and the
// bundled OBJ file matching the generator.

#include <CGAL/Bubble_mesh_3/make_layered_model.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/geological_model_summary.h>

#if __has_include(<CGAL/Bubble_mesh_3/validate_geological_model.h>)
#  include <CGAL/Bubble_mesh_3/validate_geological_model.h>
#  define TEST_HAS_VALIDATION 1
#endif
#include <CGAL/Bubble_mesh_3/IO/read_multibody_obj.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K> Model;
typedef CGAL::Bubble_mesh_3::Layered_model_parameters Parameters;

namespace {

// Every region's boundary, each triangle turned so that it faces out of the
// region, uses each directed edge exactly once and its reverse exactly once:
// closed, manifold along edges, consistently oriented. Returns the number of
// boundary triangles of each region.
std::vector<std::size_t> check_region_boundaries(const Model& m)
{
  std::vector<std::size_t> count(m.number_of_regions() + 1, 0);
  for(std::size_t r = 1; r <= m.number_of_regions(); ++r)
  {
    std::map<std::pair<std::size_t, std::size_t>, int> directed;
    for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
    {
      const auto& p = m.patch(m.patch_of_triangle(t));
      if(p.is_inside_region() || (p.positive_region != r && p.negative_region != r)) continue;
      auto tri = m.triangle(t);
      if(p.positive_region == r) std::swap(tri[1], tri[2]); // the normal must leave r
      for(int k = 0; k < 3; ++k) ++directed[std::make_pair(tri[k], tri[(k + 1) % 3])];
      ++count[r];
    }
    assert(count[r] > 0);
    for(const auto& e : directed)
    {
      if(e.second != 1 || directed.count(std::make_pair(e.first.second, e.first.first)) != 1)
        std::cerr << "region " << m.region(r).name << ": edge " << e.first.first << "-" << e.first.second
                  << " used " << e.second << " times one way\n";
      assert(e.second == 1);
      assert(directed.count(std::make_pair(e.first.second, e.first.first)) == 1);
    }
  }
  return count;
}

// the checks every generated model passes; returns its summary
CGAL::Bubble_mesh_3::Geological_model_summary check_model(const Model& m, const Parameters& p, const std::string& what)
{
  const std::size_t bodies = p.number_of_layers + 1;
  assert(m.number_of_regions() == 2 * bodies);

  // no two triangles on the same three vertices (an interface is one triangle)
  std::set<std::array<std::size_t, 3>> seen;
  for(auto t : m.triangles())
  {
    std::sort(t.begin(), t.end());
    assert(t[0] != t[1] && t[1] != t[2]);
    assert(seen.insert(t).second);
  }

  // patch names are unique and every patch has triangles
  std::set<std::string> names;
  std::vector<std::size_t> per_patch(m.number_of_patches(), 0);
  for(std::size_t t = 0; t < m.number_of_triangles(); ++t) ++per_patch[m.patch_of_triangle(t)];
  for(std::size_t pa = 0; pa < m.number_of_patches(); ++pa)
  {
    assert(names.insert(m.patch(pa).name).second);
    assert(per_patch[pa] > 0);
  }

  const std::vector<std::size_t> boundary = check_region_boundaries(m);

  // volumes: all positive, summing to the box
  const std::vector<double> vol = CGAL::Bubble_mesh_3::region_volumes(m);
  const double box = p.size_x * p.size_y * p.size_z;
  double sum = 0, thin = 0;
  for(std::size_t r = 1; r < vol.size(); ++r)
  {
    assert(vol[r] > 0);
    sum += vol[r];
    if(m.region(r).name.find("Thin_layer") == 0) thin += vol[r];
  }
  std::cout << what << ": " << m.number_of_regions() << " regions, " << m.number_of_patches() << " patches, "
            << m.number_of_triangles() << " triangles, " << m.number_of_points() << " points; volumes sum "
            << sum << " (box " << box << ", rel. error " << std::abs(sum - box) / box << "), outer boundary "
            << vol[0] << "; region boundaries closed and oriented ("
            << *std::min_element(boundary.begin() + 1, boundary.end()) << " .. "
            << *std::max_element(boundary.begin() + 1, boundary.end()) << " triangles)\n";
  assert(std::abs(sum - box) < 1e-9 * box);
  assert(std::abs(vol[0] - box) < 1e-9 * box);
  // the thin layer is about thin_layer_ratio of the height everywhere
  const double thin_expected = p.thin_layer_ratio * box;
  std::cout << "  thin layer volume " << thin << " (a constant thickness would give " << thin_expected << ")\n";
  assert(std::abs(thin - thin_expected) < 0.05 * thin_expected);

  // the small fault: a surface inside one region, sharing no vertex with any other patch
  std::size_t inside = 0;
  for(std::size_t pa = 0; pa < m.number_of_patches(); ++pa)
  {
    if(!m.patch(pa).is_inside_region()) continue;
    ++inside;
    assert(m.patch(pa).name == "Small_fault");
    assert(m.region(m.patch(pa).positive_region).name == "Layer_" + std::to_string(p.number_of_layers) + "_hangingwall");
    std::set<std::size_t> own, other;
    for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
      for(std::size_t v : m.triangle(t)) (m.patch_of_triangle(t) == pa ? own : other).insert(v);
    std::size_t shared = 0;
    for(std::size_t v : own) shared += other.count(v);
    // its border is one closed loop of edges used once
    std::map<std::pair<std::size_t, std::size_t>, int> edges;
    for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
      if(m.patch_of_triangle(t) == pa)
        for(int k = 0; k < 3; ++k)
        {
          std::size_t a = m.triangle(t)[k], b = m.triangle(t)[(k + 1) % 3];
          ++edges[std::make_pair(std::min(a, b), std::max(a, b))];
        }
    std::size_t border = 0;
    std::map<std::size_t, int> border_degree;
    for(const auto& e : edges)
    {
      assert(e.second <= 2);
      if(e.second == 1) { ++border; ++border_degree[e.first.first]; ++border_degree[e.first.second]; }
    }
    for(const auto& d : border_degree) assert(d.second == 2);
    std::cout << "  small fault: " << own.size() << " vertices, " << border << " border edges, " << shared
              << " vertices shared with other patches\n";
    assert(shared == 0);
    assert(border >= 6);
  }
  assert(inside == (p.small_fault ? 1u : 0u));

  // the fault offsets the layers: no horizon of one side shares a vertex with
  // a horizon of the other side (they would line up across the fault)
  std::set<std::size_t> horizon_vertices[2];
  for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
  {
    const std::string& n = m.patch(m.patch_of_triangle(t)).name;
    if(n.find("Horizon_") != 0) continue;
    const int side = n.find("_hangingwall") != std::string::npos ? 1 : 0;
    for(std::size_t v : m.triangle(t)) horizon_vertices[side].insert(v);
  }
  assert(!horizon_vertices[0].empty() && !horizon_vertices[1].empty());
  for(std::size_t v : horizon_vertices[0]) assert(horizon_vertices[1].count(v) == 0);

  const CGAL::Bubble_mesh_3::Geological_model_summary s = CGAL::Bubble_mesh_3::summarize_geological_model(m);
  std::cout << "  min angle " << s.min_angle << " degrees (patch " << s.min_angle_patch_name << "), edges: min "
            << s.min_edge_length << ", median " << s.median_edge_length << ", longest " << s.max_edge_length << "\n";

#ifdef TEST_HAS_VALIDATION
  CGAL::Real_timer timer;
  timer.start();
  CGAL::Bubble_mesh_3::validate_geological_model(m);
  std::cout << "  validate_geological_model passes (" << timer.time() << " s)\n";
#else
  std::cout << "  SKIP validate_geological_model (not available)\n";
#endif
  return s;
}

bool same(const Model& a, const Model& b)
{
  if(a.points() != b.points() || a.triangles() != b.triangles() || a.triangle_patches() != b.triangle_patches())
    return false;
  if(a.number_of_patches() != b.number_of_patches() || a.number_of_regions() != b.number_of_regions()) return false;
  for(std::size_t pa = 0; pa < a.number_of_patches(); ++pa)
    if(a.patch(pa).name != b.patch(pa).name || a.patch(pa).positive_region != b.patch(pa).positive_region ||
       a.patch(pa).negative_region != b.patch(pa).negative_region)
      return false;
  for(std::size_t r = 0; r <= a.number_of_regions(); ++r)
    if(a.region(r).name != b.region(r).name) return false;
  return true;
}

template <class F>
bool throws_invalid_argument(F f)
{
  try { f(); }
  catch(const std::invalid_argument& e)
  {
    std::cout << "  rejected: " << e.what() << "\n";
    return true;
  }
  return false;
}

} // namespace

int main()
{
  CGAL::Real_timer timer;
  timer.start();

  // the default model, as bundled
  const Parameters p;
  Model model;
  CGAL::Bubble_mesh_3::make_layered_model(model, p);
  const auto s = check_model(model, p, "default model");
  std::cout << "  generated in " << timer.time() << " s\n";
  // the surface meshing bound is 30 degrees; horizons, meshed in projection, lose a little
  assert(s.min_angle >= 29.);
  // edges respect the size bound (horizons are meshed in projection: a little slack)
  assert(s.max_edge_length <= 1.05 * 0.2 * p.size_z);
  assert(model.number_of_triangles() > 3000 && model.number_of_triangles() < 8000);
  std::vector<std::string> expected_regions = {"Layer_1_footwall", "Layer_2_footwall", "Thin_layer_footwall",
                                               "Layer_3_footwall", "Layer_4_footwall", "Layer_1_hangingwall",
                                               "Layer_2_hangingwall", "Thin_layer_hangingwall", "Layer_3_hangingwall",
                                               "Layer_4_hangingwall"};
  for(std::size_t r = 1; r <= model.number_of_regions(); ++r) assert(model.region(r).name == expected_regions[r - 1]);

  // determinism, and the seed matters
  Model again;
  CGAL::Bubble_mesh_3::make_layered_model(again, p);
  assert(same(model, again));
  Parameters other_seed = p;
  other_seed.seed = 7;
  Model seeded;
  CGAL::Bubble_mesh_3::make_layered_model(seeded, other_seed);
  assert(!same(model, seeded));
  std::cout << "same parameters give the identical model; seed 7 gives another one ("
            << seeded.number_of_triangles() << " triangles)\n";

  // other shapes
  Parameters q;
  q.number_of_layers = 3;
  q.fault_dip = 80;
  q.small_fault = false;
  q.size_x = 800;
  Model varied;
  CGAL::Bubble_mesh_3::make_layered_model(varied, q);
  check_model(varied, q, "3 layers, dip 80, 800 m, no small fault");

  // a finer model for benchmarks: many more triangles, still valid
  Parameters fine = p;
  fine.edge_length = 0.4 * 0.2 * p.size_z;
  Model fine_model;
  timer.reset();
  CGAL::Bubble_mesh_3::make_layered_model(fine_model, fine);
  std::cout << "finer model (edge length " << fine.edge_length << ") generated in " << timer.time() << " s\n";
  const auto fs = check_model(fine_model, fine, "finer model");
  assert(fine_model.number_of_triangles() > 4 * model.number_of_triangles());
  assert(fs.min_angle >= 29.);

  // parameters that would make a wrong model are refused
  std::cout << "invalid parameters:\n";
  Parameters bad = p;
  bad.number_of_layers = 1;
  assert(throws_invalid_argument([&] { Model m; CGAL::Bubble_mesh_3::make_layered_model(m, bad); }));
  bad = p;
  bad.fault_dip = 40;
  assert(throws_invalid_argument([&] { Model m; CGAL::Bubble_mesh_3::make_layered_model(m, bad); }));
  bad = p;
  // a throw equal to the thin layer's thickness lines two horizons up across the fault
  bad.fault_throw_ratio = p.thin_layer_ratio * p.size_z / ((p.size_z * (1 - p.thin_layer_ratio)) / p.number_of_layers);
  assert(throws_invalid_argument([&] { Model m; CGAL::Bubble_mesh_3::make_layered_model(m, bad); }));
  bad = p;
  bad.undulation_ratio = 0.3; // horizons would cross
  assert(throws_invalid_argument([&] { Model m; CGAL::Bubble_mesh_3::make_layered_model(m, bad); }));

  // the bundled file is this generator's output
  const std::string bundled = std::string(BUBBLE_MESH_3_EXAMPLE_DATA_DIR) + "/layered_model.obj";
  if(std::ifstream(bundled).good())
  {
    Model read;
    CGAL::Bubble_mesh_3::IO::read_multibody_obj(bundled, read);
    const std::vector<double> v0 = CGAL::Bubble_mesh_3::region_volumes(model);
    const std::vector<double> v1 = CGAL::Bubble_mesh_3::region_volumes(read);
    std::cout << "bundled " << bundled << ": " << read.number_of_regions() << " regions, "
              << read.number_of_triangles() << " triangles, " << read.number_of_points() << " points\n";
    assert(read.number_of_regions() == model.number_of_regions());
    assert(read.number_of_triangles() == model.number_of_triangles());
    assert(read.number_of_points() == model.number_of_points());
    double worst = 0;
    for(std::size_t r = 1; r <= model.number_of_regions(); ++r)
    {
      std::size_t rr = 0;
      for(std::size_t k = 1; k <= read.number_of_regions(); ++k)
        if(read.region(k).name == model.region(r).name) rr = k;
      assert(rr != 0);
      worst = std::max(worst, std::abs(v1[rr] - v0[r]) / v0[r]);
    }
    std::cout << "  region volumes match the generated model (largest rel. difference " << worst << ")\n";
    if(worst >= 1e-9)
      std::cerr << "the bundled file is out of date: regenerate it with generate_layered_model -o " << bundled << "\n";
    assert(worst < 1e-9);
#ifdef TEST_HAS_VALIDATION
    CGAL::Bubble_mesh_3::validate_geological_model(read);
    std::cout << "  validate_geological_model passes on the file\n";
#endif
  }
  else
    std::cout << "SKIP bundled file " << bundled << " (not found)\n";

  std::cout << "test_layered_model: OK\n";
  return EXIT_SUCCESS;
}
