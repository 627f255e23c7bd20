// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Clustering of a 100k-point surface-like set for k in [2, 12] (issue 4):
// k-means (k-means++ seeding, Lloyd), SSE, Calinski-Harabasz and the
// subsampled silhouette for each k, then the choice of k. Prints seconds.
//
// Usage: bench_clustering [number_of_points=100000] [k_min=2] [k_max=12] [seed=0]

#include <CGAL/Bubble_mesh_3/K_means_clustering.h>
#include <CGAL/Bubble_mesh_3/cluster_validity.h>

#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Timer.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace BM = CGAL::Bubble_mesh_3;

// Points on the surfaces of a layered block 10 km x 8 km x 3 km: four
// undulating horizons, a dipping fault plane and the four sides, with
// densities proportional to areas (what a region's surface points look like).
static std::vector<std::array<double, 3> > surface_like_points(std::size_t n, unsigned seed)
{
  CGAL::Random rng(seed);
  const double L = 10000, W = 8000, H = 3000;
  const double horizons[4] = {0., 900., 1800., 3000.};
  std::vector<std::array<double, 3> > pts;
  pts.reserve(n);
  while(pts.size() < n)
  {
    const double u = rng.get_double(0, 1), x = rng.get_double(0, L), y = rng.get_double(0, W);
    if(u < 0.6) // horizons
    {
      const double z0 = horizons[rng.get_int(0, 4)];
      pts.push_back({{x, y, z0 + 120. * std::sin(x / 1500.) * std::cos(y / 1100.)}});
    }
    else if(u < 0.7) // fault plane dipping 60 degrees
    {
      const double z = rng.get_double(0, H);
      pts.push_back({{4000. + z / std::tan(M_PI / 3.), y, z}});
    }
    else // sides
    {
      const double z = rng.get_double(0, H);
      switch(rng.get_int(0, 4))
      {
        case 0: pts.push_back({{0., y, z}}); break;
        case 1: pts.push_back({{L, y, z}}); break;
        case 2: pts.push_back({{x, 0., z}}); break;
        default: pts.push_back({{x, W, z}}); break;
      }
    }
  }
  return pts;
}

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 100000;
  const std::size_t k_min = argc > 2 ? std::stoul(argv[2]) : 2;
  const std::size_t k_max = argc > 3 ? std::stoul(argv[3]) : 12;
  const unsigned seed = argc > 4 ? unsigned(std::stoul(argv[4])) : 0u;

  const std::vector<std::array<double, 3> > pts = surface_like_points(n, seed);
  const BM::K_means_clustering km(CGAL::parameters::random_seed(seed));
  std::cout << n << " surface-like points, k in [" << k_min << ", " << k_max << "], "
            << km.number_of_restarts() << " restarts, at most " << km.max_iterations() << " Lloyd iterations\n";

  // per-k cost of each part
  std::cout << "   k   k-means s   SSE+CH s   silhouette s        SSE            CH   silhouette\n";
  CGAL::Real_timer total;
  total.start();
  for(std::size_t k = k_min; k <= k_max; ++k)
  {
    CGAL::Real_timer t;
    t.start();
    std::vector<std::size_t> labels;
    std::vector<std::array<double, 3> > centres;
    km(pts, k, labels, centres);
    const double t_km = t.time();
    const double sse = BM::sum_of_squared_errors(pts, labels);
    const double ch = BM::calinski_harabasz_index(pts, labels);
    const double t_ch = t.time() - t_km;
    const double s = BM::silhouette_coefficient(pts, labels, CGAL::parameters::random_seed(seed));
    const double t_s = t.time() - t_km - t_ch;
    std::cout << std::setw(4) << k << std::setw(12) << std::fixed << std::setprecision(3) << t_km << std::setw(11)
              << t_ch << std::setw(15) << t_s << std::setw(13) << std::scientific << std::setprecision(4) << sse
              << std::setw(14) << ch << std::fixed << std::setw(11) << s << "\n";
  }
  const double t_table = total.time();

  // the selection as the placement runs it
  CGAL::Real_timer t;
  CGAL::Timer cpu; // user time: the machine may be shared
  t.start();
  cpu.start();
  const BM::Number_of_clusters_selection sel = BM::select_number_of_clusters(pts, k_min, k_max, km);
  const double t_select = t.time();
  std::cout << std::setprecision(3) << "table: " << t_table << " s; select_number_of_clusters: " << t_select
            << " s wall, " << cpu.time() << " s CPU (all threads) -> k = " << sel.number_of_clusters << " (CH " << sel.calinski_harabasz_choice << ", silhouette "
            << sel.silhouette_choice << ", elbow " << sel.elbow_choice << ")\n";
  return EXIT_SUCCESS;
}
