// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Plugs a custom model of `KMeansClustering` and a custom model of
// `BubbleSizingField` into the placement: nothing else changes.
//
// - Slab_clustering cuts the points into k slabs of equal count along the
//   longest side of their bounding box: deterministic, no random numbers.
// - Depth_graded_sizing_field wants the default radius times a factor that
//   grows linearly with depth below the model's top, so that the mesh
//   coarsens downwards without touching the surfaces' own sizes.
//
// Usage: custom_clustering_and_sizing [model.ml|.ts|.obj]
// Without a model, the package's default layered model is generated.

#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/Surface_bubble_sizing_field.h>
#include <CGAL/Bubble_mesh_3/cluster_validity.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/make_layered_model.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <numeric>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Bubble<K> Bubble;
namespace BM = CGAL::Bubble_mesh_3;

// a model of KMeansClustering
struct Slab_clustering
{
  void operator()(const std::vector<std::array<double, 3> >& points, std::size_t k,
                  std::vector<std::size_t>& labels, std::vector<std::array<double, 3> >& centres) const
  {
    const std::size_t n = points.size();
    k = (std::min)(k, n);
    labels.assign(n, 0);
    centres.assign(k, std::array<double, 3>{{0., 0., 0.}});
    if(n == 0) return;
    std::array<double, 3> lo = points[0], hi = points[0];
    for(const auto& p : points)
      for(int d = 0; d < 3; ++d) { lo[d] = (std::min)(lo[d], p[d]); hi[d] = (std::max)(hi[d], p[d]); }
    int axis = 0;
    for(int d = 1; d < 3; ++d)
      if(hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return points[a][axis] < points[b][axis]; });
    std::vector<std::size_t> count(k, 0);
    for(std::size_t rank = 0; rank < n; ++rank)
    {
      const std::size_t c = rank * k / n, i = order[rank];
      labels[i] = c;
      ++count[c];
      for(int d = 0; d < 3; ++d) centres[c][d] += points[i][d];
    }
    for(std::size_t c = 0; c < k; ++c)
      for(int d = 0; d < 3; ++d) centres[c][d] /= double(count[c]);
  }
};

// a model of BubbleSizingField, built on the default one
class Depth_graded_sizing_field
{
public:
  typedef K::Point_3 Point_3;

  Depth_graded_sizing_field(const BM::Surface_bubble_sizing_field<K>& base, double top, double depth_for_double)
    : base_(base), top_(top), depth_for_double_(depth_for_double) {}

  double operator()(const Point_3& p, std::size_t region) const
  {
    const double depth = (std::max)(0., top_ - p.z());
    return base_(p, region) * (1. + depth / depth_for_double_);
  }

private:
  BM::Surface_bubble_sizing_field<K> base_;
  double top_, depth_for_double_;
};

int main(int argc, char** argv)
{
  try
  {
    BM::Geological_model_3<K> model;
    if(argc > 1) BM::IO::read_geological_model(argv[1], model);
    else BM::make_layered_model(model);
    const std::vector<Bubble> surface = BM::place_surface_bubbles(model);
    const CGAL::Bbox_3 box = BM::bbox(model);

    // 1. the defaults: k-means, k chosen per region, radii from the surface bubbles
    const std::vector<Bubble> by_default = BM::place_initial_bubbles(model, surface);

    // 2. the custom models, passed to the same function
    const BM::Surface_bubble_sizing_field<K> base(model, surface);
    const Depth_graded_sizing_field graded(base, box.zmax(), box.zmax() - box.zmin());
    std::vector<BM::Region_placement_statistics> stats;
    const std::vector<Bubble> custom = BM::place_initial_bubbles(
      model, surface, graded,
      BM::parameters::clustering_model(Slab_clustering(),
                                       BM::parameters::placement_statistics(&stats)));

    // the validity indices and the choice of k work with any model too
    std::vector<std::array<double, 3> > pts;
    for(std::size_t v : BM::region_surface_points(model, 1))
      pts.push_back({{model.point(v).x(), model.point(v).y(), model.point(v).z()}});
    const BM::Number_of_clusters_selection sel = BM::select_number_of_clusters(pts, 2, 8, Slab_clustering());

    std::cout << "default clustering and sizing: " << by_default.size() << " initial bubbles\n"
              << "slab clustering, depth-graded sizing: " << custom.size() << " initial bubbles\n";
    for(std::size_t r = 1; r < stats.size(); ++r)
      std::cout << "  " << model.region_label(r) << ": k = " << stats[r].number_of_clusters << ", cell edge "
                << stats[r].cell_edge << ", " << stats[r].number_of_bubbles << " bubbles\n";
    std::cout << "slab clustering of region 1's surface points: k = " << sel.number_of_clusters
              << " (CH " << sel.calinski_harabasz_choice << ", silhouette " << sel.silhouette_choice << ")\n";

    // deeper bubbles are larger with the graded field
    double top_r = 0., bottom_r = 0.;
    std::size_t top_n = 0, bottom_n = 0;
    const double mid = 0.5 * (box.zmin() + box.zmax());
    for(const Bubble& b : custom)
      (b.center.z() > mid ? (top_r += b.radius, ++top_n) : (bottom_r += b.radius, ++bottom_n));
    if(top_n > 0 && bottom_n > 0)
      std::cout << "mean radius above mid-height " << top_r / double(top_n) << ", below " << bottom_r / double(bottom_n)
                << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "custom_clustering_and_sizing: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
