// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_SVG_HISTOGRAMS_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_SVG_HISTOGRAMS_H

#include <CGAL/Bubble_mesh_3/Quality_report.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

struct Svg_curve
{
  std::string label;
  std::string color;
  double width = 1.5;
  std::string dash; // "" = solid
  const Quality_histogram* histograms[3] = {nullptr, nullptr, nullptr}; // aspect ratio, face, dihedral
};

inline std::string svg_text(const std::string& s)
{
  std::string r;
  for(char c : s)
  {
    if(c == '&') r += "&amp;";
    else if(c == '<') r += "&lt;";
    else if(c == '>') r += "&gt;";
    else if(c == '"') r += "&quot;";
    else r += c;
  }
  return r;
}

inline std::string svg_number(double v)
{
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.2f", v);
  return buf;
}

// colours that stay apart on screen and on paper; past ten, dashes tell curves apart
inline void svg_style(std::size_t i, Svg_curve& c)
{
  static const char* palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                  "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};
  static const char* dashes[] = {"", "6,3", "2,2", "8,3,2,3"};
  c.color = palette[i % 10];
  c.dash = dashes[(i / 10) % 4];
}

// the smallest of 1, 2, 2.5, 5 times a power of ten that is >= v
inline double nice_ceiling(double v)
{
  if(!(v > 0)) return 1.;
  const double p = std::pow(10., std::floor(std::log10(v)));
  for(double m : {1., 2., 2.5, 5., 10.})
    if(m * p >= v * (1 - 1e-12)) return m * p;
  return 10. * p;
}

struct Svg_panel_axis
{
  const char* title;
  const char* x_label;
  double x_min, x_max;              // drawn range
  double ideal;                     // value of the ideal element
  const char* ideal_label;
};

inline void write_svg_panel(std::ostream& os, const Svg_panel_axis& ax, std::size_t which,
                            const std::vector<Svg_curve>& curves, double left, double top,
                            double width, double height)
{
  // panel frame: plot area inside margins for tick labels
  const double ml = 58, mr = 12, mt = 28, mb = 48;
  const double x0 = left + ml, x1 = left + width - mr, y0 = top + height - mb, y1 = top + mt;
  auto X = [&](double v) { return x0 + (v - ax.x_min) / (ax.x_max - ax.x_min) * (x1 - x0); };

  double fmax = 0.;
  for(const Svg_curve& c : curves)
    if(c.histograms[which])
      for(double f : c.histograms[which]->frequencies) fmax = (std::max)(fmax, f);
  const double ymax = nice_ceiling(fmax);
  auto Y = [&](double f) { return y0 - f / ymax * (y0 - y1); };

  os << "<g>\n<text x=\"" << svg_number(0.5 * (x0 + x1)) << "\" y=\"" << svg_number(top + 18)
     << "\" text-anchor=\"middle\" font-size=\"15\" font-weight=\"bold\">" << ax.title << "</text>\n";
  if(which == 0)
  {
    // the open last bin [10, +infinity) is drawn over [10, x_max], shaded
    os << "<rect x=\"" << svg_number(X(10.)) << "\" y=\"" << svg_number(y1) << "\" width=\""
       << svg_number(X(ax.x_max) - X(10.)) << "\" height=\"" << svg_number(y0 - y1)
       << "\" fill=\"#f0f0f0\"/>\n<text x=\"" << svg_number(0.5 * (X(10.) + X(ax.x_max))) << "\" y=\""
       << svg_number(y1 + 24) << "\" text-anchor=\"middle\" font-size=\"10\" fill=\"#666666\">&gt;10</text>\n";
  }
  // horizontal grid and y ticks: 5 steps
  for(int k = 0; k <= 5; ++k)
  {
    const double f = ymax * k / 5.;
    os << "<line x1=\"" << svg_number(x0) << "\" y1=\"" << svg_number(Y(f)) << "\" x2=\"" << svg_number(x1)
       << "\" y2=\"" << svg_number(Y(f)) << "\" stroke=\"#dddddd\"/>\n";
    char label[32];
    std::snprintf(label, sizeof(label), ymax * 100 < 5 ? "%.2f%%" : (ymax * 100 < 50 ? "%.1f%%" : "%.0f%%"), 100. * f);
    os << "<text x=\"" << svg_number(x0 - 5) << "\" y=\"" << svg_number(Y(f) + 4)
       << "\" text-anchor=\"end\" font-size=\"11\">" << label << "</text>\n";
  }
  // x ticks: every 20 degrees for angles, every 1 for the aspect ratio
  std::vector<std::pair<double, std::string> > ticks;
  if(which == 0)
    for(int v = 1; v <= 10; ++v) ticks.push_back(std::make_pair(double(v), std::to_string(v)));
  else
    for(int v = 0; v <= 180; v += 20) ticks.push_back(std::make_pair(double(v), std::to_string(v)));
  for(const auto& t : ticks)
  {
    os << "<line x1=\"" << svg_number(X(t.first)) << "\" y1=\"" << svg_number(y0) << "\" x2=\""
       << svg_number(X(t.first)) << "\" y2=\"" << svg_number(y0 + 5) << "\" stroke=\"black\"/>\n";
    os << "<text x=\"" << svg_number(X(t.first)) << "\" y=\"" << svg_number(y0 + 18)
       << "\" text-anchor=\"middle\" font-size=\"11\">" << svg_text(t.second) << "</text>\n";
  }
  // axes and their labels
  os << "<line x1=\"" << svg_number(x0) << "\" y1=\"" << svg_number(y0) << "\" x2=\"" << svg_number(x1)
     << "\" y2=\"" << svg_number(y0) << "\" stroke=\"black\"/>\n"
     << "<line x1=\"" << svg_number(x0) << "\" y1=\"" << svg_number(y0) << "\" x2=\"" << svg_number(x0)
     << "\" y2=\"" << svg_number(y1) << "\" stroke=\"black\"/>\n"
     << "<text x=\"" << svg_number(0.5 * (x0 + x1)) << "\" y=\"" << svg_number(y0 + 38)
     << "\" text-anchor=\"middle\" font-size=\"12\">" << ax.x_label << "</text>\n"
     << "<text transform=\"translate(" << svg_number(left + 13) << "," << svg_number(0.5 * (y0 + y1))
     << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">relative frequency</text>\n";
  // the ideal element
  os << "<line x1=\"" << svg_number(X(ax.ideal)) << "\" y1=\"" << svg_number(y0) << "\" x2=\""
     << svg_number(X(ax.ideal)) << "\" y2=\"" << svg_number(y1) << "\" stroke=\"#888888\" stroke-dasharray=\"3,3\"/>\n"
     << "<text x=\"" << svg_number(X(ax.ideal) + 3) << "\" y=\"" << svg_number(y1 + 10)
     << "\" font-size=\"10\" fill=\"#666666\">" << ax.ideal_label << "</text>\n";
  // the curves: steps over the bins; the overflow bin is drawn over [10, x_max].
  // Last listed is drawn first: the thick whole-model curve goes under the regions
  for(auto it = curves.rbegin(); it != curves.rend(); ++it)
  {
    const Svg_curve& c = *it;
    const Quality_histogram* h = c.histograms[which];
    if(!h || h->total == 0) continue;
    os << "<path fill=\"none\" stroke=\"" << c.color << "\" stroke-width=\"" << svg_number(c.width) << "\"";
    if(!c.dash.empty()) os << " stroke-dasharray=\"" << c.dash << "\"";
    os << " d=\"M" << svg_number(X(h->lower_edges.front())) << "," << svg_number(Y(0));
    for(std::size_t i = 0; i < h->frequencies.size(); ++i)
    {
      const double hi = std::isfinite(h->upper_edges[i]) ? h->upper_edges[i] : ax.x_max;
      os << " L" << svg_number(X(h->lower_edges[i])) << "," << svg_number(Y(h->frequencies[i])) << " L"
         << svg_number(X(hi)) << "," << svg_number(Y(h->frequencies[i]));
    }
    const double end = std::isfinite(h->upper_edges.back()) ? h->upper_edges.back() : ax.x_max;
    os << " L" << svg_number(X(end)) << "," << svg_number(Y(0)) << "\">";
    os << "<title>" << svg_text(c.label) << "</title></path>\n";
  }
  os << "</g>\n";
}

inline void write_svg_figure(std::ostream& os, const std::string& title, const std::string& subtitle,
                             const std::vector<Svg_curve>& curves)
{
  const double panel_w = 400, panel_h = 320, top = 50;
  const double width = 3 * panel_w + 20;
  // legend: up to 4 entries a row
  const std::size_t per_row = 4;
  const std::size_t rows = (curves.size() + per_row - 1) / per_row;
  const double legend_top = top + panel_h + 10;
  const double height = legend_top + 22. * double(rows) + 16;

  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << svg_number(width) << "\" height=\""
     << svg_number(height) << "\" viewBox=\"0 0 " << svg_number(width) << " " << svg_number(height)
     << "\" font-family=\"Helvetica, Arial, sans-serif\">\n"
     << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
     << "<text x=\"10\" y=\"22\" font-size=\"17\" font-weight=\"bold\">" << svg_text(title) << "</text>\n"
     << "<text x=\"10\" y=\"40\" font-size=\"12\" fill=\"#444444\">" << svg_text(subtitle) << "</text>\n";
  const Svg_panel_axis axes[3] = {
    {"Aspect ratio", "longest edge / shortest altitude (bins of 0.5)", 1., 11., 1.2247, "ideal 1.22"},
    {"Face angle", "face angle (degrees, bins of 10)", 0., 180., 60., "ideal 60"},
    {"Dihedral angle", "dihedral angle (degrees, bins of 10)", 0., 180., 70.53, "ideal 70.5"}};
  for(std::size_t k = 0; k < 3; ++k)
    write_svg_panel(os, axes[k], k, curves, 10 + double(k) * panel_w, top, panel_w, panel_h);
  for(std::size_t i = 0; i < curves.size(); ++i)
  {
    const double x = 70 + double(i % per_row) * 290, y = legend_top + 22. * double(i / per_row) + 8;
    os << "<line x1=\"" << svg_number(x) << "\" y1=\"" << svg_number(y) << "\" x2=\"" << svg_number(x + 34)
       << "\" y2=\"" << svg_number(y) << "\" stroke=\"" << curves[i].color << "\" stroke-width=\""
       << svg_number(curves[i].width) << "\"";
    if(!curves[i].dash.empty()) os << " stroke-dasharray=\"" << curves[i].dash << "\"";
    os << "/>\n<text x=\"" << svg_number(x + 42) << "\" y=\"" << svg_number(y + 4) << "\" font-size=\"12\">"
       << svg_text(curves[i].label) << "</text>\n";
  }
  os << "</svg>\n";
}

inline void set_histograms(Svg_curve& c, const Region_quality& q)
{
  c.histograms[0] = &q.aspect_ratio_histogram;
  c.histograms[1] = &q.face_angle_histogram;
  c.histograms[2] = &q.dihedral_angle_histogram;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

writes the paper's three quality histograms of `report` (aspect ratio, face
angle, dihedral angle; relative frequencies) as one SVG picture of three
panels, one step curve per region and a thick black one for the merged model,
as in the paper's Figures 7-9; with a legend, axis labels and ticks, and a
dashed line at the ideal element's value.
*/
inline void write_svg_histograms(std::ostream& os, const Mesh_quality_report& report)
{
  std::vector<internal::Svg_curve> curves;
  for(std::size_t i = 0; i < report.regions.size(); ++i)
  {
    const Region_quality& q = report.regions[i];
    internal::Svg_curve c;
    c.label = "region " + std::to_string(q.region) + (q.name.empty() ? "" : " " + q.name) + " (" +
              std::to_string(q.number_of_tetrahedra) + " tets)";
    internal::svg_style(i, c);
    internal::set_histograms(c, q);
    curves.push_back(c);
  }
  internal::Svg_curve all;
  all.label = "whole model (" + std::to_string(report.all.number_of_tetrahedra) + " tets)";
  all.color = "#222222";
  all.width = 3.5;
  internal::set_histograms(all, report.all);
  curves.push_back(all);
  internal::write_svg_figure(os, "Mesh quality: " + report.name,
                             "relative frequency per region and for the whole model; aspect ratio: "
                             "regular tetrahedron 1.2247, last bin: above 10",
                             curves);
}

/*!
\ingroup PkgBubbleMesh3IO

writes the three histograms of several meshes side by side (the merged model
of each, one curve per mesh), as in the paper's Figures 10-12. `names[i]`
labels mesh `i` (its report name when missing or empty).
*/
inline void write_svg_histogram_comparison(std::ostream& os, const std::vector<Mesh_quality_report>& reports,
                                           const std::vector<std::string>& names = std::vector<std::string>())
{
  std::vector<internal::Svg_curve> curves;
  for(std::size_t i = 0; i < reports.size(); ++i)
  {
    internal::Svg_curve c;
    c.label = (i < names.size() && !names[i].empty() ? names[i] : reports[i].name) + " (" +
              std::to_string(reports[i].all.number_of_tetrahedra) + " tets)";
    internal::svg_style(i, c);
    c.width = 2.2;
    internal::set_histograms(c, reports[i].all);
    curves.push_back(c);
  }
  internal::write_svg_figure(os, "Mesh quality comparison",
                             "relative frequency over the whole model of each mesh; aspect ratio: "
                             "regular tetrahedron 1.2247, last bin: above 10",
                             curves);
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_SVG_HISTOGRAMS_H
