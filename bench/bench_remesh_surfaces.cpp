// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Surface re-meshing (issue 9) on given models, one row per model: smallest
// triangle angle and the triangles under 25 degrees (those an input corner
// forces apart), share of edges within [0.5, 1.5] of the target, largest
// relative region volume change against the bound that the distance of the
// new triangles to the input gives, curve Hausdorff distance, validity of
// the output (conforming, closed oriented regions, no crossing) and time.
//
// Usage: bench_remesh_surfaces [--details] [--size L] [--min-size L] [--refine-ribbons] [--no-balance-volumes] MODEL [MODEL ...]
//   (default: the bundled model and every ../shared/data/geomodels model of issue 9)
//   --details  also lists the triangles under 25 degrees outside the wedges of sharp input corners,
//              and the validation problems of an invalid output
//   --min-size L  the thickness rule's floor (minimum_edge_length(L); default a tenth of the smallest patch size)
//   --refine-ribbons  the sizing field's ribbon rule (refine_ribbons(true))
//   --no-balance-volumes  leave the volumes as the chords make them (keep_region_volumes(false)); by default
//                         the free points slide until every region has its input volume

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/remesh_surfaces.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K> Model;
namespace BM = CGAL::Bubble_mesh_3;

namespace {

// Moving a surface by at most d changes the volume it encloses by at most
// d times its area (plus higher-order terms): the bound each region's
// volume change is compared with, from the sampled distance of every output
// triangle to its input patch.
std::vector<double> volume_change_bounds(const Model& input, const Model& output)
{
  std::vector<BM::internal::Remesh_triangle_tree<K> > trees;
  std::vector<std::vector<std::size_t> > patch_triangles(input.number_of_patches());
  for(std::size_t t = 0; t < input.number_of_triangles(); ++t) patch_triangles[input.patch_of_triangle(t)].push_back(t);
  for(std::size_t p = 0; p < input.number_of_patches(); ++p) trees.emplace_back(input, patch_triangles[p]);
  std::vector<double> bound(input.regions().size(), 0.);
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
  {
    const auto& tri = output.triangle(t);
    const Point &a = output.point(tri[0]), &b = output.point(tri[1]), &c = output.point(tri[2]);
    const std::size_t p = output.patch_of_triangle(t);
    if(patch_triangles[p].empty()) continue;
    const Point g = CGAL::centroid(a, b, c);
    const Point samples[7] = {g, CGAL::midpoint(a, b), CGAL::midpoint(b, c), CGAL::midpoint(c, a),
                              CGAL::midpoint(g, a), CGAL::midpoint(g, b), CGAL::midpoint(g, c)};
    double d = 0.;
    for(const Point& s : samples) d = std::max(d, std::sqrt(CGAL::squared_distance(s, trees[p].closest_point(s))));
    const double area = std::sqrt(CGAL::squared_area(a, b, c));
    const auto& patch = output.patch(p);
    if(patch.positive_region == patch.negative_region) continue; // inside a region: encloses nothing
    bound[patch.positive_region] += d * area;
    bound[patch.negative_region] += d * area;
  }
  return bound;
}

double diagonal(const Model& m)
{
  const CGAL::Bbox_3 box = BM::bbox(m);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

void details(const Model& output, const BM::Surface_remeshing_report& r, const BM::Remeshing_sizing_field<K>& field)
{
  // the triangles under the bound outside the wedges of sharp input corners, worst first
  std::vector<std::pair<double, std::size_t> > small;
  for(std::size_t t : r.small_angle_triangles_outside_sharp_wedges)
  {
    const auto& tri = output.triangle(t);
    small.push_back(std::make_pair(
      BM::internal::min_angle_degrees(output.point(tri[0]), output.point(tri[1]), output.point(tri[2])), t));
  }
  std::sort(small.begin(), small.end());
  std::map<std::size_t, std::pair<std::size_t, double> > by_patch; // patch -> (count, worst angle)
  for(const auto& a : small)
  {
    auto& c = by_patch.insert(std::make_pair(output.patch_of_triangle(a.second), std::make_pair(0, a.first))).first->second;
    ++c.first;
  }
  std::cout << "    of the " << r.number_of_small_angle_triangles << " triangles under " << r.angle_bound << " deg, "
            << r.number_of_small_angle_triangles_between_curve_points
            << " have their three points on curves (the curve sampling sets them), "
            << r.number_of_small_angle_triangles_in_sharp_wedges << " lie in the wedge of an input corner under "
            << r.angle_bound << " deg\n";
  std::cout << "    outside those wedges, by patch (triangles, smallest angle):";
  for(const auto& c : by_patch)
    std::cout << " " << output.patch(c.first).name << " " << c.second.first << " (" << c.second.second << ")";
  std::cout << "\n";
  // the points on curves: those of two patches or more, or of a border edge of one
  std::vector<std::set<std::size_t> > patches_of(output.number_of_points());
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
    for(std::size_t v : output.triangle(t)) patches_of[v].insert(output.patch_of_triangle(t));
  std::vector<bool> on_curve(output.number_of_points(), false);
  for(std::size_t v = 0; v < on_curve.size(); ++v) on_curve[v] = patches_of[v].size() > 1;
  for(const auto& e : BM::internal::edge_triangles(output))
    if(e.second.size() == 1) on_curve[e.first.first] = on_curve[e.first.second] = true;
  std::cout << "    triangles under " << r.angle_bound << " deg outside those wedges, worst first (angle, patch, centroid, edge lengths "
            << "(the first from the first point), the point's angle with c when on a curve, target at the centroid; the field's floor is "
            << field.minimum_size() << "):\n";
  for(std::size_t i = 0; i < small.size() && i < 100; ++i)
  {
    const auto& tri = output.triangle(small[i].second);
    const Point g = CGAL::centroid(output.point(tri[0]), output.point(tri[1]), output.point(tri[2]));
    std::cout << "      " << small[i].first << "  patch " << output.patch_of_triangle(small[i].second) << " ("
              << output.patch(output.patch_of_triangle(small[i].second)).name << ")  " << g << "  ";
    for(int k = 0; k < 3; ++k)
      std::cout << std::sqrt(CGAL::squared_distance(output.point(tri[k]), output.point(tri[(k + 1) % 3]))) << " ";
    std::cout << " angles";
    for(int k = 0; k < 3; ++k)
      std::cout << " " << CGAL::approximate_angle(output.point(tri[(k + 2) % 3]), output.point(tri[k]), output.point(tri[(k + 1) % 3]))
                << (on_curve[tri[k]] ? "c" : "");
    std::cout << "  target " << field(g, output.patch_of_triangle(small[i].second)) << "\n";
  }
}

} // namespace

int main(int argc, char** argv)
{
  bool show_details = false, ribbons = false, balance = true;
  double size = 0., min_size = 0.;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--details") show_details = true;
    else if((a == "--size" || a == "--min-size") && i + 1 < argc)
    {
      // a length in model units; a typo must not become 0 (the default) silently
      char* end = nullptr;
      const double v = std::strtod(argv[++i], &end);
      if(*argv[i] == '\0' || *end != '\0' || !(v > 0.) || !std::isfinite(v))
      {
        std::cerr << "bench_remesh_surfaces: " << a << " takes a positive length in model units, got '" << argv[i]
                  << "'\n";
        return 2;
      }
      (a == "--size" ? size : min_size) = v;
    }
    else if(a == "--refine-ribbons") ribbons = true;
    else if(a == "--balance-volumes" || a == "--no-balance-volumes") balance = a == "--balance-volumes";
    else if(a == "--help" || a == "-h")
    {
      std::cout << "usage: bench_remesh_surfaces [--details] [--size L] [--min-size L] [--refine-ribbons] [--no-balance-volumes] [MODEL ...]\n";
      return EXIT_SUCCESS;
    }
    else files.push_back(a);
  }
  if(files.empty())
  {
    files.push_back(std::string(BUBBLE_MESH_3_EXAMPLE_DATA_DIR) + "/layered_model.obj");
    for(const char* name : {"modelA1.ml", "modelA2.ml", "modelA5.ml", "CloudSpin_fixed.ml"})
    {
      const std::string f = std::string(BUBBLE_MESH_3_SHARED_DATA_DIR) + "/" + name;
      if(std::filesystem::exists(f)) files.push_back(f);
      else std::cout << "SKIP " << f << " (not found)\n";
    }
  }

  std::cout << "| model | triangles in -> out | min angle in -> out | under 25 deg (forced by corners) "
               "| edges in [0.5,1.5] | volume rel. error (bound) | triangle distance / size: max, % beyond bound "
               "| curve Hausdorff / diag | valid | time s |\n"
            << "|---|---|---|---|---|---|---|---|---|---|\n";
  int status = EXIT_SUCCESS;
  for(const std::string& file : files)
  {
    Model input;
    try
    {
      BM::IO::read_geological_model(file, input);
      BM::validate_geological_model(input);
    }
    catch(const std::exception& e)
    {
      std::cout << "| " << file << " | input error: " << e.what() << " |\n";
      status = EXIT_FAILURE;
      continue;
    }
    Model output;
    // the field remesh_surfaces() used, for --details: a placeholder it
    // overwrites, built without the thickness rules that make a field costly
    std::unique_ptr<BM::Remeshing_sizing_field<K> > field;
    if(show_details)
      field.reset(new BM::Remeshing_sizing_field<K>(input, BM::detect_model_features(input),
                                                    BM::parameters::elements_across_thickness(0.)));
    // a size or a floor is a named parameter only when given: its absence selects the default
    auto remesh = [&](const auto& np) {
      return size > 0. ? BM::remesh_surfaces(input, output, BM::parameters::edge_length(size, np))
                       : BM::remesh_surfaces(input, output, np);
    };
    const auto np = BM::parameters::sizing_field_output(field.get(), BM::parameters::refine_ribbons(ribbons,
                                                        BM::parameters::keep_region_volumes(balance)));
    const BM::Surface_remeshing_report r =
      min_size > 0. ? remesh(BM::parameters::minimum_edge_length(min_size, np)) : remesh(np);
    const std::vector<std::string> problems = BM::geological_model_problems(output);
    const std::vector<double> bound = volume_change_bounds(input, output);
    // the worst region against its bound
    double worst_bound = 0.;
    for(std::size_t i = 1; i < r.input_volumes.size(); ++i)
      if(std::abs(r.relative_volume_change(i)) >= r.max_relative_volume_error * (1. - 1e-12))
        worst_bound = bound[i] / std::abs(r.input_volumes[i]);
    std::ostringstream row;
    row << std::setprecision(3);
    row << "| " << std::filesystem::path(file).filename().string() << " | " << input.number_of_triangles() << " -> "
        << r.number_of_triangles << " | " << r.input_min_angle << " -> " << r.min_angle << " | "
        << r.number_of_small_angle_triangles << " (" << r.number_of_forced_small_angle_triangles << ") | "
        << 100. * r.share_of_edges_within_size << " % | " << r.max_relative_volume_error << " (" << worst_bound
        << ") | " << r.max_triangle_distance << ", " << 100. * r.share_of_triangles_beyond_distance << " % beyond "
        << r.surface_distance << " | " << r.max_curve_distance << " | " << (problems.empty() ? "yes" : "NO") << " | " << r.time << " |";
    std::cout << row.str() << std::endl;
    if(show_details)
    {
      std::cout << "    diagonal " << diagonal(input) << ", " << r.number_of_charts << " charts ("
                << r.number_of_chart_cuts << " cuts), curve points " << r.number_of_curve_points
                << " (" << r.number_of_staggered_curve_pieces << " curve pieces staggered across strips), "
                << r.number_of_collapsed_points << " crowded points collapsed, " << r.number_of_slid_curve_points
                << " curve points slid, " << r.number_of_split_curve_triangles << " triangles between curve points split\n"
                << "    volume error before balancing " << r.volume_error_before_balancing << ", "
                << r.number_of_volume_balancing_steps << " steps, " << r.number_of_volume_balancing_points
                << " points moved, farthest " << r.largest_volume_balancing_move << " sizes, "
                << r.regions_not_balanced.size() << " regions left out, " << r.time_volume_balance << " s, "
                << r.number_of_faceted_patches << " faceted surfaces re-meshed with their creases\n";
      for(const std::string& p : problems) std::cout << "    problem: " << p << "\n";
      details(output, r, *field);
    }
    if(!problems.empty()) status = EXIT_FAILURE;
  }
  std::cout << "(command: bench_remesh_surfaces";
  for(int i = 1; i < argc; ++i) std::cout << " " << argv[i];
  std::cout << ")\n";
  return status;
}
