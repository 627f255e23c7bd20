// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_SUMMARY_H
#define CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_SUMMARY_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Bubble_mesh_3/internal/vertex_angle.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal_np {
enum poor_angle_bound_t { poor_angle_bound };
enum sharp_angle_bound_t { sharp_angle_bound };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgBubbleMesh3Ref
/// the input triangle angle (degrees) under which the summary warns
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, poor_angle_bound)
/// \ingroup PkgBubbleMesh3Ref
/// the angle (degrees) of a region between two of its surfaces at an edge, or of a patch
/// between two of its border curves at a point, under which the summary warns
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, sharp_angle_bound)

} // namespace parameters

/*!
\ingroup PkgBubbleMesh3Ref

What a geological model holds, in numbers: the data behind
`write_summary_text()` and `write_summary_json()`. Angles are in degrees,
lengths and volumes in the model's units. A statistic over no element is NaN.
*/
struct Geological_model_summary
{
  /// one region of the model
  struct Region
  {
    /// region index (1 to `number_of_regions`)
    std::size_t index = 0;
    /// region name
    std::string name;
    std::size_t number_of_boundary_triangles = 0; ///< triangles of patches with the region on exactly one side
    std::size_t number_of_inside_triangles = 0;   ///< triangles of surfaces inside the region
    std::size_t number_of_points = 0;             ///< vertices of all these triangles
    double volume = 0.;                           ///< signed volume enclosed by the boundary
    // over the distinct edges and the triangles of the boundary and of the surfaces inside
    /// shortest, median and longest edge
    ///@{
    double min_edge_length = 0., median_edge_length = 0., max_edge_length = 0.;
    ///@}
    /// smallest angle of these triangles (degrees)
    double min_angle = 0.;
    /// the triangle where it occurs
    std::size_t min_angle_triangle = 0;
    /// the region's smallest angle between two of its triangles at an edge (degrees; see
    /// `region_contact_angles()`): under about 10, a pinch-out, a low-angle contact or a fold
    double min_contact_angle = 0.;
    /// the midpoint of that edge
    std::array<double, 3> min_contact_point{{0., 0., 0.}};
    /// the patches of the two triangles there (equal: the surface folds)
    std::pair<std::size_t, std::size_t> min_contact_patches{0, 0};
    /// and their names
    std::pair<std::string, std::string> min_contact_patch_names;
    /// edges where the region's angle is under `sharp_angle_bound`, and their total length
    std::size_t number_of_sharp_contact_edges = 0;
    double sharp_contact_length = 0.; ///< total length of those edges
  };

  /// a patch with the same region on both sides (e.g. a fault ending inside a body)
  struct Surface_inside_region
  {
    /// patch index
    std::size_t patch = 0;
    /// patch name
    std::string name;
    /// the region on both sides
    std::size_t region = 0;
    /// its name
    std::string region_name;
    /// triangles of the patch
    std::size_t number_of_triangles = 0;
  };

  /// a patch whose border curves meet at a small angle (see `patch_corner_angles()`)
  struct Sharp_patch_corner
  {
    /// patch index
    std::size_t patch = 0;
    /// patch name
    std::string name;
    /// the patch's smallest angle at a point of its border (degrees)
    double angle = 0.;
    /// that point
    std::array<double, 3> point{{0., 0., 0.}};
    /// the patch's border points with an angle under `sharp_angle_bound`
    std::size_t number_of_sharp_corners = 0;
    /// each of them: x, y, z and the patch's angle there
    std::vector<std::array<double, 4> > corners;
  };

  /// the file the model was read from
  std::string file_name;
  /// numbers of points, triangles, patches and regions (without the outside)
  ///@{
  std::size_t number_of_points = 0, number_of_triangles = 0, number_of_patches = 0, number_of_regions = 0;
  ///@}
  /// bounding box of the points
  Bbox_3 bbox;
  double volume = 0.; ///< volume enclosed by the outer boundary
  /// shortest, median and longest edge of all triangles
  ///@{
  double min_edge_length = 0., median_edge_length = 0., max_edge_length = 0.;
  ///@}
  double min_angle = 0.;               ///< smallest angle of any triangle
  std::size_t min_angle_triangle = 0;  ///< the triangle where it occurs
  std::size_t min_angle_patch = 0;     ///< and its patch
  /// and its name
  std::string min_angle_patch_name;
  double poor_angle_bound = 1.;            ///< angle under which a triangle counts as poor
  std::size_t number_of_poor_triangles = 0; ///< triangles with an angle under `poor_angle_bound`
  /// a region's angle between surfaces at an edge, or a patch's between border curves
  /// at a point, under which it counts as sharp
  double sharp_angle_bound = 10.;
  std::vector<Region> regions;             ///< regions 1..n, in order
  /// patches with the same region on both sides
  std::vector<Surface_inside_region> surfaces_inside_regions;
  /// the patches with a corner under `sharp_angle_bound`, sharpest first
  std::vector<Sharp_patch_corner> sharp_patch_corners;
};

namespace internal {

struct Length_statistics
{
  double min = std::numeric_limits<double>::quiet_NaN();
  double median = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
};

// min, median (mean of the two middle values for an even count) and max; sorts `v` partly
inline Length_statistics length_statistics(std::vector<double>& v)
{
  Length_statistics s;
  if(v.empty()) return s;
  const std::size_t n = v.size();
  std::nth_element(v.begin(), v.begin() + n / 2, v.end());
  s.median = v[n / 2];
  if(n % 2 == 0) s.median = 0.5 * (s.median + *std::max_element(v.begin(), v.begin() + n / 2));
  s.min = *std::min_element(v.begin(), v.end());
  s.max = *std::max_element(v.begin(), v.end());
  return s;
}

template <class GeomTraits>
Length_statistics edge_length_statistics(const Geological_model_3<GeomTraits>& model,
                                         const std::vector<std::size_t>& triangles)
{
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  edges.reserve(3 * triangles.size());
  for(std::size_t t : triangles)
  {
    const auto& v = model.triangle(t);
    for(int k = 0; k < 3; ++k)
      edges.emplace_back((std::min)(v[k], v[(k + 1) % 3]), (std::max)(v[k], v[(k + 1) % 3]));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> lengths;
  lengths.reserve(edges.size());
  for(const auto& e : edges)
    lengths.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(model.point(e.first), model.point(e.second)))));
  return length_statistics(lengths);
}

inline std::string json_string(const std::string& s)
{
  std::string r = "\"";
  for(unsigned char c : s)
  {
    switch(c)
    {
      case '"': r += "\\\""; break;
      case '\\': r += "\\\\"; break;
      case '\n': r += "\\n"; break;
      case '\r': r += "\\r"; break;
      case '\t': r += "\\t"; break;
      default:
        if(c < 0x20)
        {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", unsigned(c));
          r += buf;
        }
        else
          r += char(c);
    }
  }
  return r + "\"";
}

// JSON has no NaN or infinity: those become null
inline std::string json_number(double x)
{
  if(!std::isfinite(x)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", x);
  return buf;
}

inline std::string format_number(double x, const char* format = "%.4g")
{
  if(!std::isfinite(x)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), format, x);
  return buf;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Computes the summary of `model`: per region its triangle and point counts,
volume, edge lengths, smallest triangle angle and smallest angle between two
of its surfaces at an edge (`region_contact_angles()`); the surfaces inside regions;
the bounding box, totals, and the smallest triangle angle of the whole input
with the triangle where it occurs. The model should have valid indices (see
`validate_geological_model()`); it need not be valid otherwise.

\cgalNamedParamsBegin
  \cgalParamNBegin{poor_angle_bound}
    \cgalParamDescription{triangles with an angle under this bound (degrees) count as poor, and the text summary warns about them}
    \cgalParamType{`double`}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{sharp_angle_bound}
    \cgalParamDescription{edges where a region's angle between two of its surfaces, and border points
      where a patch's angle between two of its border curves, is under this bound (degrees) are sharp,
      and the text summary warns about them}
    \cgalParamType{`double`}
    \cgalParamDefault{10}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
Geological_model_summary summarize_geological_model(const Geological_model_3<GeomTraits>& model,
                                                    const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double nan = std::numeric_limits<double>::quiet_NaN();

  Geological_model_summary s;
  s.poor_angle_bound = choose_parameter(get_parameter(np, Bubble_mesh_3::internal_np::poor_angle_bound), 1.);
  s.sharp_angle_bound = choose_parameter(get_parameter(np, Bubble_mesh_3::internal_np::sharp_angle_bound), 10.);
  s.file_name = model.file_name();
  s.number_of_points = model.number_of_points();
  s.number_of_triangles = model.number_of_triangles();
  s.number_of_patches = model.number_of_patches();
  s.number_of_regions = model.number_of_regions();
  if(model.number_of_points() > 0) s.bbox = bbox(model);
  const std::vector<double> volumes = region_volumes(model);
  s.volume = volumes[0];

  const std::size_t nr = model.number_of_regions();
  std::vector<std::vector<std::size_t> > region_triangles(nr + 1);
  std::vector<std::size_t> boundary_count(nr + 1, 0), inside_count(nr + 1, 0);
  std::vector<std::size_t> inside_patch_count(model.number_of_patches(), 0);
  std::vector<double> angle(model.number_of_triangles());
  s.min_angle = nan;
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& v = model.triangle(t);
    angle[t] = internal::min_angle_degrees(model.point(v[0]), model.point(v[1]), model.point(v[2]));
    const std::size_t p = model.patch_of_triangle(t);
    if(std::isnan(s.min_angle) || angle[t] < s.min_angle)
    {
      s.min_angle = angle[t];
      s.min_angle_triangle = t;
      s.min_angle_patch = p;
    }
    if(angle[t] < s.poor_angle_bound) ++s.number_of_poor_triangles;
    const auto& patch = model.patch(p);
    if(patch.is_inside_region())
    {
      if(patch.positive_region == 0) continue;
      region_triangles[patch.positive_region].push_back(t);
      ++inside_count[patch.positive_region];
      ++inside_patch_count[p];
    }
    else
      for(std::size_t r : {patch.positive_region, patch.negative_region})
        if(r != 0)
        {
          region_triangles[r].push_back(t);
          ++boundary_count[r];
        }
  }
  if(model.number_of_triangles() > 0)
    s.min_angle_patch_name = model.patch(s.min_angle_patch).name;

  std::vector<std::size_t> all(model.number_of_triangles());
  for(std::size_t t = 0; t < all.size(); ++t) all[t] = t;
  const internal::Length_statistics global = internal::edge_length_statistics(model, all);
  s.min_edge_length = global.min;
  s.median_edge_length = global.median;
  s.max_edge_length = global.max;

  const std::vector<Region_contact_angles> contacts = region_contact_angles(model, s.sharp_angle_bound);
  std::vector<bool> used(model.number_of_points(), false);
  for(std::size_t r = 1; r <= nr; ++r)
  {
    Geological_model_summary::Region g;
    g.index = r;
    g.name = model.region(r).name;
    g.number_of_boundary_triangles = boundary_count[r];
    g.number_of_inside_triangles = inside_count[r];
    g.volume = volumes[r];
    g.min_angle = nan;
    std::vector<std::size_t> points;
    for(std::size_t t : region_triangles[r])
    {
      if(std::isnan(g.min_angle) || angle[t] < g.min_angle)
      {
        g.min_angle = angle[t];
        g.min_angle_triangle = t;
      }
      for(std::size_t v : model.triangle(t))
        if(!used[v])
        {
          used[v] = true;
          points.push_back(v);
        }
    }
    for(std::size_t v : points) used[v] = false;
    g.number_of_points = points.size();
    const internal::Length_statistics l = internal::edge_length_statistics(model, region_triangles[r]);
    g.min_edge_length = l.min;
    g.median_edge_length = l.median;
    g.max_edge_length = l.max;
    const Region_contact_angles& c = contacts[r];
    g.min_contact_angle = c.min_angle;
    g.min_contact_point = c.min_angle_point;
    g.min_contact_patches = c.min_angle_patches;
    if(!std::isnan(c.min_angle))
      g.min_contact_patch_names = std::make_pair(model.patch(c.min_angle_patches.first).name,
                                                 model.patch(c.min_angle_patches.second).name);
    g.number_of_sharp_contact_edges = c.number_of_sharp_edges;
    g.sharp_contact_length = c.sharp_edge_length;
    s.regions.push_back(g);
  }

  for(std::size_t p = 0; p < model.number_of_patches(); ++p)
  {
    const auto& patch = model.patch(p);
    if(!patch.is_inside_region() || patch.positive_region == 0) continue;
    Geological_model_summary::Surface_inside_region a;
    a.patch = p;
    a.name = patch.name;
    a.region = patch.positive_region;
    a.region_name = model.region(a.region).name;
    a.number_of_triangles = inside_patch_count[p];
    s.surfaces_inside_regions.push_back(a);
  }

  const std::vector<Patch_corner_angles> corners = patch_corner_angles(model, s.sharp_angle_bound);
  for(std::size_t p = 0; p < corners.size(); ++p)
  {
    if(corners[p].number_of_sharp_corners == 0) continue;
    Geological_model_summary::Sharp_patch_corner c;
    c.patch = p;
    c.name = model.patch(p).name;
    c.angle = corners[p].min_angle;
    c.point = corners[p].min_angle_point;
    c.number_of_sharp_corners = corners[p].number_of_sharp_corners;
    for(const auto& vc : corners[p].sharp_corners)
    {
      const auto& q = model.point(vc.first);
      c.corners.push_back({{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()), vc.second}});
    }
    s.sharp_patch_corners.push_back(c);
  }
  std::stable_sort(s.sharp_patch_corners.begin(), s.sharp_patch_corners.end(),
                   [](const Geological_model_summary::Sharp_patch_corner& a,
                      const Geological_model_summary::Sharp_patch_corner& b) { return a.angle < b.angle; });
  return s;
}

/*!
\ingroup PkgBubbleMesh3Ref

Writes `s` as a compact table for people, with a warning when the input has
triangles with an angle under `s.poor_angle_bound`, one for each region
whose surfaces meet at an edge at less than `s.sharp_angle_bound`, and one
for the patches whose border curves do.
*/
inline std::ostream& write_summary_text(std::ostream& os, const Geological_model_summary& s)
{
  using internal::format_number;
  os << "model " << (s.file_name.empty() ? std::string("(in memory)") : s.file_name) << ": " << s.number_of_regions
     << " regions, " << s.number_of_patches << " patches, " << s.number_of_triangles << " triangles, "
     << s.number_of_points << " points\n";
  if(s.number_of_points > 0)
    os << "  box [" << format_number(s.bbox.xmin(), "%.10g") << ", " << format_number(s.bbox.xmax(), "%.10g")
       << "] x [" << format_number(s.bbox.ymin(), "%.10g") << ", " << format_number(s.bbox.ymax(), "%.10g")
       << "] x [" << format_number(s.bbox.zmin(), "%.10g") << ", " << format_number(s.bbox.zmax(), "%.10g")
       << "], volume " << format_number(s.volume, "%.6g") << "\n";
  os << "  edge length min / median / max " << format_number(s.min_edge_length) << " / "
     << format_number(s.median_edge_length) << " / " << format_number(s.max_edge_length) << ", min angle "
     << format_number(s.min_angle, "%.3g") << " deg";
  if(s.number_of_triangles > 0)
    os << " at triangle " << s.min_angle_triangle << " (patch '" << s.min_angle_patch_name << "')";
  os << "\n";

  std::size_t width = 6;
  for(const auto& r : s.regions) width = (std::max)(width, r.name.size() + 4 + std::to_string(r.index).size());
  char line[512];
  std::snprintf(line, sizeof(line), "  %-*s %9s %8s %8s %12s %10s %10s %10s %9s\n", int(width), "region",
                "triangles", "inside", "points", "volume", "edge min", "median", "max", "min angle");
  os << line;
  for(const auto& r : s.regions)
  {
    const std::string name = std::to_string(r.index) + " '" + r.name + "'";
    std::snprintf(line, sizeof(line), "  %-*s %9zu %8zu %8zu %12s %10s %10s %10s %9s\n", int(width), name.c_str(),
                  r.number_of_boundary_triangles, r.number_of_inside_triangles, r.number_of_points,
                  format_number(r.volume, "%.5g").c_str(), format_number(r.min_edge_length).c_str(),
                  format_number(r.median_edge_length).c_str(), format_number(r.max_edge_length).c_str(),
                  format_number(r.min_angle, "%.3g").c_str());
    os << line;
  }
  if(!s.surfaces_inside_regions.empty())
  {
    os << "  surfaces inside regions:\n";
    for(const auto& a : s.surfaces_inside_regions)
      os << "    patch " << a.patch << " '" << a.name << "' in region " << a.region << " '" << a.region_name
         << "': " << a.number_of_triangles << " triangles\n";
  }
  if(s.number_of_poor_triangles > 0)
    os << "warning: input min angle " << format_number(s.min_angle, "%.3g") << " deg at triangle "
       << s.min_angle_triangle << " (patch '" << s.min_angle_patch_name << "'); " << s.number_of_poor_triangles
       << " triangles have an angle under " << format_number(s.poor_angle_bound, "%g")
       << " deg: tetrahedra at those triangles will be poor; try --remesh-surfaces\n";
  for(const auto& r : s.regions)
  {
    if(r.number_of_sharp_contact_edges == 0) continue;
    const auto& n = r.min_contact_patch_names;
    os << "warning: region " << r.index << " '" << r.name << "': its surfaces meet at "
       << format_number(r.min_contact_angle, "%.3g") << " deg at (" << format_number(r.min_contact_point[0], "%.10g")
       << ", " << format_number(r.min_contact_point[1], "%.10g") << ", " << format_number(r.min_contact_point[2], "%.10g")
       << "), "
       << (r.min_contact_patches.first == r.min_contact_patches.second
             ? "where patch '" + n.first + "' folds back"
             : "between patches '" + n.first + "' and '" + n.second + "'")
       << "; " << r.number_of_sharp_contact_edges << (r.number_of_sharp_contact_edges == 1 ? " edge" : " edges")
       << " (total length "
       << format_number(r.sharp_contact_length, "%.4g") << ") under " << format_number(s.sharp_angle_bound, "%g")
       << " deg, as at a pinch-out: no conforming mesh has good tetrahedra there, and the quality report counts"
          " them apart\n";
  }
  if(!s.sharp_patch_corners.empty())
  {
    std::size_t corners = 0;
    for(const auto& c : s.sharp_patch_corners) corners += c.number_of_sharp_corners;
    os << "warning: " << s.sharp_patch_corners.size() << (s.sharp_patch_corners.size() == 1 ? " patch has " : " patches have ")
       << corners << (corners == 1 ? " corner" : " corners") << " under " << format_number(s.sharp_angle_bound, "%g")
       << " deg, where two of " << (s.sharp_patch_corners.size() == 1 ? "its" : "their")
       << " border curves meet (as where a strip between two cut lines ends): triangles there"
          " are thin unless the strip is meshed at its width (--remesh-surfaces --refine-ribbons); sharpest:";
    for(std::size_t i = 0; i < (std::min)(std::size_t(3), s.sharp_patch_corners.size()); ++i)
    {
      const auto& c = s.sharp_patch_corners[i];
      os << (i == 0 ? " " : ", ") << "patch '" << c.name << "' " << format_number(c.angle, "%.3g") << " deg at ("
         << format_number(c.point[0], "%.10g") << ", " << format_number(c.point[1], "%.10g") << ", "
         << format_number(c.point[2], "%.10g") << ")";
    }
    os << (s.sharp_patch_corners.size() > 3 ? ", ...\n" : "\n");
  }
  return os;
}

/*!
\ingroup PkgBubbleMesh3Ref

Writes `s` as one JSON object (NaN and infinities as `null`).
*/
inline std::ostream& write_summary_json(std::ostream& os, const Geological_model_summary& s)
{
  using internal::json_number;
  using internal::json_string;
  auto lengths = [](double mn, double md, double mx) {
    return "{\"min\": " + json_number(mn) + ", \"median\": " + json_number(md) + ", \"max\": " + json_number(mx) + "}";
  };
  os << "{\n  \"file\": " << json_string(s.file_name) << ",\n"
     << "  \"number_of_regions\": " << s.number_of_regions << ",\n"
     << "  \"number_of_patches\": " << s.number_of_patches << ",\n"
     << "  \"number_of_triangles\": " << s.number_of_triangles << ",\n"
     << "  \"number_of_points\": " << s.number_of_points << ",\n";
  if(s.number_of_points > 0)
    os << "  \"bbox\": {\"xmin\": " << json_number(s.bbox.xmin()) << ", \"ymin\": " << json_number(s.bbox.ymin())
       << ", \"zmin\": " << json_number(s.bbox.zmin()) << ", \"xmax\": " << json_number(s.bbox.xmax())
       << ", \"ymax\": " << json_number(s.bbox.ymax()) << ", \"zmax\": " << json_number(s.bbox.zmax()) << "},\n";
  else
    os << "  \"bbox\": null,\n";
  os << "  \"volume\": " << json_number(s.volume) << ",\n"
     << "  \"edge_length\": " << lengths(s.min_edge_length, s.median_edge_length, s.max_edge_length) << ",\n"
     << "  \"min_angle\": {\"degrees\": " << json_number(s.min_angle) << ", \"triangle\": " << s.min_angle_triangle
     << ", \"patch\": " << s.min_angle_patch << ", \"patch_name\": " << json_string(s.min_angle_patch_name) << "},\n"
     << "  \"poor_angle_bound\": " << json_number(s.poor_angle_bound) << ",\n"
     << "  \"number_of_poor_triangles\": " << s.number_of_poor_triangles << ",\n"
     << "  \"sharp_angle_bound\": " << json_number(s.sharp_angle_bound) << ",\n"
     << "  \"regions\": [";
  for(std::size_t i = 0; i < s.regions.size(); ++i)
  {
    const auto& r = s.regions[i];
    os << (i == 0 ? "\n" : ",\n") << "    {\"index\": " << r.index << ", \"name\": " << json_string(r.name)
       << ", \"number_of_boundary_triangles\": " << r.number_of_boundary_triangles
       << ", \"number_of_inside_triangles\": " << r.number_of_inside_triangles
       << ", \"number_of_points\": " << r.number_of_points << ", \"volume\": " << json_number(r.volume)
       << ", \"edge_length\": " << lengths(r.min_edge_length, r.median_edge_length, r.max_edge_length)
       << ", \"min_angle\": " << json_number(r.min_angle) << ", \"min_angle_triangle\": " << r.min_angle_triangle
       << ", \"min_contact_angle\": " << json_number(r.min_contact_angle) << ", \"min_contact_point\": ["
       << json_number(r.min_contact_point[0]) << ", " << json_number(r.min_contact_point[1]) << ", "
       << json_number(r.min_contact_point[2]) << "], \"min_contact_patches\": [" << r.min_contact_patches.first << ", "
       << r.min_contact_patches.second << "], \"number_of_sharp_contact_edges\": " << r.number_of_sharp_contact_edges
       << ", \"sharp_contact_length\": " << json_number(r.sharp_contact_length) << "}";
  }
  os << (s.regions.empty() ? "],\n" : "\n  ],\n") << "  \"surfaces_inside_regions\": [";
  for(std::size_t i = 0; i < s.surfaces_inside_regions.size(); ++i)
  {
    const auto& a = s.surfaces_inside_regions[i];
    os << (i == 0 ? "\n" : ",\n") << "    {\"patch\": " << a.patch << ", \"name\": " << json_string(a.name)
       << ", \"region\": " << a.region << ", \"region_name\": " << json_string(a.region_name)
       << ", \"number_of_triangles\": " << a.number_of_triangles << "}";
  }
  os << (s.surfaces_inside_regions.empty() ? "],\n" : "\n  ],\n") << "  \"sharp_patch_corners\": [";
  for(std::size_t i = 0; i < s.sharp_patch_corners.size(); ++i)
  {
    const auto& c = s.sharp_patch_corners[i];
    os << (i == 0 ? "\n" : ",\n") << "    {\"patch\": " << c.patch << ", \"name\": " << json_string(c.name)
       << ", \"angle\": " << json_number(c.angle) << ", \"point\": [" << json_number(c.point[0]) << ", "
       << json_number(c.point[1]) << ", " << json_number(c.point[2])
       << "], \"number_of_sharp_corners\": " << c.number_of_sharp_corners << ", \"corners\": [";
    for(std::size_t k = 0; k < c.corners.size(); ++k)
      os << (k == 0 ? "[" : ", [") << json_number(c.corners[k][0]) << ", " << json_number(c.corners[k][1]) << ", "
         << json_number(c.corners[k][2]) << ", " << json_number(c.corners[k][3]) << "]";
    os << "]}";
  }
  os << (s.sharp_patch_corners.empty() ? "]\n" : "\n  ]\n") << "}\n";
  return os;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_SUMMARY_H
