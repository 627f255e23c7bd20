// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

/*!
\ingroup PkgBubbleMesh3Concepts
\cgalConcept

Partitions a set of points into `k` clusters. `place_initial_bubbles()`
clusters each region's surface points with a model of this concept (named
parameter `clustering_model`), and `select_number_of_clusters()` calls it once
per k tried; the bounding box of every cluster is then filled with
candidate bubbles.

Points are plain `std::array<double, 3>`, so that a model needs no kernel.
A model decides how it clusters (k-means, k-medoids, a spatial split...);
the placement only reads the labels. For the placement to be reproducible,
a model must be deterministic: the same points and `k` give the same labels
and centres (draw random numbers from a seed the model holds, not from a
global generator).

A model must be copyable, and its call operator must be safe to call from
several threads at once (regions are clustered in parallel when TBB is
linked).

\cgalHasModel `CGAL::Bubble_mesh_3::K_means_clustering`
*/
class KMeansClustering
{
public:
  /*!
  Clusters `points` into at most `k` clusters.

  On return:
  - `labels.size() == points.size()`, and `labels[i]` is the cluster of
    `points[i]`, in `[0, centres.size())`;
  - `centres.size() == min(k, points.size())`, `centres[c]` being a
    representative point of cluster `c` (the mean for k-means);
  - a cluster may be empty only when the points have fewer than `k`
    distinct positions.

  \pre `k >= 1`
  */
  void operator()(const std::vector<std::array<double, 3> >& points, std::size_t k,
                  std::vector<std::size_t>& labels,
                  std::vector<std::array<double, 3> >& centres) const;
};
