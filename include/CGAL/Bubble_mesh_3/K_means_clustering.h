// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_K_MEANS_CLUSTERING_H
#define CGAL_BUBBLE_MESH_3_K_MEANS_CLUSTERING_H

#include <CGAL/Bubble_mesh_3/internal/placement_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Random.h>
#include <CGAL/assertions.h>

#include <Eigen/Core>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

The default model of `KMeansClustering`: k-means++ seeding followed by Lloyd
iterations, on Eigen matrices.

- The points are shifted to their centroid first, so that real coordinates
  (millions of metres) lose no digits in the squared distances.
- k-means++: the first centre is a uniformly drawn point, each next centre a
  point drawn with probability proportional to its squared distance to the
  nearest centre already chosen.
- Lloyd: assign every point to its nearest centre (ties go to the lowest
  index), move every centre to the mean of its points; a centre left with no
  point jumps to the point farthest from its own centre. Stop when no centre
  moves more than `tolerance` times the bounding-box diagonal, when no label
  changes, or after `max_iterations` iterations.
- The whole is run from `number_of_restarts` seedings, drawn one after the
  other from one `CGAL::Random(seed)`, and the labelling with the smallest
  sum of squared errors is kept (the first one on ties).

The result depends only on the points, `k` and the parameters: the
assignment step may run in parallel (TBB), but every label is computed on its
own and all sums are taken in point order.

Cost: O(restarts x iterations x n x k) time, O(n + k) memory.

\cgalModels `KMeansClustering`
*/
class K_means_clustering
{
public:
  /// point type of the clustered coordinates
  typedef std::array<double, 3> Point;

  /*!
  \cgalNamedParamsBegin
    \cgalParamNBegin{random_seed}
      \cgalParamDescription{seed of the k-means++ draws}
      \cgalParamType{unsigned int}
      \cgalParamDefault{0}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{largest number of Lloyd iterations per run}
      \cgalParamType{std::size_t}
      \cgalParamDefault{100}
    \cgalParamNEnd
    \cgalParamNBegin{convergence_tolerance}
      \cgalParamDescription{a run stops when no centre moves more than this fraction of the bounding-box diagonal}
      \cgalParamType{double}
      \cgalParamDefault{1e-4}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_restarts}
      \cgalParamDescription{number of seedings tried; the smallest SSE wins}
      \cgalParamType{std::size_t}
      \cgalParamDefault{3}
    \cgalParamNEnd
  \cgalNamedParamsEnd
  */
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit K_means_clustering(const NamedParameters& np = CGAL::parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    seed_ = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
    max_iterations_ = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                       std::size_t(100));
    tolerance_ = choose_parameter(get_parameter(np, internal_np::convergence_tolerance), 1e-4);
    restarts_ = (std::max)(std::size_t(1),
                           choose_parameter(get_parameter(np, internal_np::number_of_restarts),
                                            std::size_t(3)));
  }

  /// seed of the random initialisation
  unsigned int seed() const { return seed_; }
  /// most Lloyd iterations per run
  std::size_t max_iterations() const { return max_iterations_; }
  /// convergence tolerance of the centre moves
  double tolerance() const { return tolerance_; }
  /// runs from different seeds, the best one kept
  std::size_t number_of_restarts() const { return restarts_; }

  /*!
  Clusters `points` into `min(k, points.size())` clusters. On return,
  `labels[i]` is the cluster of `points[i]` and `centres[c]` the mean of the
  points of cluster `c`. A cluster is empty only when the points have fewer
  than `k` distinct positions.
  \pre `k >= 1`
  */
  void operator()(const std::vector<Point>& points, std::size_t k,
                  std::vector<std::size_t>& labels, std::vector<Point>& centres) const
  {
    CGAL_precondition(k >= 1);
    const std::size_t n = points.size();
    labels.assign(n, 0);
    centres.clear();
    if(n == 0) return;
    k = (std::min)(k, n);

    // centred copy: digits are kept for far-away coordinates
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for(const Point& p : points) mean += Eigen::Vector3d(p[0], p[1], p[2]);
    mean /= double(n);
    Eigen::Matrix3Xd X(3, n);
    Eigen::Vector3d lo = Eigen::Vector3d::Constant((std::numeric_limits<double>::max)());
    Eigen::Vector3d hi = -lo;
    for(std::size_t i = 0; i < n; ++i)
    {
      X.col(i) = Eigen::Vector3d(points[i][0], points[i][1], points[i][2]) - mean;
      lo = lo.cwiseMin(X.col(i));
      hi = hi.cwiseMax(X.col(i));
    }
    const double shift_bound = tolerance_ * (hi - lo).norm();

    CGAL::Random rng(seed_);
    double best_sse = (std::numeric_limits<double>::max)();
    Eigen::Matrix3Xd best_centres;
    std::vector<std::size_t> run_labels(n);
    for(std::size_t run = 0; run < restarts_; ++run)
    {
      Eigen::Matrix3Xd C = seed_centres(X, k, rng);
      const double sse = lloyd(X, C, run_labels, shift_bound);
      if(sse < best_sse)
      {
        best_sse = sse;
        best_centres = C;
        labels = run_labels;
      }
    }

    centres.resize(k);
    for(std::size_t c = 0; c < k; ++c)
    {
      const Eigen::Vector3d q = best_centres.col(c) + mean;
      centres[c] = Point{{q[0], q[1], q[2]}};
    }
  }

private:
  // k-means++ (D^2 sampling)
  static Eigen::Matrix3Xd seed_centres(const Eigen::Matrix3Xd& X, std::size_t k, CGAL::Random& rng)
  {
    const std::size_t n = std::size_t(X.cols());
    Eigen::Matrix3Xd C(3, k);
    C.col(0) = X.col(rng.get_int(0, int(n)));
    std::vector<double> d2(n);
    for(std::size_t i = 0; i < n; ++i) d2[i] = (X.col(i) - C.col(0)).squaredNorm();
    for(std::size_t c = 1; c < k; ++c)
    {
      double total = 0.;
      for(double d : d2) total += d;
      std::size_t pick = 0;
      if(total > 0.)
      {
        const double u = rng.get_double(0., total);
        double acc = 0.;
        pick = n - 1;
        for(std::size_t i = 0; i < n; ++i)
        {
          acc += d2[i];
          if(acc > u && d2[i] > 0.) { pick = i; break; }
        }
      }
      else
        pick = std::size_t(rng.get_int(0, int(n))); // all points coincide with centres
      C.col(c) = X.col(pick);
      for(std::size_t i = 0; i < n; ++i)
        d2[i] = (std::min)(d2[i], (X.col(i) - C.col(c)).squaredNorm());
    }
    return C;
  }

  static std::size_t nearest(const Eigen::Matrix3Xd& C, const Eigen::Vector3d& x)
  {
    std::size_t best = 0;
    double best_d = (C.col(0) - x).squaredNorm();
    for(Eigen::Index c = 1; c < C.cols(); ++c)
    {
      const double d = (C.col(c) - x).squaredNorm();
      if(d < best_d) { best_d = d; best = std::size_t(c); }
    }
    return best;
  }

  // assigns every point to its nearest centre; returns whether a label changed
  static bool assign(const Eigen::Matrix3Xd& X, const Eigen::Matrix3Xd& C, std::vector<std::size_t>& labels)
  {
    const std::size_t n = std::size_t(X.cols());
    std::vector<char> changed_flag(n, 0);
    auto work = [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i)
      {
        const std::size_t l = nearest(C, X.col(i));
        if(l != labels[i]) { labels[i] = l; changed_flag[i] = 1; }
      }
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(n > 20000)
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                        [&](const tbb::blocked_range<std::size_t>& r) { work(r.begin(), r.end()); });
    else
#endif
      work(0, n);
    return std::find(changed_flag.begin(), changed_flag.end(), char(1)) != changed_flag.end();
  }

  // per-cluster coordinate sums and sizes, in point order
  static void sums(const Eigen::Matrix3Xd& X, const std::vector<std::size_t>& labels, std::size_t k,
                   Eigen::Matrix3Xd& sum, std::vector<std::size_t>& count)
  {
    sum = Eigen::Matrix3Xd::Zero(3, Eigen::Index(k));
    count.assign(k, 0);
    for(std::size_t i = 0; i < labels.size(); ++i)
    {
      sum.col(Eigen::Index(labels[i])) += X.col(Eigen::Index(i));
      ++count[labels[i]];
    }
  }

  // Lloyd iterations from the centres in C; returns the SSE of the final labels
  double lloyd(const Eigen::Matrix3Xd& X, Eigen::Matrix3Xd& C, std::vector<std::size_t>& labels,
               double shift_bound) const
  {
    const std::size_t n = std::size_t(X.cols());
    const std::size_t k = std::size_t(C.cols());
    std::fill(labels.begin(), labels.end(), std::size_t(-1));
    assign(X, C, labels);
    Eigen::Matrix3Xd sum;
    std::vector<std::size_t> count;
    for(std::size_t it = 0; it < max_iterations_; ++it)
    {
      sums(X, labels, k, sum, count);
      double max_shift2 = 0.;
      for(std::size_t c = 0; c < k; ++c)
      {
        Eigen::Vector3d q;
        if(count[c] > 0)
          q = sum.col(c) / double(count[c]);
        else
        {
          // an emptied centre restarts at the point worst served by its centre
          std::size_t far = 0;
          double far_d = -1.;
          for(std::size_t i = 0; i < n; ++i)
          {
            const double d = (X.col(i) - C.col(labels[i])).squaredNorm();
            if(d > far_d) { far_d = d; far = i; }
          }
          q = X.col(far);
        }
        max_shift2 = (std::max)(max_shift2, (q - C.col(c)).squaredNorm());
        C.col(c) = q;
      }
      const bool changed = assign(X, C, labels);
      if(!changed || max_shift2 <= shift_bound * shift_bound) break;
    }
    // the centres returned are the means of the final labels
    sums(X, labels, k, sum, count);
    for(std::size_t c = 0; c < k; ++c)
      if(count[c] > 0) C.col(c) = sum.col(c) / double(count[c]);
    double sse = 0.;
    for(std::size_t i = 0; i < n; ++i) sse += (X.col(i) - C.col(labels[i])).squaredNorm();
    return sse;
  }

  unsigned int seed_ = 0;
  std::size_t max_iterations_ = 100;
  double tolerance_ = 1e-4;
  std::size_t restarts_ = 3;
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_K_MEANS_CLUSTERING_H
