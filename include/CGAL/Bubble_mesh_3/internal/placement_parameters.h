// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_PLACEMENT_PARAMETERS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_PLACEMENT_PARAMETERS_H

// Named parameters of the placement stage (surface bubbles, clustering,
// cluster validity, sizing field, initial interior bubbles). They chain with
// CGAL's own parameters: `parameters::cell_edge_factor(1.2).random_seed(7)`,
// or, to append after a CGAL chain, the two-argument form
// `parameters::cell_edge_factor(1.2, CGAL::parameters::random_seed(7))`.
// CGAL tags reused here: `random_seed` (clustering and silhouette subsample),
// `number_of_iterations` (Lloyd iterations of `K_means_clustering`).

#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/// \ingroup PkgBubbleMesh3Ref
/// How the weight-point rule of the initial radius weighs the nearby surface bubbles.
enum class Radius_weighting
{
  INVERSE_DISTANCE, ///< lambda_j proportional to 1/d_j: the closer, the heavier (METHOD.md, default)
  INVERSE_RADIUS    ///< lambda_j proportional to 1/r_j: the paper's printed formula
};

struct Region_placement_statistics;

/// \ingroup PkgBubbleMesh3Ref
/// default of `place_initial_bubbles()`'s `graded_cell_factor`: initial cells about as large as the
/// spacing of the relaxed bubbles (0 would give the paper's lattice of one cell edge per region)
constexpr double default_graded_cell_factor = 2.5;

namespace internal_np {
enum number_of_clusters_t { number_of_clusters };
enum min_number_of_clusters_t { min_number_of_clusters };
enum max_number_of_clusters_t { max_number_of_clusters };
enum clustering_model_t { clustering_model };
enum convergence_tolerance_t { convergence_tolerance };
enum number_of_restarts_t { number_of_restarts };
enum silhouette_sample_size_t { silhouette_sample_size };
enum surface_radius_factor_t { surface_radius_factor };
enum cell_edge_factor_t { cell_edge_factor };
enum graded_cell_factor_t { graded_cell_factor };
enum surface_clearance_factor_t { surface_clearance_factor };
enum interaction_range_factor_t { interaction_range_factor };
enum radius_weighting_t { radius_weighting };
enum size_gradation_t { size_gradation };
enum area_weighted_radius_floor_t { area_weighted_radius_floor };
enum region_scale_factors_t { region_scale_factors };
enum parallel_regions_t { parallel_regions };
enum placement_statistics_t { placement_statistics };
} // namespace internal_np

namespace parameters {

// CGAL's defaults and reused tags, reachable from this namespace too
using CGAL::parameters::default_values;
using CGAL::parameters::random_seed;
using CGAL::parameters::number_of_iterations;

/// fixed number of clusters per region; 0 (default) chooses it in [min, max]
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_clusters)
/// smallest number of clusters tried (default 2)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, min_number_of_clusters)
/// largest number of clusters tried (default 10)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, max_number_of_clusters)
/// Lloyd stops when no centre moves more than this fraction of the bounding-box diagonal (default 1e-4)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, convergence_tolerance)
/// k-means runs from this many k-means++ seedings and keeps the smallest SSE (default 3)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_restarts)
/// above this many points the silhouette is computed on a seeded subsample of this size (default 2000)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, silhouette_sample_size)
/// surface bubble radius = factor * median incident edge length (default 0.5)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, surface_radius_factor)
/// cell edge = factor * (r_max + r_min) / 2 (default 1)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, cell_edge_factor)
/// g > 0: the initial cells follow the sizing field, a cell's edge within a factor sqrt(2) of g times the radius at its centre; 0: one cell edge per region, the paper's lattice (default `default_graded_cell_factor`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, graded_cell_factor)
/// a candidate must be at least factor * its radius from every surface triangle (default 1)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, surface_clearance_factor)
/// surface bubble j is a weight point when l_ij < factor * (R0 + r_j) (default 1.5)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, interaction_range_factor)
/// weights of the weight-point rule (default `Radius_weighting::INVERSE_DISTANCE`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(Radius_weighting, radius_weighting)
/// the wanted radius grows at most this much per unit of distance from a surface bubble; 0: no bound (default 0.5)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, size_gradation)
/// R0 is at least half the value of the 5 % and 95 % quantiles taken by surface area (each surface bubble weighted by
/// its radius squared) instead of by count (default false; `make_bubble_mesh_3()` sets it on re-meshed surfaces)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, area_weighted_radius_floor)
/// entry r multiplies the wanted radius in region r; missing entries are 1 (default empty)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::vector<double>, region_scale_factors)
/// process regions (and candidates) with TBB when it is linked (default true); the result does not depend on it
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, parallel_regions)
/// where `place_initial_bubbles()` writes one `Region_placement_statistics` per region (default none)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::vector<Region_placement_statistics>*, placement_statistics)

/// the `KMeansClustering` model used by `place_initial_bubbles()` (default `K_means_clustering`)
template <class Clustering>
CGAL::Named_function_parameters<Clustering, internal_np::clustering_model_t>
clustering_model(const Clustering& c)
{
  return CGAL::Named_function_parameters<Clustering, internal_np::clustering_model_t>(c);
}

template <class Clustering, class T, class Tag, class Base>
CGAL::Named_function_parameters<Clustering, internal_np::clustering_model_t,
                                CGAL::Named_function_parameters<T, Tag, Base> >
clustering_model(const Clustering& c, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return CGAL::Named_function_parameters<Clustering, internal_np::clustering_model_t,
                                         CGAL::Named_function_parameters<T, Tag, Base> >(c, np);
}

} // namespace parameters

namespace internal {

// The 5 % and 95 % quantiles of `v` (sorted here; not empty): what the
// placement and the sizing field take for the smallest and largest surface
// radius, since a few vertices of huge triangles (a box's top given as two
// triangles) would otherwise set them (bench/README.md, session 6).
inline std::pair<double, double> quantiles_5_95(std::vector<double>& v)
{
  std::sort(v.begin(), v.end());
  const std::size_t q = (v.size() - 1) / 20;
  return std::make_pair(v[q], v[v.size() - 1 - q]);
}

// The same quantiles of radii weighted by the area each covers (r^2): the
// smallest radius at which the radii up to it cover 5 % (95 %) of the sum. A
// patch refined to a tenth of the size has a hundred times as many bubbles
// per area, and by count would make the largest radii look like outliers.
inline std::pair<double, double> area_weighted_quantiles_5_95(std::vector<double>& v)
{
  std::sort(v.begin(), v.end());
  double total = 0.;
  for(double r : v) total += r * r;
  std::pair<double, double> q(v.back(), v.back());
  double covered = 0.;
  bool low = false;
  for(double r : v)
  {
    covered += r * r;
    if(!low && covered >= 0.05 * total) { q.first = r; low = true; }
    if(covered >= 0.95 * total) { q.second = r; break; }
  }
  return q;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_PLACEMENT_PARAMETERS_H
