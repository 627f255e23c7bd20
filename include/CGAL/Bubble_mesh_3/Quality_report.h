// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_QUALITY_REPORT_H
#define CGAL_BUBBLE_MESH_3_QUALITY_REPORT_H

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

A relative-frequency histogram with fixed bins `[lower_edges[i], upper_edges[i])`;
the last bin is closed (angles) or open-ended (aspect ratio, upper edge `+infinity`).

A value is binned after adding `binning_tolerance` to it, so that angles that
are exact in theory (60 degrees in an equilateral face, 90 in a right corner)
land in the bin they start, whatever the rounding of `acos`.
*/
struct Quality_histogram
{
  std::vector<double> lower_edges;     ///< lower edge of each bin
  std::vector<double> upper_edges;     ///< upper edge of each bin (`+infinity` for an overflow bin)
  std::vector<std::size_t> counts;     ///< values in each bin
  std::vector<double> frequencies;     ///< `counts[i] / total` (all 0 when `total == 0`)
  std::size_t total = 0;               ///< number of values

  /// 1e-9 (in the unit of the values)
  static constexpr double binning_tolerance = 1e-9;

  /// `n` bins of width `w` from `first`; with `overflow`, one more bin `[first + n w, +infinity)`
  static Quality_histogram uniform(double first, double w, std::size_t n, bool overflow)
  {
    Quality_histogram h;
    for(std::size_t i = 0; i < n; ++i)
    {
      h.lower_edges.push_back(first + double(i) * w);
      h.upper_edges.push_back(first + double(i + 1) * w);
    }
    if(overflow)
    {
      h.lower_edges.push_back(first + double(n) * w);
      h.upper_edges.push_back(std::numeric_limits<double>::infinity());
    }
    h.counts.assign(h.lower_edges.size(), 0);
    h.frequencies.assign(h.lower_edges.size(), 0.);
    return h;
  }

  /// the paper's angle bins: 18 bins of 10 degrees over [0, 180]
  static Quality_histogram angle_bins() { return uniform(0., 10., 18, false); }

  /// aspect-ratio bins: 18 bins of 0.5 over [1, 10), then [10, +infinity).
  /// Width 0.5 separates the paper's peaks (1.5-2 for bubbles, 3-4 for TetGen);
  /// the minimum possible value, sqrt(3/2) = 1.2247, falls in the first bin;
  /// the last bin is the share above 10 that the paper says should stay under 10 %.
  static Quality_histogram aspect_ratio_bins() { return uniform(1., 0.5, 18, true); }

  /// adds one value; below the first edge counts in the first bin, above the
  /// last (or NaN) in the last
  void add(double v)
  {
    const std::size_t n = counts.size();
    std::size_t i = n - 1;
    if(!std::isnan(v))
    {
      const double x = v + binning_tolerance;
      if(x < upper_edges[0]) i = 0;
      else
      {
        const double w = upper_edges[0] - lower_edges[0];
        const double k = std::floor((x - lower_edges[0]) / w);
        if(k < double(n - 1)) i = std::size_t(k);
      }
    }
    ++counts[i];
    ++total;
  }

  /// adds the counts of another histogram with the same bins
  void merge(const Quality_histogram& other)
  {
    for(std::size_t i = 0; i < counts.size(); ++i) counts[i] += other.counts[i];
    total += other.total;
  }

  /// computes `frequencies` from `counts`
  void normalize()
  {
    for(std::size_t i = 0; i < counts.size(); ++i)
      frequencies[i] = total == 0 ? 0. : double(counts[i]) / double(total);
  }
};

/*!
\ingroup PkgBubbleMesh3Ref

Quality of the tetrahedra of one region, or of the whole mesh (`region` is then
`all_regions`). Angles are in degrees. A value that has no meaning for an empty
set (minimum of nothing) is NaN; the JSON writer prints it as `null`.
*/
struct Region_quality
{
  /// the region label of the merged model
  static constexpr int all_regions = (std::numeric_limits<int>::min)();
  /// thresholds of the smallest-dihedral shares, degrees
  static constexpr std::array<double, 4> dihedral_thresholds = {{5., 10., 15., 20.}};

  int region = all_regions;                     ///< region label, or `all_regions`
  std::string name;                             ///< region name when the input gives one
  std::size_t number_of_tetrahedra = 0;         ///< tets in the region
  std::size_t number_of_vertices = 0;           ///< distinct vertices of these tets
  double volume = 0.;                           ///< sum of the tets' absolute volumes
  std::size_t number_of_degenerate_tetrahedra = 0;        ///< tets of volume 0
  std::size_t number_of_negatively_oriented_tetrahedra = 0; ///< `CGAL::orientation(p,q,r,s) == NEGATIVE`

  double min_dihedral_angle = std::nan("");     ///< smallest of all dihedral angles
  double max_dihedral_angle = std::nan("");     ///< largest of all dihedral angles
  double mean_dihedral_angle = std::nan("");    ///< mean of the 6 n dihedral angles
  double mean_smallest_dihedral_angle = std::nan(""); ///< mean over tets of each tet's smallest dihedral
  /// share of tets whose smallest dihedral angle is under 5, 10, 15, 20 degrees
  std::array<double, 4> share_smallest_dihedral_under = {{0., 0., 0., 0.}};
  /// share of tets with a dihedral angle under 10 degrees that touch no surface
  /// triangle (share an edge with none) whose surface angle is under 10 degrees:
  /// the small dihedrals the input does not explain. NaN when the mesh has no
  /// boundary triangles (nothing known about the surfaces).
  double share_under_10_not_at_small_surface_angle = std::nan("");
  /// share of tets counted by `share_under_10_not_at_small_surface_angle`
  /// that have a vertex on a sharp contact of their region: a boundary edge
  /// where the region's angle between the surfaces (the sum of its tets'
  /// dihedral angles there, between two boundary triangles) is under 10
  /// degrees, as at a pinch-out or a layer cut by a surface at a low angle,
  /// or that lie inside such a contact's wedge (the nearest one) where it is
  /// thinner than their longest edge: within L / theta of the contact line
  /// for a wedge of theta radians. Every tet with a vertex there is thin
  /// whatever the mesher does, and one of size L fits across the wedge
  /// nowhere nearer than L / theta. NaN as above.
  double share_under_10_at_sharp_contact = std::nan("");
  /// share of tets counted by `share_under_10_not_at_small_surface_angle`
  /// that also have no vertex on a surface triangle whose surface angle is
  /// under 10 degrees: the small dihedrals nothing in the input touches, even
  /// at a point. Near a needle triangle (kept input surfaces) the tets around
  /// its vertices are crowded by its short edge without sharing an edge with
  /// it; this share leaves those out. NaN as above.
  double share_under_10_not_touching_small_surface_angle = std::nan("");

  double min_face_angle = std::nan("");         ///< smallest of the 12 n face angles
  double max_face_angle = std::nan("");         ///< largest of the 12 n face angles

  double min_aspect_ratio = std::nan("");       ///< best tet (sqrt(3/2) at best)
  double median_aspect_ratio = std::nan("");    ///< median (mean of the two middle values for even n)
  double max_aspect_ratio = std::nan("");       ///< worst tet (`+infinity` for a flat tet)
  double share_aspect_ratio_above_10 = 0.;      ///< share of tets with aspect ratio > 10
  double share_aspect_ratio_above_40 = 0.;      ///< share of tets with aspect ratio > 40

  Quality_histogram aspect_ratio_histogram = Quality_histogram::aspect_ratio_bins(); ///< one value per tet
  Quality_histogram face_angle_histogram = Quality_histogram::angle_bins();         ///< 12 values per tet
  Quality_histogram dihedral_angle_histogram = Quality_histogram::angle_bins();     ///< 6 values per tet
};

/*!
\ingroup PkgBubbleMesh3Ref

One of the worst tetrahedra (smallest dihedral angle first), with where it is
and what surface it touches, so that a user can tell a bad tet the input forces
(it sits against a surface triangle with a small angle) from one the mesher placed badly.
*/
struct Worst_tetrahedron
{
  std::size_t index = 0;                        ///< position in the input tet list
  int region = 0;                               ///< its region
  std::array<std::size_t, 4> vertices = {{0, 0, 0, 0}}; ///< 0-based point indices
  std::array<double, 3> centroid = {{0., 0., 0.}};      ///< where it is
  double min_dihedral_angle = 0.;               ///< degrees
  double max_dihedral_angle = 0.;               ///< degrees
  double aspect_ratio = 0.;                     ///< longest edge / shortest altitude
  double volume = 0.;                           ///< absolute volume
  int boundary_faces = 0;                       ///< its faces that are boundary triangles
  /// smallest surface angle over the boundary triangles that share at least an
  /// edge with it (see `Mesh_quality_report::surface_angle_source`); NaN if it touches none
  double touching_surface_min_angle = std::nan("");
  /// smallest angle of its region between the surfaces at a boundary edge
  /// through one of its vertices (see `Region_quality::share_under_10_at_sharp_contact`);
  /// NaN if no vertex is on a boundary edge
  double contact_min_angle = std::nan("");
  std::vector<int> touching_patches;            ///< patches of those triangles, sorted, distinct
};

/*!
\ingroup PkgBubbleMesh3Ref

The quality report of a labelled tetrahedral mesh, built by `compute_mesh_quality()`.

The aspect ratio is the longest edge over the shortest altitude: a regular
tetrahedron gives sqrt(3/2) = 1.2247, the best possible value. The paper's
"0.81 for an ideal element" is the reciprocal normalisation (shortest altitude
over longest edge, sqrt(2/3) = 0.8165); this report never prints that one.
*/
struct Mesh_quality_report
{
  std::string name;                             ///< mesh name (file name in the program)
  std::size_t number_of_points = 0;             ///< points of the input, used by tets or not
  std::size_t number_of_boundary_triangles = 0; ///< boundary triangles given with the mesh
  /// what "surface angle" means in this report: `"input triangles"` (given per
  /// boundary triangle: the smallest angle of the input triangle it lies on),
  /// `"boundary facets"` (none given: each boundary triangle's own smallest angle)
  /// or `"none"` (no boundary triangles); the named parameter `surface_angle_source`
  /// of `compute_mesh_quality()` names other angles (the program passes `"boundary facets,
  /// or the input corner forcing them"` on re-meshed surfaces, `Corner_forced_facet_angle`)
  std::string surface_angle_source = "none";
  std::optional<std::size_t> number_of_steiner_points;            ///< passed through when known
  std::optional<std::size_t> number_of_input_triangles;           ///< passed through when known
  std::optional<std::size_t> number_of_input_triangles_kept_whole; ///< passed through when known

  Region_quality all;                           ///< the merged model
  std::vector<Region_quality> regions;          ///< one per region label, increasing labels
  std::vector<Worst_tetrahedron> worst_tetrahedra; ///< smallest dihedral first
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_QUALITY_REPORT_H
