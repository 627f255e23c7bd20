// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_CLUSTER_VALIDITY_H
#define CGAL_BUBBLE_MESH_3_CLUSTER_VALIDITY_H

#include <CGAL/Bubble_mesh_3/internal/placement_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Random.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal {

// Means and sizes of the clusters given by `labels` (cluster count = largest label + 1),
// with the points shifted by their centroid so far-away coordinates keep their digits.
struct Cluster_means
{
  std::array<double, 3> origin{{0., 0., 0.}};
  std::vector<std::array<double, 3> > shifted;  // points - origin
  std::vector<std::array<double, 3> > means;    // cluster means - origin
  std::vector<std::size_t> sizes;

  Cluster_means(const std::vector<std::array<double, 3> >& points, const std::vector<std::size_t>& labels)
  {
    CGAL_precondition(points.size() == labels.size());
    const std::size_t n = points.size();
    for(const auto& p : points)
      for(int d = 0; d < 3; ++d) origin[d] += p[d] / double(n);
    shifted.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      for(int d = 0; d < 3; ++d) shifted[i][d] = points[i][d] - origin[d];
    const std::size_t k = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
    means.assign(k, std::array<double, 3>{{0., 0., 0.}});
    sizes.assign(k, 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      for(int d = 0; d < 3; ++d) means[labels[i]][d] += shifted[i][d];
      ++sizes[labels[i]];
    }
    for(std::size_t c = 0; c < k; ++c)
      if(sizes[c] > 0)
        for(int d = 0; d < 3; ++d) means[c][d] /= double(sizes[c]);
  }

  std::size_t number_of_nonempty_clusters() const
  {
    return std::size_t(std::count_if(sizes.begin(), sizes.end(), [](std::size_t s) { return s > 0; }));
  }
};

inline double squared_distance_3(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return x * x + y * y + z * z;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Sum of squared errors (within-cluster sum of squares): the sum over all
points of the squared distance to the mean of their cluster. Smaller is
better; it always decreases with k, so it is read at its elbow.
\pre `labels.size() == points.size()`
*/
inline double sum_of_squared_errors(const std::vector<std::array<double, 3> >& points,
                                    const std::vector<std::size_t>& labels)
{
  const internal::Cluster_means cm(points, labels);
  double w = 0.;
  for(std::size_t i = 0; i < points.size(); ++i)
    w += internal::squared_distance_3(cm.shifted[i], cm.means[labels[i]]);
  return w;
}

/*!
\ingroup PkgBubbleMesh3Ref

Calinski-Harabasz index `(B / (k - 1)) / (W / (n - k))`, where `k` is the
number of non-empty clusters, `B = sum_c n_c |m_c - m|^2` the between-cluster
dispersion, `W` the sum of squared errors. Larger is better. Returns 0 when
`k < 2` or `n <= k`, and infinity when `W == 0 < B`.
\pre `labels.size() == points.size()`
*/
inline double calinski_harabasz_index(const std::vector<std::array<double, 3> >& points,
                                      const std::vector<std::size_t>& labels)
{
  const internal::Cluster_means cm(points, labels);
  const std::size_t n = points.size();
  const std::size_t k = cm.number_of_nonempty_clusters();
  if(k < 2 || n <= k) return 0.;
  double w = 0., b = 0.;
  for(std::size_t i = 0; i < n; ++i)
    w += internal::squared_distance_3(cm.shifted[i], cm.means[labels[i]]);
  const std::array<double, 3> zero{{0., 0., 0.}}; // the overall mean, after the shift
  for(std::size_t c = 0; c < cm.sizes.size(); ++c)
    b += double(cm.sizes[c]) * internal::squared_distance_3(cm.means[c], zero);
  if(w == 0.) return b > 0. ? std::numeric_limits<double>::infinity() : 0.;
  return (b / double(k - 1)) / (w / double(n - k));
}

/*!
\ingroup PkgBubbleMesh3Ref

Mean silhouette coefficient. For a point `i` with `a` the mean distance to
the other points of its cluster and `b` the smallest mean distance to the
points of another cluster, `s(i) = (b - a) / max(a, b)`; `s(i) = 0` for a
point alone in its cluster. The result is the mean of `s(i)`, in [-1, 1],
larger is better; 0 when there are fewer than two non-empty clusters.

Exact (O(n^2)) when `n` is at most `silhouette_sample_size`; otherwise it is
the silhouette of a subsample of exactly `silhouette_sample_size` distinct
points drawn uniformly with `CGAL::Random(random_seed)` (partial
Fisher-Yates shuffle), distances being taken within the subsample only, so
the cost is O(m^2) whatever `n` (about 0.05 s for m = 2000). The estimate's
sampling error shrinks like 1/sqrt(m); test_placement compares it with the
exact value (6000 points, m = 500: they differ by less than 0.03).

\cgalNamedParamsBegin
  \cgalParamNBegin{silhouette_sample_size}
    \cgalParamDescription{largest number of points used}
    \cgalParamType{std::size_t}
    \cgalParamDefault{2000}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{seed of the subsample}
    \cgalParamType{unsigned int}
    \cgalParamDefault{0}
  \cgalParamNEnd
\cgalNamedParamsEnd
\pre `labels.size() == points.size()`
*/
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
double silhouette_coefficient(const std::vector<std::array<double, 3> >& points,
                              const std::vector<std::size_t>& labels,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  CGAL_precondition(points.size() == labels.size());
  const std::size_t m_max = (std::max)(std::size_t(2),
    choose_parameter(get_parameter(np, internal_np::silhouette_sample_size), std::size_t(2000)));
  const unsigned int seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);

  const std::size_t n = points.size();
  std::vector<std::size_t> sample(n);
  std::iota(sample.begin(), sample.end(), std::size_t(0));
  if(n > m_max)
  {
    CGAL::Random rng(seed);
    for(std::size_t i = 0; i < m_max; ++i)
      std::swap(sample[i], sample[i + std::size_t(rng.get_int(0, int(n - i)))]);
    sample.resize(m_max);
    std::sort(sample.begin(), sample.end());
  }
  const std::size_t m = sample.size();
  const std::size_t k = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;

  std::vector<std::size_t> size(k, 0);
  for(std::size_t i : sample) ++size[labels[i]];
  if(std::count_if(size.begin(), size.end(), [](std::size_t s) { return s > 0; }) < 2) return 0.;

  double total = 0.;
  std::vector<double> dist_sum(k);
  for(std::size_t a = 0; a < m; ++a)
  {
    const std::size_t i = sample[a];
    const std::size_t li = labels[i];
    if(size[li] < 2) continue; // s(i) = 0
    std::fill(dist_sum.begin(), dist_sum.end(), 0.);
    for(std::size_t b = 0; b < m; ++b)
      if(b != a)
        dist_sum[labels[sample[b]]] += std::sqrt(internal::squared_distance_3(points[i], points[sample[b]]));
    const double ai = dist_sum[li] / double(size[li] - 1);
    double bi = (std::numeric_limits<double>::max)();
    for(std::size_t c = 0; c < k; ++c)
      if(c != li && size[c] > 0) bi = (std::min)(bi, dist_sum[c] / double(size[c]));
    const double den = (std::max)(ai, bi);
    if(den > 0.) total += (bi - ai) / den;
  }
  return total / double(m);
}

/// \ingroup PkgBubbleMesh3Ref
/// The three validity indices of one clustering.
struct Cluster_validity
{
  /// k
  std::size_t number_of_clusters = 0;
  /// sum of squared distances of the points to their cluster centres (the elbow curve)
  double sum_of_squared_errors = 0.;
  /// Calinski-Harabasz index (larger is better)
  double calinski_harabasz = 0.;
  /// mean silhouette coefficient, in [-1, 1] (larger is better)
  double silhouette = 0.;
};

/*!
\ingroup PkgBubbleMesh3Ref

Result of `select_number_of_clusters()`: the k chosen, why, the per-k table
and the clustering obtained for the chosen k.
*/
struct Number_of_clusters_selection
{
  std::size_t number_of_clusters = 0;        ///< the k chosen
  std::size_t calinski_harabasz_choice = 0;  ///< k of the largest CH
  std::size_t silhouette_choice = 0;         ///< k of the largest silhouette
  std::size_t elbow_choice = 0;              ///< k at the elbow of the SSE curve (0 if fewer than 3 values)
  std::vector<Cluster_validity> table;       ///< one row per k tried, in increasing k
  std::vector<std::size_t> labels;           ///< labels of the chosen clustering
  std::vector<std::array<double, 3> > centres; ///< centres of the chosen clustering
};

namespace internal {

// Elbow of a decreasing SSE curve: the k farthest below the chord joining
// its first and last values, both axes normalised to [0,1]. 0 if undefined.
inline std::size_t sse_elbow(const std::vector<Cluster_validity>& table)
{
  if(table.size() < 3) return 0;
  const double k0 = double(table.front().number_of_clusters), k1 = double(table.back().number_of_clusters);
  double lo = (std::numeric_limits<double>::max)(), hi = -lo;
  for(const Cluster_validity& row : table)
  {
    lo = (std::min)(lo, row.sum_of_squared_errors);
    hi = (std::max)(hi, row.sum_of_squared_errors);
  }
  if(!(hi > lo)) return 0;
  const double y0 = (table.front().sum_of_squared_errors - lo) / (hi - lo);
  const double y1 = (table.back().sum_of_squared_errors - lo) / (hi - lo);
  std::size_t best = 0;
  double best_gap = 0.;
  for(const Cluster_validity& row : table)
  {
    const double x = (double(row.number_of_clusters) - k0) / (k1 - k0);
    const double y = (row.sum_of_squared_errors - lo) / (hi - lo);
    const double gap = (y0 + (y1 - y0) * x) - y;
    if(gap > best_gap) { best_gap = gap; best = row.number_of_clusters; }
  }
  return best;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Clusters `points` with `clustering` for every k in
[`k_min`, `k_max`] (k_max is clamped to the number of points), computes the
three validity indices and chooses k by this rule:

1. k_CH = the k of the largest Calinski-Harabasz index, k_S = the k of the
   largest silhouette (the smallest k on ties).
2. If k_CH == k_S (the paper reports that they agree), that k is chosen.
3. Otherwise the one of the two nearer to the elbow of the SSE curve is
   chosen (elbow: the k lying farthest below the chord from the first to the
   last SSE value, both axes normalised); if both are equally near, or if the
   elbow is undefined (fewer than three k values), k_S is chosen, since the
   silhouette is bounded and does not favour many clusters.

The whole table is returned so that a caller can apply another rule.

\tparam KMeansClustering a model of `KMeansClustering`
\cgalNamedParamsBegin
  \cgalParamNBegin{silhouette_sample_size} \cgalParamDescription{see `silhouette_coefficient()`}
    \cgalParamType{std::size_t} \cgalParamDefault{2000} \cgalParamNEnd
  \cgalParamNBegin{random_seed} \cgalParamDescription{seed of the silhouette subsample}
    \cgalParamType{unsigned int} \cgalParamDefault{0} \cgalParamNEnd
\cgalNamedParamsEnd
\pre `1 <= k_min <= k_max`, `points` not empty
*/
template <class KMeansClustering, class NamedParameters = CGAL::parameters::Default_named_parameters>
Number_of_clusters_selection
select_number_of_clusters(const std::vector<std::array<double, 3> >& points,
                          std::size_t k_min, std::size_t k_max,
                          const KMeansClustering& clustering,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  CGAL_precondition(k_min >= 1 && k_min <= k_max && !points.empty());
  k_max = (std::min)(k_max, points.size());
  k_min = (std::min)(k_min, k_max);

  Number_of_clusters_selection sel;
  std::vector<std::vector<std::size_t> > all_labels;
  std::vector<std::vector<std::array<double, 3> > > all_centres;
  for(std::size_t k = k_min; k <= k_max; ++k)
  {
    std::vector<std::size_t> labels;
    std::vector<std::array<double, 3> > centres;
    clustering(points, k, labels, centres);
    Cluster_validity row;
    row.number_of_clusters = k;
    row.sum_of_squared_errors = sum_of_squared_errors(points, labels);
    row.calinski_harabasz = calinski_harabasz_index(points, labels);
    row.silhouette = silhouette_coefficient(points, labels, np);
    sel.table.push_back(row);
    all_labels.push_back(std::move(labels));
    all_centres.push_back(std::move(centres));
  }

  std::size_t i_ch = 0, i_s = 0;
  for(std::size_t i = 1; i < sel.table.size(); ++i)
  {
    if(sel.table[i].calinski_harabasz > sel.table[i_ch].calinski_harabasz) i_ch = i;
    if(sel.table[i].silhouette > sel.table[i_s].silhouette) i_s = i;
  }
  sel.calinski_harabasz_choice = sel.table[i_ch].number_of_clusters;
  sel.silhouette_choice = sel.table[i_s].number_of_clusters;
  sel.elbow_choice = internal::sse_elbow(sel.table);

  std::size_t chosen = i_s;
  if(i_ch != i_s && sel.elbow_choice != 0)
  {
    const auto gap = [&](std::size_t i) {
      const std::size_t k = sel.table[i].number_of_clusters;
      return k > sel.elbow_choice ? k - sel.elbow_choice : sel.elbow_choice - k;
    };
    if(gap(i_ch) < gap(i_s)) chosen = i_ch;
  }
  sel.number_of_clusters = sel.table[chosen].number_of_clusters;
  sel.labels = std::move(all_labels[chosen]);
  sel.centres = std::move(all_centres[chosen]);
  return sel;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_CLUSTER_VALIDITY_H
