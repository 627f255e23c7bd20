// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// bench_relaxation (issue 5): throughput of relax_bubbles() in bubble-steps per
// second with 1 and 2 threads on the layered model scaled up, and, per model,
// the pipeline's relaxation (time, where it goes) and the distribution of the
// overlap ratios it leaves. A benchmark, not a test.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/Surface_bubble_sizing_field.h>
#include <CGAL/Bubble_mesh_3/control_bubble_population.h>
#include <CGAL/Bubble_mesh_3/make_layered_model.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>
#include <CGAL/Bubble_mesh_3/relax_bubbles.h>
#include <CGAL/Bubble_mesh_3/Repulsive_bubble_force.h>
#include <CGAL/Bubble_mesh_3/remesh_surfaces.h>
#include <CGAL/Bubble_mesh_3/retriangulate_planar_patches.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "../test/Bubble_mesh_3/region_sides.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace BM = CGAL::Bubble_mesh_3;
namespace params = CGAL::Bubble_mesh_3::parameters;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef BM::Geological_model_3<K> Model;
typedef BM::Bubble<K> Bubble;

namespace {

const char* usage =
  "Usage: bench_relaxation throughput [--edge-length E] [--steps N] [--warmup W] [--threads LIST] [--skin LIST]\n"
  "       bench_relaxation alpha [MODEL ...] [--threads N] [--skin S] [--rounds]\n"
  "                            [--remesh-surfaces | --planar [--tilted-size-factor F]]\n"
  "                            [--repulsive] [--by-wall]\n"
  "                            [--cell-edge-factor F] [--graded-cells G]\n"
  "                            [--damping C] [--resting R] [--paper-overlap-ratio]\n"
  "                            [--paper-dynamics]\n"
  "\n"
  "throughput  the bundled layered model (make_layered_model) with surface triangles of\n"
  "            longest edge E (default 12, for about 200k interior bubbles): surface\n"
  "            bubbles, placement, one population pass (the crowded start thinned), then\n"
  "            N relaxation steps (default 100; no population control, no early stop,\n"
  "            no resting bubbles: a tolerance of 0 leaves none at rest)\n"
  "            from that same start with each thread count of LIST (default 1,2).\n"
  "            Prints bubble-steps per second over steps W+1 to N (default W = 20: the\n"
  "            first steps of a crowded start cost more confinement work; wall clock\n"
  "            as the visitor sees it), over the whole call (set-up included), and\n"
  "            the process CPU time of the call; the result must be the same for every\n"
  "            thread count (checked), and the neighbour-list rebuilds. --skin sets\n"
  "            relax_bubbles()'s neighbor_skin (default: its own default); a\n"
  "            list (0.15,0.25,0.15,0.25) runs every thread count for each in turn,\n"
  "            from the same start: interleaved runs, for A/B on a noisy machine.\n"
  "alpha       for each MODEL (default: the bundled layered_model.obj and every .ml in\n"
  "            ../shared/data/geomodels next to the checkout): surface bubbles, placement\n"
  "            and relax_bubbles() with default parameters on N threads (default 1);\n"
  "            relaxation wall and CPU time and where the wall time went (steps,\n"
  "            population passes); bubbles outside their region by\n"
  "            CGAL::Side_of_triangle_mesh; overlap-ratio quantiles, histogram and the\n"
  "            share inside [10,14]. --rounds prints a line at the end of every\n"
  "            population round (region, changes, population, steps, last move).\n"
  "            --graded-cells passes place_initial_bubbles()'s graded_cell_factor (cells\n"
  "            that follow the sizing field; default: its own, as the program; 0: the\n"
  "            paper's lattice, whose edge --cell-edge-factor scales, default 1).\n"
  "            --paper-dynamics relaxes with METHOD.md's damped dynamics (Heun's\n"
  "            scheme, inertial_relaxation(false)) instead of FIRE; --damping passes\n"
  "            its damping c (default: its own, 2 sqrt(m k) = 2 with m = k = 1).\n"
  "            --resting passes its resting_displacement_ratio (default: its own;\n"
  "            0: every bubble moves at every step). Bubble-steps count moved bubbles.\n"
  "            --paper-overlap-ratio: population control with METHOD.md's ratio as it\n"
  "            stands (solid_angle_overlap_ratio(false), wall_overlap_ratio(false)); the share\n"
  "            of interior bubbles inside [10,14] is printed with both ratios either way.\n"
  "            --remesh-surfaces runs remesh_surfaces() (defaults) on each model first,\n"
  "            as bubble_mesh_3 --remesh-surfaces does, and relaxes in the re-meshed one\n"
  "            (with the sizing field's area_weighted_radius_floor, as the program).\n"
  "            --planar re-triangulates the planar pieces first (retriangulate_planar_patches(),\n"
  "            defaults), as bubble_mesh_3 does by default with the surfaces kept;\n"
  "            --planar-axis-only refines only the axis-plane pieces (refine_tilted_pieces(false));\n"
  "            --tilted-size-factor F passes its tilted_size_factor (default 1.5).\n"
  "            --repulsive relaxes with Repulsive_bubble_force instead of the cubic law.\n"
  "            --by-wall also splits the interior bubbles by distance to the nearest\n"
  "            input triangle (in their radius) and, within 3 radii, by that triangle's\n"
  "            longest edge (in their radius): where the ratios outside [10,14] sit.\n"
  "            A MODEL written layered:E is the bundled model made at longest surface\n"
  "            edge E (make_layered_model; 80 is the bundled size). --skin as above.\n";

double cpu_seconds()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::string load_average()
{
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

// wall time of the steps, and of what happens between rounds, as a visitor sees them
struct Step_clock
{
  CGAL::Real_timer timer;
  std::size_t warmup = 1;  // steps of a region before the timed window opens (at least 1)
  double first = -1., last = 0., previous = 0.;
  double step_seconds = 0., between_rounds = 0., before_first = 0.;
  double timed_bubble_steps = 0.;  // over the steps after the warm-up
  double cpu_first = 0., cpu_last = 0.;  // process CPU time at `first` and `last`
  bool started = false;
  bool print_rounds = false;  // a line at the end of every round (alpha --rounds)

  Step_clock() { timer.start(); }
  void operator()(const BM::Relaxation_progress& p)
  {
    const double now = timer.time();
    if(p.end_of_round && print_rounds)
      std::cout << "    region " << p.region << " round " << p.round << ": +" << p.added << " -" << p.removed
                << " -> " << p.population << " bubbles, " << p.step << " steps, last move " << p.max_displacement
                << " r, at " << now << " s" << std::endl;
    if(!p.end_of_round)
    {
      if(!started) { before_first = now; started = true; }
      else if(p.step == 1) between_rounds += now - previous;
      else step_seconds += now - previous;
      if(p.step == warmup && first < 0.) { first = now; cpu_first = cpu_seconds(); }
      if(p.step > warmup) timed_bubble_steps += double(p.population);
      last = now;
      cpu_last = cpu_seconds();
    }
    previous = now;
  }
};

// FNV-1a over the bits of the centres and radii: compares results across builds
std::uint64_t result_hash(const std::vector<Bubble>& bubbles)
{
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&](double v) {
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    for(int b = 0; b < 8; ++b) { h ^= (u >> (8 * b)) & 0xff; h *= 1099511628211ull; }
  };
  for(const Bubble& b : bubbles)
  {
    add(b.center.x()); add(b.center.y()); add(b.center.z()); add(b.radius);
  }
  return h;
}

struct Models
{
  std::vector<std::string> paths;
};

bool read_model(const std::string& path, Model& m)
{
  try
  {
    BM::IO::read_geological_model(path, m);
    return true;
  }
  catch(const std::exception& e)
  {
    std::cerr << path << ": " << e.what() << std::endl;
    return false;
  }
}

int throughput(double edge_length, std::size_t steps, std::size_t warmup, const std::vector<std::size_t>& thread_counts,
               const std::vector<double>& skins)
{
  Model m;
  BM::Layered_model_parameters lp;
  lp.edge_length = edge_length;
  CGAL::Real_timer t;
  t.start();
  BM::make_layered_model(m, lp);
  const std::vector<Bubble> surface = BM::place_surface_bubbles(m);
  const BM::Surface_bubble_sizing_field<K> sizing(m, surface);
  std::vector<Bubble> start = BM::place_initial_bubbles(m, surface, sizing);
  const std::size_t placed = start.size();
  BM::control_bubble_population(m, surface, start, sizing);
  std::cout << "layered model, edge length " << edge_length << ": " << m.number_of_triangles() << " triangles, "
            << surface.size() << " surface bubbles, " << placed << " placed, " << start.size()
            << " interior bubbles after one population pass (" << t.time() << " s)" << std::endl;

  for(double skin : skins)
  {
    if(skins.size() > 1) std::cout << " neighbor_skin " << skin << ":" << std::endl;
    std::vector<Bubble> first_result;
    double one_thread = 0.;
    for(std::size_t threads : thread_counts)
    {
      std::vector<Bubble> interior = start;
      Step_clock clock;
      clock.warmup = warmup;
      const std::string load = load_average();
      const double c0 = cpu_seconds();
      const BM::Relaxation_report rep = BM::relax_bubbles(
        m, surface, interior, sizing,
        params::number_of_threads(
          threads, params::number_of_population_rounds(
                     0, params::number_of_relaxation_steps(
                          steps, params::displacement_tolerance(
                                   0., params::neighbor_skin(skin, params::visitor(std::ref(clock))))))));
      const double cpu = cpu_seconds() - c0;
      const double step_wall = clock.last - clock.first;
      const double rate = clock.timed_bubble_steps / step_wall;
      if(threads == thread_counts.front()) one_thread = rate;
      std::cout << std::fixed << std::setprecision(3) << "  " << threads << " thread(s): " << rep.steps
                << " region-steps, " << rep.bubble_steps << " bubble-steps; steps " << warmup + 1 << " to " << steps << ": "
                << clock.timed_bubble_steps << " bubble-steps in " << step_wall << " s wall -> "
                << std::setprecision(0) << rate << " bubble-steps/s (" << rate / double(threads) << " per thread)"
                << std::setprecision(3) << ", " << clock.cpu_last - clock.cpu_first << " s CPU -> " << std::setprecision(0)
                << clock.timed_bubble_steps / (clock.cpu_last - clock.cpu_first) << " per CPU second"
                << std::setprecision(3) << "; whole call " << rep.seconds << " s wall, " << cpu << " s CPU -> "
                << std::setprecision(0) << rep.bubble_steps / rep.seconds << " bubble-steps/s wall, "
                << rep.bubble_steps / cpu << " per CPU second; " << rep.list_rebuilds << " list rebuilds"
                << std::setprecision(2);
      if(threads != thread_counts.front()) std::cout << "; speed-up " << rate / one_thread;
      std::cout << "; load before: " << load << "; result hash " << std::hex << result_hash(interior) << std::dec
                << std::endl;
      if(first_result.empty()) first_result = interior;
      else
      {
        bool same = first_result.size() == interior.size();
        for(std::size_t i = 0; same && i < interior.size(); ++i)
          same = first_result[i].center == interior[i].center && first_result[i].radius == interior[i].radius;
        std::cout << "    same result as with " << thread_counts.front() << " thread(s): " << (same ? "yes" : "NO")
                  << std::endl;
        if(!same) return EXIT_FAILURE;
      }
    }
  }
  return EXIT_SUCCESS;
}

double quantile(const std::vector<double>& sorted, double q)
{
  if(sorted.empty()) return 0.;
  return sorted[std::size_t(q * double(sorted.size() - 1) + 0.5)];
}

// The interior bubbles by distance d from the nearest input triangle (in their
// radius) and, for d < 3, by that triangle's longest edge L (in their radius),
// each class with its overlap ratios against [10, 14]: a bubble beside an
// input triangle many radii wide faces a wall with no surface bubble on it.
void print_wall_classes(const Model& m, const std::vector<Bubble>& interior, const std::vector<double>& alpha)
{
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator> > > Tree;
  std::vector<K::Triangle_3> triangles;
  for(const Model::Triangle& t : m.triangles()) triangles.emplace_back(m.point(t[0]), m.point(t[1]), m.point(t[2]));
  if(triangles.empty()) return;
  Tree tree(triangles.cbegin(), triangles.cend());
  tree.accelerate_distance_queries();
  const char* names[8] = {"d < 1", "1 <= d < 2", "2 <= d < 3", "3 <= d < 5", "d >= 5",
                          "d < 3, L < 3", "d < 3, 3 <= L < 6", "d < 3, L >= 6"};
  std::size_t count[8][3] = {};
  for(std::size_t i = 0; i < interior.size(); ++i)
  {
    const Bubble& b = interior[i];
    const auto hit = tree.closest_point_and_primitive(b.center);
    const double d = std::sqrt(CGAL::squared_distance(b.center, hit.first)) / b.radius;
    const K::Triangle_3& t = *hit.second;
    double longest = 0.;
    for(int k = 0; k < 3; ++k) longest = (std::max)(longest, std::sqrt(CGAL::squared_distance(t[k], t[(k + 1) % 3])));
    longest /= b.radius;
    const int side = alpha[i] < 10. ? 0 : alpha[i] > 14. ? 2 : 1;
    ++count[d < 1. ? 0 : d < 2. ? 1 : d < 3. ? 2 : d < 5. ? 3 : 4][side];
    if(d < 3.) ++count[longest < 3. ? 5 : longest < 6. ? 6 : 7][side];
  }
  std::ostringstream out; // (its own stream: the caller's number format stays as it is)
  out << "  by distance d to the nearest input triangle and its longest edge L, both over the bubble's radius:\n"
      << "  | class | bubbles | <10 | [10,14] | >14 | share in [10,14] |\n  |---|---|---|---|---|---|\n";
  for(int c = 0; c < 8; ++c)
  {
    const std::size_t n = count[c][0] + count[c][1] + count[c][2];
    out << "  | " << names[c] << " | " << n << " | " << count[c][0] << " | " << count[c][1] << " | " << count[c][2]
        << " | " << std::fixed << std::setprecision(1) << (n > 0 ? 100. * double(count[c][1]) / double(n) : 0.)
        << " % |\n";
  }
  std::cout << out.str() << std::flush;
}

int alpha_table(const std::vector<std::string>& paths, std::size_t threads, double skin, bool print_rounds,
                bool remesh, int planar, double tilted_factor, bool repulsive, bool by_wall, double cell_edge_factor, double graded, double damping, double resting, bool paper_dynamics,
                bool paper_ratio)
{
  std::ostringstream table;
  table << "| model | interior | outside | relax wall s | CPU s | steps | rounds | min | 1% | 5% | 25% | 50% | 75% | "
           "95% | 99% | max | <10 | [10,14] | >14 |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
           "---|---|\n";
  int status = EXIT_SUCCESS;
  for(const std::string& path : paths)
  {
    Model m;
    std::string name = path.substr(path.find_last_of('/') + 1);
    if(path.compare(0, 8, "layered:") == 0)
    {
      // the bundled model's generator at another size: a scale study on clean surfaces
      BM::Layered_model_parameters lp;
      lp.edge_length = std::atof(path.c_str() + 8);
      if(!(lp.edge_length > 0.))
      {
        std::cerr << path << ": the edge length after 'layered:' must be a positive number" << std::endl;
        status = EXIT_FAILURE;
        continue;
      }
      try { BM::make_layered_model(m, lp); }
      catch(const std::exception& e)
      {
        std::cerr << path << ": " << e.what() << std::endl;
        status = EXIT_FAILURE;
        continue;
      }
      name = "layered model, edge length " + path.substr(8);
    }
    else if(!read_model(path, m)) { status = EXIT_FAILURE; continue; }
    if(planar && !remesh)
    {
      Model retriangulated;
      const BM::Planar_retriangulation_report pr =
        BM::retriangulate_planar_patches(m, retriangulated, BM::parameters::refine_tilted_pieces(planar == 1,
                                                                  BM::parameters::tilted_size_factor(tilted_factor)));
      std::cout << name << ": planar pieces re-triangulated, " << pr.number_of_points_added << " new points, "
                << m.number_of_triangles() << " -> " << retriangulated.number_of_triangles() << " triangles" << std::endl;
      m = std::move(retriangulated);
      name += " (planar)";
    }
    if(remesh)
    {
      Model remeshed;
      const BM::Surface_remeshing_report rr = BM::remesh_surfaces(m, remeshed);
      std::cout << name << ": surfaces re-meshed, " << m.number_of_triangles() << " -> " << remeshed.number_of_triangles()
                << " triangles, min angle " << rr.min_angle << " (" << rr.time << " s)" << std::endl;
      m = std::move(remeshed);
      name += " (re-meshed)";
    }
    if(repulsive) name += " (repulsive law)";
    const std::vector<Bubble> surface = BM::place_surface_bubbles(m);
    // as make_bubble_mesh_3() on re-meshed surfaces
    const BM::Surface_bubble_sizing_field<K> sizing(m, surface, params::area_weighted_radius_floor(remesh));
    std::vector<Bubble> interior =
      BM::place_initial_bubbles(m, surface, sizing, params::graded_cell_factor(graded, params::cell_edge_factor(cell_edge_factor)));
    const std::size_t placed = interior.size();
    Step_clock clock;
    clock.print_rounds = print_rounds;
    const std::string load = load_average();
    const double c0 = cpu_seconds();
    const auto np = params::inertial_relaxation(!paper_dynamics, params::solid_angle_overlap_ratio(!paper_ratio, params::wall_overlap_ratio(!paper_ratio, params::number_of_threads(
      threads, params::resting_displacement_ratio(resting, params::neighbor_skin(skin, params::visitor(std::ref(clock))))))));
    const auto relax = [&](const auto& with) {
      return repulsive ? BM::relax_bubbles(m, surface, interior, sizing, params::force_law(BM::Repulsive_bubble_force(), with))
                       : BM::relax_bubbles(m, surface, interior, sizing, with);
    };
    const BM::Relaxation_report rep = damping >= 0. ? relax(params::damping(damping, np)) : relax(np);
    const double cpu = cpu_seconds() - c0;
    const Region_sides<K> sides(m);
    std::size_t outside = 0;
    for(const Bubble& b : interior)
      if(!sides.inside(b)) ++outside;
    std::vector<double> alpha = BM::overlap_ratios(m, surface, interior, params::solid_angle_overlap_ratio(!paper_ratio, params::wall_overlap_ratio(!paper_ratio)));
    // METHOD.md's formula as it stands (neighbours counted whatever their size), for issue 5's figure
    std::size_t paper_inside = 0;
    for(double a : paper_ratio ? alpha : BM::overlap_ratios(m, surface, interior, params::solid_angle_overlap_ratio(false, params::wall_overlap_ratio(false))))
      paper_inside += (a >= 10. && a <= 14.);
    const std::vector<double> alpha_of_bubble = alpha;
    std::sort(alpha.begin(), alpha.end());
    std::size_t rounds = 0, converged = 0;
    for(const BM::Region_relaxation_report& r : rep.regions) { rounds += r.rounds; converged += r.converged; }
    std::cout << name << ": " << m.number_of_regions() << " regions, " << m.number_of_triangles() << " triangles, "
              << surface.size() << " surface bubbles, " << placed << " placed -> " << interior.size()
              << " relaxed (" << rep.added << " added, " << rep.removed << " removed, " << rep.rejected
              << " rejected)\n  relaxation " << rep.seconds << " s wall, " << cpu << " s CPU (" << threads
              << " thread(s), load before " << load << "): " << rep.steps << " steps, " << rep.bubble_steps
              << " bubble-steps, " << rounds << " population rounds over " << rep.regions.size() << " regions ("
              << converged << " converged)\n  wall time: before the first step " << clock.before_first
              << " s, steps " << clock.step_seconds << " s, between rounds (population passes, list rebuilds) "
              << clock.between_rounds << " s (meaningful with 1 thread: regions run one after the other)\n"
              << "  outside their region (Side_of_triangle_mesh): " << outside << "; overlap ratio <10: " << rep.below
              << ", [10,14]: " << rep.inside << ", >14: " << rep.above << " -> " << std::setprecision(4)
              << 100. * rep.share_inside_bounds() << " % inside (METHOD.md's unweighted ratio: "
              << 100. * double(paper_inside) / double((std::max)(std::size_t(1), interior.size()))
              << " % inside)\n  histogram (bin k: k <= alpha < k+1):";
    for(std::size_t b = 0; b < rep.overlap_histogram.size(); ++b)
      if(rep.overlap_histogram[b] > 0) std::cout << " " << b << ":" << rep.overlap_histogram[b];
    std::cout << std::endl;
    for(const BM::Region_relaxation_report& r : rep.regions)
      std::cout << "    region " << r.region << ": " << r.input_population << " -> " << r.population << " bubbles ("
                << r.surface_bubbles << " on its surfaces), " << r.steps << " steps, " << r.rounds << " rounds, "
                << (r.converged ? "converged" : "not converged") << " (last move " << r.max_displacement << "), "
                << (r.population_settled ? "settled" : r.stopped_cycling ? "cycle guard" : "round budget")
                << ", <10/in/>14: " << r.below << "/" << r.inside << "/" << r.above << ", " << r.seconds << " s"
                << std::endl;
    if(by_wall) print_wall_classes(m, interior, alpha_of_bubble);
    table << std::fixed << std::setprecision(2) << "| " << name << " | " << interior.size() << " | " << outside
          << " | " << rep.seconds << " | " << cpu << " | " << rep.steps << " | " << rounds;
    for(double q : {0., 0.01, 0.05, 0.25, 0.5, 0.75, 0.95, 0.99, 1.}) table << " | " << quantile(alpha, q);
    table << std::setprecision(1) << " | " << rep.below << " | " << rep.inside << " ("
          << 100. * rep.share_inside_bounds() << " %) | " << rep.above << " |\n";
    if(outside > 0) status = EXIT_FAILURE;
  }
  std::cout << "\n" << table.str();
  return status;
}

std::vector<std::string> default_models(const char* argv0)
{
  // the checkout is two levels above the build's bench directory, or the current directory
  std::vector<std::string> roots = {".", "..", "../.."};
  std::string exe(argv0);
  const std::size_t slash = exe.find_last_of('/');
  if(slash != std::string::npos) roots.push_back(exe.substr(0, slash) + "/../..");
  for(const std::string& root : roots)
  {
    const std::string obj = root + "/examples/Bubble_mesh_3/data/layered_model.obj";
    if(!std::ifstream(obj)) continue;
    std::vector<std::string> out = {obj};
    for(const char* name : {"modelA1", "modelA2", "modelA5", "CloudSpin_fixed"})
    {
      const std::string ml = root + "/../shared/data/geomodels/" + name + ".ml";
      if(std::ifstream(ml)) out.push_back(ml);
    }
    return out;
  }
  return {};
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2 || (std::strcmp(argv[1], "throughput") != 0 && std::strcmp(argv[1], "alpha") != 0))
  {
    std::cerr << usage;
    return 2;
  }
  const bool alpha = std::strcmp(argv[1], "alpha") == 0;
  double edge_length = 12., cell_edge_factor = 1., graded = BM::default_graded_cell_factor, damping = -1.; // damping < 0: relax_bubbles()'s own
  double resting = BM::internal::Dynamics_settings().rest_ratio; // relax_bubbles()'s default
  std::size_t steps = 100, warmup = 20;
  std::vector<double> skins{BM::internal::Dynamics_settings().skin}; // relax_bubbles()'s default
  std::vector<std::size_t> threads = alpha ? std::vector<std::size_t>{1} : std::vector<std::size_t>{1, 2};
  std::vector<std::string> models;
  bool print_rounds = false, remesh = false, repulsive = false, by_wall = false, paper_ratio = false, paper_dynamics = false;
  int planar = 0; // 1: retriangulate_planar_patches() defaults, 2: axis planes only
  double tilted_factor = BM::default_tilted_size_factor; // its tilted_size_factor
  for(int i = 2; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(a == "--edge-length" && has_value) edge_length = std::atof(argv[++i]);
    else if(a == "--steps" && has_value) steps = std::size_t(std::atol(argv[++i]));
    else if(a == "--warmup" && has_value) warmup = std::size_t(std::atol(argv[++i]));
    else if(a == "--skin" && has_value)
    {
      skins.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while(std::getline(list, item, ','))
        skins.push_back(std::atof(item.c_str()));
    }
    else if(a == "--rounds" && alpha) print_rounds = true;
    else if(a == "--cell-edge-factor" && alpha && has_value) cell_edge_factor = std::atof(argv[++i]);
    else if(a == "--graded-cells" && alpha && has_value) graded = std::atof(argv[++i]);
    else if(a == "--damping" && alpha && has_value)
    {
      damping = std::atof(argv[++i]);
      if(!(damping >= 0.)) { std::cerr << "--damping takes a number >= 0, got '" << argv[i] << "'\n" << usage; return 2; }
    }
    else if(a == "--resting" && alpha && has_value) resting = std::atof(argv[++i]);
    else if(a == "--remesh-surfaces" && alpha) remesh = true;
    else if(a == "--paper-overlap-ratio" && alpha) paper_ratio = true;
    else if(a == "--paper-dynamics" && alpha) paper_dynamics = true;
    else if(a == "--planar" && alpha) planar = 1;
    else if(a == "--planar-axis-only" && alpha) planar = 2;
    else if(a == "--tilted-size-factor" && alpha && has_value)
    {
      tilted_factor = std::atof(argv[++i]);
      if(!(tilted_factor >= 1.)) { std::cerr << "--tilted-size-factor takes a number >= 1, got '" << argv[i] << "'\n" << usage; return 2; }
    }
    else if(a == "--repulsive" && alpha) repulsive = true;
    else if(a == "--by-wall" && alpha) by_wall = true;
    else if(a == "--threads" && has_value)
    {
      threads.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while(std::getline(list, item, ',')) threads.push_back(std::size_t(std::atol(item.c_str())));
    }
    else if(a.size() > 1 && a[0] == '-')
    {
      std::cerr << usage;
      return 2;
    }
    else models.push_back(a);
  }
  const bool bad_skin = skins.empty() || std::any_of(skins.begin(), skins.end(), [](double s) { return !(s > 0.); });
  if(threads.empty() || !(edge_length > 0.) || !(cell_edge_factor > 0.) || !(graded >= 0.) || !(resting >= 0. && resting < 1.) || bad_skin || warmup == 0 || warmup >= steps)
  {
    std::cerr << usage;
    return 2;
  }
  std::cout << "command:";
  for(int i = 0; i < argc; ++i) std::cout << " " << argv[i];
  std::cout << "\n" << sysconf(_SC_NPROCESSORS_ONLN) << " cores online, load " << load_average() << std::endl;
  if(!alpha) return throughput(edge_length, steps, warmup, threads, skins);
  if(models.empty()) models = default_models(argv[0]);
  return alpha_table(models, threads.front(), skins.front(), print_rounds, remesh, planar, tilted_factor, repulsive, by_wall, cell_edge_factor, graded, damping, resting, paper_dynamics, paper_ratio);
}
