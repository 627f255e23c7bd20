// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Clusters the surface points of every region of a geological model with
// k-means, k chosen in [k_min, k_max] by the validity indices, prints the
// per-k SSE / Calinski-Harabasz / silhouette table of each region and writes
// the points coloured by cluster as an ASCII PLY file (properties: region,
// cluster).
//
// Usage: cluster_surface_points [model.ml|.ts|.obj] [out.ply] [k_min] [k_max] [seed]
// Without a model, the package's default layered model is generated.

#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/K_means_clustering.h>
#include <CGAL/Bubble_mesh_3/cluster_validity.h>
#include <CGAL/Bubble_mesh_3/make_layered_model.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>

#include <array>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace BM = CGAL::Bubble_mesh_3;

struct Coloured_point
{
  std::array<double, 3> p;
  std::size_t region, cluster;
};

// a colour per (region, cluster) that neighbouring indices do not share
static std::array<int, 3> colour(std::size_t region, std::size_t cluster)
{
  const std::size_t i = 7 * region + 3 * cluster;
  return {{int((i * 97) % 200 + 55), int((i * 57 + 80) % 200 + 55), int((i * 151 + 160) % 200 + 55)}};
}

int main(int argc, char** argv)
{
  try
  {
    BM::Geological_model_3<K> model;
    if(argc > 1) BM::IO::read_geological_model(argv[1], model);
    else BM::make_layered_model(model);
    const std::string out = argc > 2 ? argv[2] : "surface_clusters.ply";
    const std::size_t k_min = argc > 3 ? std::stoul(argv[3]) : 2;
    const std::size_t k_max = argc > 4 ? std::stoul(argv[4]) : 10;
    const unsigned int seed = argc > 5 ? unsigned(std::stoul(argv[5])) : 0u;

    const BM::K_means_clustering kmeans(CGAL::parameters::random_seed(seed));
    std::vector<Coloured_point> coloured;
    for(std::size_t r = 1; r <= model.number_of_regions(); ++r)
    {
      std::vector<std::array<double, 3> > pts;
      for(std::size_t v : BM::region_surface_points(model, r))
      {
        const K::Point_3& p = model.point(v);
        pts.push_back({{p.x(), p.y(), p.z()}});
      }
      if(pts.empty()) continue;
      CGAL::Real_timer timer;
      timer.start();
      const BM::Number_of_clusters_selection sel =
        BM::select_number_of_clusters(pts, k_min, k_max, kmeans, CGAL::parameters::random_seed(seed));
      std::cout << model.region_label(r) << ": " << pts.size() << " surface points, " << timer.time() << " s\n"
                << "   k           SSE            CH  silhouette\n";
      for(const BM::Cluster_validity& row : sel.table)
        std::cout << std::setw(4) << row.number_of_clusters << std::scientific << std::setprecision(5)
                  << std::setw(14) << row.sum_of_squared_errors << std::setw(14) << row.calinski_harabasz
                  << std::fixed << std::setprecision(4) << std::setw(12) << row.silhouette << "\n";
      std::cout << "  largest CH at k = " << sel.calinski_harabasz_choice << ", largest silhouette at k = "
                << sel.silhouette_choice << ", SSE elbow at k = " << sel.elbow_choice << " -> k = "
                << sel.number_of_clusters << "\n";
      for(std::size_t i = 0; i < pts.size(); ++i) coloured.push_back({pts[i], r, sel.labels[i]});
    }

    std::ofstream os(out);
    os << std::setprecision(17);
    os << "ply\nformat ascii 1.0\ncomment surface points of " << (argc > 1 ? argv[1] : "the default model")
       << " by region and k-means cluster\nelement vertex " << coloured.size()
       << "\nproperty double x\nproperty double y\nproperty double z\n"
          "property uchar red\nproperty uchar green\nproperty uchar blue\n"
          "property int region\nproperty int cluster\nend_header\n";
    for(const Coloured_point& c : coloured)
    {
      const std::array<int, 3> rgb = colour(c.region, c.cluster);
      os << c.p[0] << ' ' << c.p[1] << ' ' << c.p[2] << ' ' << rgb[0] << ' ' << rgb[1] << ' ' << rgb[2] << ' '
         << c.region << ' ' << c.cluster << '\n';
    }
    if(!os) throw std::runtime_error("cannot write " + out);
    std::cout << "wrote " << coloured.size() << " points to " << out << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "cluster_surface_points: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
