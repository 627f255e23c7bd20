// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_QUALITY_REPORT_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_QUALITY_REPORT_H

#include <CGAL/Bubble_mesh_3/Quality_report.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iterator>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

// JSON has no NaN or infinity: both become null
inline std::string json_number(double v)
{
  if(!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.12g", v);
  return buf;
}

inline std::string json_string(const std::string& s)
{
  std::string r = "\"";
  for(char ch : s)
  {
    const unsigned char c = static_cast<unsigned char>(ch);
    if(c == '"' || c == '\\') { r += '\\'; r += ch; }
    else if(c == '\n') r += "\\n";
    else if(c == '\t') r += "\\t";
    else if(c < 32)
    {
      char buf[8];
      std::snprintf(buf, sizeof(buf), "\\u%04x", c);
      r += buf;
    }
    else r += ch;
  }
  return r + "\"";
}

template <class T, class F>
std::string json_array(const std::vector<T>& v, F f)
{
  std::string r = "[";
  for(std::size_t i = 0; i < v.size(); ++i)
  {
    if(i > 0) r += ", ";
    r += f(v[i]);
  }
  return r + "]";
}

inline std::string json_histogram(const Quality_histogram& h)
{
  auto num = [](double x) { return json_number(x); };
  return "{\"bin_lower\": " + json_array(h.lower_edges, num) +
         ", \"bin_upper\": " + json_array(h.upper_edges, num) +
         ", \"count\": " + json_array(h.counts, [](std::size_t c) { return std::to_string(c); }) +
         ", \"frequency\": " + json_array(h.frequencies, num) + "}";
}

inline void write_region_json(std::ostream& os, const Region_quality& q, const std::string& indent)
{
  const std::string in = indent + "  ";
  os << "{\n";
  if(q.region == Region_quality::all_regions) os << in << "\"region\": \"all\",\n";
  else os << in << "\"region\": " << q.region << ",\n";
  if(!q.name.empty()) os << in << "\"name\": " << json_string(q.name) << ",\n";
  os << in << "\"tetrahedra\": " << q.number_of_tetrahedra << ",\n"
     << in << "\"vertices\": " << q.number_of_vertices << ",\n"
     << in << "\"volume\": " << json_number(q.volume) << ",\n"
     << in << "\"degenerate_tetrahedra\": " << q.number_of_degenerate_tetrahedra << ",\n"
     << in << "\"negatively_oriented_tetrahedra\": " << q.number_of_negatively_oriented_tetrahedra << ",\n"
     << in << "\"dihedral_angle\": {\"min\": " << json_number(q.min_dihedral_angle)
     << ", \"max\": " << json_number(q.max_dihedral_angle)
     << ", \"mean\": " << json_number(q.mean_dihedral_angle) << "},\n"
     << in << "\"smallest_dihedral_angle\": {\"mean\": " << json_number(q.mean_smallest_dihedral_angle)
     << ", \"share_under_5\": " << json_number(q.share_smallest_dihedral_under[0])
     << ", \"share_under_10\": " << json_number(q.share_smallest_dihedral_under[1])
     << ", \"share_under_15\": " << json_number(q.share_smallest_dihedral_under[2])
     << ", \"share_under_20\": " << json_number(q.share_smallest_dihedral_under[3])
     << ", \"share_under_10_not_at_small_surface_angle\": "
     << json_number(q.share_under_10_not_at_small_surface_angle)
     << ", \"share_under_10_at_sharp_contact\": " << json_number(q.share_under_10_at_sharp_contact)
     << ", \"share_under_10_not_touching_small_surface_angle\": "
     << json_number(q.share_under_10_not_touching_small_surface_angle) << "},\n"
     << in << "\"face_angle\": {\"min\": " << json_number(q.min_face_angle)
     << ", \"max\": " << json_number(q.max_face_angle) << "},\n"
     << in << "\"aspect_ratio\": {\"min\": " << json_number(q.min_aspect_ratio)
     << ", \"median\": " << json_number(q.median_aspect_ratio)
     << ", \"max\": " << json_number(q.max_aspect_ratio)
     << ", \"share_above_10\": " << json_number(q.share_aspect_ratio_above_10)
     << ", \"share_above_40\": " << json_number(q.share_aspect_ratio_above_40) << "},\n"
     << in << "\"histograms\": {\n"
     << in << "  \"aspect_ratio\": " << json_histogram(q.aspect_ratio_histogram) << ",\n"
     << in << "  \"face_angle\": " << json_histogram(q.face_angle_histogram) << ",\n"
     << in << "  \"dihedral_angle\": " << json_histogram(q.dihedral_angle_histogram) << "\n"
     << in << "}\n"
     << indent << "}";
}

inline std::string optional_json(const std::optional<std::size_t>& v)
{
  return v ? std::to_string(*v) : std::string("null");
}

inline void write_report_json(std::ostream& os, const Mesh_quality_report& r, const std::string& indent)
{
  const std::string in = indent + "  ";
  os << "{\n"
     << in << "\"name\": " << json_string(r.name) << ",\n"
     << in << "\"aspect_ratio_definition\": \"longest edge / shortest altitude; regular tetrahedron: "
        "sqrt(3/2) = 1.2247 (the paper's 0.81 is the reciprocal, shortest altitude / longest edge)\",\n"
     << in << "\"points\": " << r.number_of_points << ",\n"
     << in << "\"boundary_triangles\": " << r.number_of_boundary_triangles << ",\n"
     << in << "\"surface_angle_source\": " << json_string(r.surface_angle_source) << ",\n"
     << in << "\"steiner_points\": " << optional_json(r.number_of_steiner_points) << ",\n"
     << in << "\"input_triangles\": " << optional_json(r.number_of_input_triangles) << ",\n"
     << in << "\"input_triangles_kept_whole\": " << optional_json(r.number_of_input_triangles_kept_whole) << ",\n"
     << in << "\"all\": ";
  write_region_json(os, r.all, in);
  os << ",\n" << in << "\"regions\": [";
  for(std::size_t i = 0; i < r.regions.size(); ++i)
  {
    os << (i == 0 ? "\n" : ",\n") << in << "  ";
    write_region_json(os, r.regions[i], in + "  ");
  }
  os << "\n" << in << "],\n" << in << "\"worst_tetrahedra\": [";
  for(std::size_t i = 0; i < r.worst_tetrahedra.size(); ++i)
  {
    const Worst_tetrahedron& w = r.worst_tetrahedra[i];
    os << (i == 0 ? "\n" : ",\n") << in << "  {\"index\": " << w.index << ", \"region\": " << w.region
       << ", \"vertices\": [" << w.vertices[0] << ", " << w.vertices[1] << ", " << w.vertices[2] << ", "
       << w.vertices[3] << "], \"centroid\": [" << json_number(w.centroid[0]) << ", "
       << json_number(w.centroid[1]) << ", " << json_number(w.centroid[2])
       << "], \"min_dihedral_angle\": " << json_number(w.min_dihedral_angle)
       << ", \"max_dihedral_angle\": " << json_number(w.max_dihedral_angle)
       << ", \"aspect_ratio\": " << json_number(w.aspect_ratio)
       << ", \"volume\": " << json_number(w.volume)
       << ", \"boundary_faces\": " << w.boundary_faces
       << ", \"touching_surface_min_angle\": " << json_number(w.touching_surface_min_angle)
       << ", \"contact_min_angle\": " << json_number(w.contact_min_angle)
       << ", \"touching_patches\": "
       << json_array(w.touching_patches, [](int p) { return std::to_string(p); }) << "}";
  }
  os << "\n" << in << "]\n" << indent << "}";
}

// fixed-width cell for the text tables; NaN and infinity spelt out
inline std::string cell(double v, int precision)
{
  if(std::isnan(v)) return "-";
  if(std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream s;
  // huge values (aspect ratios of nearly flat tets) in scientific notation, so that columns keep their width
  if(std::abs(v) >= 1e6) s << std::scientific << std::setprecision(2) << v;
  else s << std::fixed << std::setprecision(precision) << v;
  return s.str();
}

inline std::string percent(double share) { return cell(100. * share, 1); }

inline std::string region_label(const Region_quality& q)
{
  if(q.region == Region_quality::all_regions) return "all";
  std::string s = std::to_string(q.region);
  if(!q.name.empty()) s += " " + q.name;
  return s;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

writes `report` as one JSON object: the header fields, `"all"` (the merged model),
`"regions"` (one object per region) and `"worst_tetrahedra"`. Angles are in
degrees, shares in [0,1]; NaN and infinity (a flat tetrahedron's aspect ratio)
are written as `null`. Numbers have 12 significant digits.
*/
inline void write_quality_report_json(std::ostream& os, const Mesh_quality_report& report)
{
  internal::write_report_json(os, report, "");
  os << "\n";
}

/*!
\ingroup PkgBubbleMesh3IO

writes several reports as `{"meshes": [report, ...]}`.
*/
inline void write_quality_reports_json(std::ostream& os, const std::vector<Mesh_quality_report>& reports)
{
  os << "{\n  \"meshes\": [";
  for(std::size_t i = 0; i < reports.size(); ++i)
  {
    os << (i == 0 ? "\n    " : ",\n    ");
    internal::write_report_json(os, reports[i], "    ");
  }
  os << "\n  ]\n}\n";
}

/*!
\ingroup PkgBubbleMesh3IO

writes `report` as a compact text table: one row per region and one for the
merged model (`all`), then the worst tetrahedra.
*/
inline void write_quality_report_text(std::ostream& os, const Mesh_quality_report& report)
{
  using internal::cell;
  using internal::percent;
  os << "Mesh quality: " << report.name << "\n"
     << "  points " << report.number_of_points << ", boundary triangles "
     << report.number_of_boundary_triangles;
  if(report.number_of_steiner_points) os << ", Steiner points " << *report.number_of_steiner_points;
  if(report.number_of_input_triangles_kept_whole)
  {
    os << ", input triangles kept whole " << *report.number_of_input_triangles_kept_whole;
    if(report.number_of_input_triangles) os << " of " << *report.number_of_input_triangles;
  }
  os << "\n  angles in degrees; AR = aspect ratio, longest edge / shortest altitude"
        " (regular tet 1.2247; the paper's 0.81 is its reciprocal)\n"
        "  mindih = smallest dihedral of a tet; <5 ... = % of tets with mindih under it\n\n";

  const char* header[] = {"region", "tets", "verts", "volume", "dih min", "dih max", "dih mean",
                          "mindih mean", "<5%", "<10%", "<15%", "<20%", "AR med", "AR max",
                          "AR>10%", "AR>40%"};
  const int width[] = {14, 9, 8, 11, 9, 9, 9, 12, 7, 7, 7, 7, 9, 10, 8, 8};
  auto row = [&](const std::vector<std::string>& cells) {
    for(std::size_t i = 0; i < cells.size(); ++i)
    {
      if(i == 0) os << "  " << std::left << std::setw(width[i]) << cells[i];
      else os << std::right << std::setw(width[i]) << cells[i];
    }
    os << std::left << "\n";
  };
  row(std::vector<std::string>(std::begin(header), std::end(header)));
  std::vector<const Region_quality*> rows;
  for(const Region_quality& q : report.regions) rows.push_back(&q);
  rows.push_back(&report.all);
  for(const Region_quality* q : rows)
  {
    std::ostringstream vol;
    vol << std::setprecision(5) << q->volume;
    std::string label = internal::region_label(*q);
    if(label.size() > 13) label = label.substr(0, 13);
    row({label, std::to_string(q->number_of_tetrahedra), std::to_string(q->number_of_vertices), vol.str(),
         cell(q->min_dihedral_angle, 2), cell(q->max_dihedral_angle, 2), cell(q->mean_dihedral_angle, 2),
         cell(q->mean_smallest_dihedral_angle, 2), percent(q->share_smallest_dihedral_under[0]),
         percent(q->share_smallest_dihedral_under[1]), percent(q->share_smallest_dihedral_under[2]),
         percent(q->share_smallest_dihedral_under[3]), cell(q->median_aspect_ratio, 3),
         cell(q->max_aspect_ratio, 2), percent(q->share_aspect_ratio_above_10),
         percent(q->share_aspect_ratio_above_40)});
  }
  if(report.all.number_of_degenerate_tetrahedra > 0)
    os << "  degenerate (flat) tetrahedra: " << report.all.number_of_degenerate_tetrahedra << "\n";
  if(!std::isnan(report.all.share_under_10_not_at_small_surface_angle))
    os << "  tets under 10 degrees not against a surface angle under 10 (" << report.surface_angle_source
       << "): " << percent(report.all.share_under_10_not_at_small_surface_angle)
       << " %\n  of them next to a sharp contact (surfaces meeting at under 10 degrees in their region, as at a"
          " pinch-out: a vertex on it, or inside its wedge where that is thinner than the tet): "
       << percent(report.all.share_under_10_at_sharp_contact)
       << " %\n  of them with no vertex on a surface angle under 10 either (touching the input nowhere): "
       << percent(report.all.share_under_10_not_touching_small_surface_angle) << " %\n";

  if(!report.worst_tetrahedra.empty())
  {
    os << "\n  worst tetrahedra; bfaces = faces on a surface, surfang = smallest angle of the surface\n"
       << "  triangles sharing an edge with the tet (angles of the " << report.surface_angle_source << "),\n"
       << "  contact = smallest angle of its region between surfaces at a boundary edge through a vertex\n"
       << "  " << std::right << std::setw(9) << "tet" << std::setw(8) << "region" << std::setw(9)
       << "mindih" << std::setw(9) << "maxdih" << std::setw(10) << "AR" << std::setw(8) << "bfaces"
       << std::setw(9) << "surfang" << std::setw(9) << "contact" << "  centroid\n";
    for(const Worst_tetrahedron& w : report.worst_tetrahedra)
    {
      std::ostringstream c;
      c << std::setprecision(6) << "(" << w.centroid[0] << ", " << w.centroid[1] << ", " << w.centroid[2] << ")";
      os << "  " << std::setw(9) << w.index << std::setw(8) << w.region << std::setw(9)
         << cell(w.min_dihedral_angle, 3) << std::setw(9) << cell(w.max_dihedral_angle, 2) << std::setw(10)
         << cell(w.aspect_ratio, 2) << std::setw(8) << w.boundary_faces << std::setw(9)
         << cell(w.touching_surface_min_angle, 2) << std::setw(9) << cell(w.contact_min_angle, 2) << "  "
         << c.str() << "\n";
    }
    os << std::left;
  }
}

/*!
\ingroup PkgBubbleMesh3IO

writes several reports side by side: one column per mesh, one row per measure
of the merged model (`names[i]` heads column `i`; the report name when empty).
*/
inline void write_quality_comparison_text(std::ostream& os, const std::vector<Mesh_quality_report>& reports,
                                          const std::vector<std::string>& names = std::vector<std::string>())
{
  using internal::cell;
  using internal::percent;
  std::vector<std::string> heads;
  std::size_t w = 12;
  for(std::size_t i = 0; i < reports.size(); ++i)
  {
    heads.push_back(i < names.size() && !names[i].empty() ? names[i] : reports[i].name);
    w = (std::max)(w, heads.back().size() + 2);
  }
  auto row = [&](const std::string& label, auto value) {
    os << "  " << std::left << std::setw(34) << label;
    for(const Mesh_quality_report& r : reports) os << std::right << std::setw(int(w)) << value(r);
    os << std::left << "\n";
  };
  os << "Mesh quality comparison (merged model; angles in degrees; AR = longest edge / shortest altitude)\n";
  os << "  " << std::left << std::setw(34) << "";
  for(const std::string& h : heads) os << std::right << std::setw(int(w)) << h;
  os << std::left << "\n";
  auto count = [](std::size_t n) { return std::to_string(n); };
  auto opt = [](const std::optional<std::size_t>& n) { return n ? std::to_string(*n) : std::string("-"); };
  row("tetrahedra", [&](const Mesh_quality_report& r) { return count(r.all.number_of_tetrahedra); });
  row("vertices", [&](const Mesh_quality_report& r) { return count(r.all.number_of_vertices); });
  row("regions", [&](const Mesh_quality_report& r) { return count(r.regions.size()); });
  row("volume", [&](const Mesh_quality_report& r) {
    std::ostringstream s;
    s << std::setprecision(6) << r.all.volume;
    return s.str();
  });
  row("min dihedral", [](const Mesh_quality_report& r) { return cell(r.all.min_dihedral_angle, 3); });
  row("max dihedral", [](const Mesh_quality_report& r) { return cell(r.all.max_dihedral_angle, 3); });
  row("mean dihedral", [](const Mesh_quality_report& r) { return cell(r.all.mean_dihedral_angle, 3); });
  row("mean smallest dihedral", [](const Mesh_quality_report& r) { return cell(r.all.mean_smallest_dihedral_angle, 3); });
  for(std::size_t k = 0; k < 4; ++k)
  {
    const int t = int(Region_quality::dihedral_thresholds[k]);
    row("% tets smallest dihedral < " + std::to_string(t),
        [k](const Mesh_quality_report& r) { return percent(r.all.share_smallest_dihedral_under[k]); });
  }
  row("% < 10 not at surface angle < 10", [](const Mesh_quality_report& r) {
    return percent(r.all.share_under_10_not_at_small_surface_angle);
  });
  row("  of them at a sharp contact", [](const Mesh_quality_report& r) {
    return percent(r.all.share_under_10_at_sharp_contact);
  });
  row("  of them touching no surface angle < 10", [](const Mesh_quality_report& r) {
    return percent(r.all.share_under_10_not_touching_small_surface_angle);
  });
  row("min face angle", [](const Mesh_quality_report& r) { return cell(r.all.min_face_angle, 3); });
  row("max face angle", [](const Mesh_quality_report& r) { return cell(r.all.max_face_angle, 3); });
  row("aspect ratio median", [](const Mesh_quality_report& r) { return cell(r.all.median_aspect_ratio, 3); });
  row("aspect ratio max", [](const Mesh_quality_report& r) { return cell(r.all.max_aspect_ratio, 2); });
  row("% aspect ratio > 10", [](const Mesh_quality_report& r) { return percent(r.all.share_aspect_ratio_above_10); });
  row("% aspect ratio > 40", [](const Mesh_quality_report& r) { return percent(r.all.share_aspect_ratio_above_40); });
  row("Steiner points", [&](const Mesh_quality_report& r) { return opt(r.number_of_steiner_points); });
  row("input triangles kept whole", [&](const Mesh_quality_report& r) { return opt(r.number_of_input_triangles_kept_whole); });
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_QUALITY_REPORT_H
