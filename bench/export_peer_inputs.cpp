// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// export_peer_inputs: writes what the peer meshers need to mesh a geological
// model with its surfaces (TetGen .poly, Gmsh discrete .msh + region shells),
// and counts the input triangles that a peer's mesh keeps whole. A helper of
// bench/compare_peers; not a test.

#include "peer_inputs.h"

#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/IO/read_tet_mesh.h>
#include <CGAL/Bubble_mesh_3/IO/write_quality_report.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace BM = CGAL::Bubble_mesh_3;
namespace BMIO = CGAL::Bubble_mesh_3::IO::internal;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

namespace {

const char* usage =
  "Usage: export_peer_inputs MODEL --out-dir DIR [--name BASE] [--merge-tolerance T]\n"
  "       export_peer_inputs MODEL --kept-whole MESH [--json FILE] [--tolerance T]\n"
  "\n"
  "MODEL is a GOCAD Model3d (.ml), TSurf (.ts) or multi-body OBJ (.obj).\n"
  "\n"
  "First form - writes, for the peer meshers, in DIR (BASE defaults to MODEL's name):\n"
  "  BASE.poly       TetGen PLC: the model's points, one facet per input triangle with\n"
  "                  marker patch index + 1, one region attribute (the region index)\n"
  "                  per region at a seed point strictly inside it (a step from a\n"
  "                  boundary triangle's centroid along its normal, checked with\n"
  "                  CGAL::Side_of_triangle_mesh and an AABB distance query)\n"
  "  BASE.surf.msh   Gmsh 4.1 discrete mesh: one surface entity per patch (tag = patch + 1)\n"
  "  BASE.regions.json  per region: index, name, shells (surface tags, outer shell first),\n"
  "                  surfaces inside the region; patch names; regions without a seed\n"
  "\n"
  "Second form - counts the input triangles that MESH (any format bubble_mesh_3_quality\n"
  "reads) keeps whole: input points are matched to mesh vertices within T times the\n"
  "bounding-box diagonal (default 1e-9), then each triangle is looked up among the\n"
  "tetrahedra's faces. Prints, and with --json writes, the counts.\n"
  "\n"
  "Exit status: 0 on success, 1 on an unreadable model or mesh (or a region without a\n"
  "seed point), 2 on bad usage.\n";

int usage_error(const std::string& what)
{
  std::cerr << "export_peer_inputs: " << what << "\n(see export_peer_inputs --help)\n";
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  std::string model_file, out_dir, name, kept_mesh, json;
  double merge_tolerance = 0., tolerance = 1e-9;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if(i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    auto number = [&](double& out) {
      std::string s;
      if(!value(s)) return false;
      char* end = nullptr;
      out = std::strtod(s.c_str(), &end);
      return end != s.c_str() && *end == '\0' && out >= 0.;
    };
    if(a == "-h" || a == "--help")
    {
      std::cout << usage;
      return EXIT_SUCCESS;
    }
    else if(a == "--out-dir") { if(!value(out_dir)) return usage_error("--out-dir needs a directory"); }
    else if(a == "--name") { if(!value(name)) return usage_error("--name needs a base name"); }
    else if(a == "--kept-whole") { if(!value(kept_mesh)) return usage_error("--kept-whole needs a mesh file"); }
    else if(a == "--json") { if(!value(json)) return usage_error("--json needs a file name"); }
    else if(a == "--merge-tolerance")
    {
      if(!number(merge_tolerance)) return usage_error("--merge-tolerance needs a number >= 0");
    }
    else if(a == "--tolerance") { if(!number(tolerance)) return usage_error("--tolerance needs a number >= 0"); }
    else if(a.size() > 1 && a[0] == '-') return usage_error("unknown option '" + a + "'");
    else if(model_file.empty()) model_file = a;
    else return usage_error("more than one model given ('" + model_file + "', '" + a + "')");
  }
  if(model_file.empty()) return usage_error("no model given");
  if(out_dir.empty() == kept_mesh.empty()) return usage_error("give exactly one of --out-dir and --kept-whole");
  if(name.empty()) name = BM::bench::base_name(model_file);

  BM::Geological_model_3<K> model;
  try
  {
    BM::IO::read_geological_model(model_file, model, BM::parameters::merge_tolerance(merge_tolerance));
  }
  catch(const std::exception& e)
  {
    std::cerr << "export_peer_inputs: error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  try
  {
    if(!kept_mesh.empty())
    {
      const BM::Labeled_tetrahedral_mesh_3 mesh = BM::IO::read_tet_mesh(kept_mesh);
      const BM::bench::Kept_whole_count c = BM::bench::count_triangles_kept_whole(model, mesh, tolerance);
      std::cout << kept_mesh << ": " << c.kept_whole << " of " << c.triangles << " input triangles kept whole ("
                << (c.triangles ? 100. * double(c.kept_whole) / double(c.triangles) : 100.) << " %); "
                << c.points_found << " of " << c.points << " input points are mesh vertices\n";
      if(!json.empty())
        BMIO::write_atomically(json, [&](std::ostream& os) {
          os << "{\"mesh\": " << BMIO::json_string(kept_mesh) << ", \"triangles\": " << c.triangles
             << ", \"kept_whole\": " << c.kept_whole << ", \"points\": " << c.points
             << ", \"points_found\": " << c.points_found << "}\n";
        });
      return EXIT_SUCCESS;
    }

    const auto seeds = BM::bench::region_seed_points(model);
    const auto shells = BM::bench::region_shells(model);
    const std::string base = out_dir + "/" + name;
    BMIO::write_atomically(base + ".poly", [&](std::ostream& os) {
      BM::bench::write_tetgen_poly(os, model, seeds);
    });
    BMIO::write_atomically(base + ".surf.msh", [&](std::ostream& os) {
      BM::bench::write_gmsh_discrete_surfaces(os, model);
    });
    std::vector<std::size_t> missing;
    BMIO::write_atomically(base + ".regions.json", [&](std::ostream& os) {
      os << "{\n  \"model\": " << BMIO::json_string(model_file) << ",\n  \"points\": " << model.number_of_points()
         << ",\n  \"triangles\": " << model.number_of_triangles() << ",\n  \"patches\": [";
      for(std::size_t p = 0; p < model.number_of_patches(); ++p)
        os << (p ? ", " : "") << "{\"tag\": " << p + 1 << ", \"name\": " << BMIO::json_string(model.patch(p).name)
           << ", \"positive_region\": " << model.patch(p).positive_region
           << ", \"negative_region\": " << model.patch(p).negative_region << "}";
      os << "],\n  \"regions\": [\n";
      for(std::size_t r = 1; r <= model.number_of_regions(); ++r)
      {
        os << "    {\"index\": " << r << ", \"name\": " << BMIO::json_string(model.region(r).name) << ", \"shells\": [";
        for(std::size_t s = 0; s < shells[r].shells.size(); ++s)
        {
          os << (s ? ", " : "") << "[";
          for(std::size_t k = 0; k < shells[r].shells[s].size(); ++k) os << (k ? ", " : "") << shells[r].shells[s][k];
          os << "]";
        }
        os << "], \"inside\": [";
        for(std::size_t k = 0; k < shells[r].inside.size(); ++k) os << (k ? ", " : "") << shells[r].inside[k];
        os << "], \"seed\": ";
        if(seeds[r].found)
          os << std::setprecision(17) << "[" << CGAL::to_double(seeds[r].point.x()) << ", "
             << CGAL::to_double(seeds[r].point.y()) << ", " << CGAL::to_double(seeds[r].point.z()) << "]";
        else
        {
          os << "null";
          missing.push_back(r);
        }
        os << "}" << (r < model.number_of_regions() ? "," : "") << "\n";
      }
      os << "  ]\n}\n";
    });
    std::cout << "wrote " << base << ".poly, " << base << ".surf.msh, " << base << ".regions.json ("
              << model.number_of_points() << " points, " << model.number_of_triangles() << " triangles, "
              << model.number_of_patches() << " patches, " << model.number_of_regions() << " regions)\n";
    for(std::size_t r : missing)
      std::cerr << "export_peer_inputs: error: no seed point found inside " << model.region_label(r) << "\n";
    return missing.empty() ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  catch(const std::exception& e)
  {
    std::cerr << "export_peer_inputs: error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
