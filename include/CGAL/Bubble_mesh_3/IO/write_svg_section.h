// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_WRITE_SVG_SECTION_H
#define CGAL_BUBBLE_MESH_3_IO_WRITE_SVG_SECTION_H

#include <CGAL/Bubble_mesh_3/Bubble.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Bubble_mesh_3/mesh_quality.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal_np {
enum svg_width_t { svg_width };
enum svg_title_t { svg_title };
enum draw_cell_edges_t { draw_cell_edges };
enum region_names_t { region_names };
enum section_bubbles_t { section_bubbles };
enum highlight_dihedral_below_t { highlight_dihedral_below };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgBubbleMesh3IO
/// `write_svg_section()`, `write_svg_bubble_section()`: width of the picture in pixels (default 900)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, svg_width)
/// \ingroup PkgBubbleMesh3IO
/// `write_svg_section()`, `write_svg_bubble_section()`: a title above the picture (default none)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::string, svg_title)
/// \ingroup PkgBubbleMesh3IO
/// `write_svg_section()`: draw the outline of every cut cell (default `true`)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, draw_cell_edges)
/// \ingroup PkgBubbleMesh3IO
/// `write_svg_section()`: the names of the regions for the legend, entry `r` for region `r` (default: numbers)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::vector<std::string>, region_names)
/// \ingroup PkgBubbleMesh3IO
/// `write_svg_section()`: cut cells whose smallest dihedral angle is under this many degrees
/// are drawn in magenta, and the legend counts them (default 0: none)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, highlight_dihedral_below)

/// \ingroup PkgBubbleMesh3IO
/// `write_svg_section()`: bubbles whose balls the plane cuts are drawn over the cells as
/// circles (the exact cut of each ball); a pointer to a `std::vector<Bubble<K> >` (default none)
template <class K>
Named_function_parameters<const std::vector<Bubble<K> >*, internal_np::section_bubbles_t>
section_bubbles(const std::vector<Bubble<K> >* b)
{
  return Named_function_parameters<const std::vector<Bubble<K> >*, internal_np::section_bubbles_t>(b);
}
/// \cond SKIP_IN_MANUAL
template <class K, class T, class Tag, class Base>
Named_function_parameters<const std::vector<Bubble<K> >*, internal_np::section_bubbles_t,
                          Named_function_parameters<T, Tag, Base> >
section_bubbles(const std::vector<Bubble<K> >* b, const Named_function_parameters<T, Tag, Base>& np)
{
  return {b, np};
}
/// \endcond

} // namespace parameters

namespace IO {
namespace internal {

// Pictures in the plane's own frame: u to the right, v up (v is the projection
// of +z onto the plane unless the plane is nearly horizontal; then u = x, v = y).
struct Svg_section_canvas
{
  struct Polygon { std::vector<std::array<double, 2> > p; int region; bool poor; };
  struct Segment { std::array<double, 2> a, b; int patch; };
  struct Circle { std::array<double, 2> c; double r; int region; bool fixed; };

  std::array<double, 3> origin{}, n{}, u{}, v{};
  double poor_below = 0.; // cells with a smaller dihedral angle are poor (0: none is)
  std::vector<Polygon> polygons;
  std::vector<Segment> segments;
  std::vector<Circle> circles;

  template <class Plane>
  explicit Svg_section_canvas(const Plane& plane)
  {
    const auto o = plane.point();
    origin = {{CGAL::to_double(o.x()), CGAL::to_double(o.y()), CGAL::to_double(o.z())}};
    n = normalized({{CGAL::to_double(plane.a()), CGAL::to_double(plane.b()), CGAL::to_double(plane.c())}});
    if(std::abs(n[2]) < 0.99)
    {
      v = normalized({{-n[2] * n[0], -n[2] * n[1], 1. - n[2] * n[2]}}); // +z minus its normal part
      u = cross(n, v);
    }
    else
    {
      u = {{1., 0., 0.}};
      v = {{0., n[2] > 0 ? 1. : -1., 0.}};
    }
  }

  static std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b)
  {
    return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  }
  static std::array<double, 3> normalized(std::array<double, 3> a)
  {
    const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for(double& x : a) x /= l;
    return a;
  }
  template <class Point>
  std::array<double, 3> rel(const Point& p) const
  {
    return {{CGAL::to_double(p.x()) - origin[0], CGAL::to_double(p.y()) - origin[1],
             CGAL::to_double(p.z()) - origin[2]}};
  }
  std::array<double, 3> rel(const std::array<double, 3>& p) const
  {
    return {{p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]}};
  }
  static double dot(const std::array<double, 3>& a, const std::array<double, 3>& b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  std::array<double, 2> in_plane(const std::array<double, 3>& r) const { return {{dot(r, u), dot(r, v)}}; }

  // crossing points of the plane with the edges of a simplex given by its corners
  template <class Point, std::size_t N>
  std::vector<std::array<double, 2> > cut(const std::array<Point, N>& corner) const
  {
    std::array<std::array<double, 3>, N> r;
    std::array<double, N> d;
    bool below = false, above = false;
    for(std::size_t i = 0; i < N; ++i)
    {
      r[i] = rel(corner[i]);
      d[i] = dot(r[i], n);
      below = below || d[i] < 0;
      above = above || d[i] > 0;
    }
    std::vector<std::array<double, 2> > pts;
    if(!below || !above) return pts; // touching is not cutting: skip, so shared faces draw once
    for(std::size_t i = 0; i < N; ++i)
      for(std::size_t j = i + 1; j < N; ++j)
      {
        if(d[i] == 0 && d[j] == 0) continue;
        if(d[i] == 0 || d[j] == 0)
        {
          const std::size_t k = d[i] == 0 ? i : j;
          const std::array<double, 2> p = in_plane(r[k]);
          if(std::find(pts.begin(), pts.end(), p) == pts.end()) pts.push_back(p);
          continue;
        }
        if((d[i] < 0) == (d[j] < 0)) continue;
        const double t = d[i] / (d[i] - d[j]);
        std::array<double, 3> q;
        for(int c = 0; c < 3; ++c) q[c] = r[i][c] + t * (r[j][c] - r[i][c]);
        pts.push_back(in_plane(q));
      }
    return pts;
  }

  void add_cell(std::vector<std::array<double, 2> > pts, int region, bool poor = false)
  {
    if(pts.size() < 3) return;
    double cx = 0, cy = 0;
    for(const auto& p : pts) { cx += p[0]; cy += p[1]; }
    cx /= double(pts.size());
    cy /= double(pts.size());
    std::sort(pts.begin(), pts.end(), [&](const std::array<double, 2>& a, const std::array<double, 2>& b) {
      return std::atan2(a[1] - cy, a[0] - cx) < std::atan2(b[1] - cy, b[0] - cx);
    });
    polygons.push_back({pts, region, poor});
  }
  // a tetrahedron of `region` given by its corners: its cut, marked poor by `poor_below`
  template <class Point>
  void add_tetrahedron(const std::array<Point, 4>& p, int region)
  {
    std::vector<std::array<double, 2> > pts = cut(p);
    if(pts.size() < 3) return;
    const bool poor = poor_below > 0. && tetrahedron_quality(p[0], p[1], p[2], p[3]).min_dihedral_angle < poor_below;
    add_cell(std::move(pts), region, poor);
  }
  void add_facet(const std::vector<std::array<double, 2> >& pts, int patch)
  {
    if(pts.size() == 2) segments.push_back({pts[0], pts[1], patch});
  }
  template <class Point>
  void add_ball(const Point& c, double radius, int region, bool fixed)
  {
    const std::array<double, 3> r = rel(c);
    const double d = dot(r, n);
    if(std::abs(d) >= radius) return;
    circles.push_back({in_plane(r), std::sqrt(radius * radius - d * d), region, fixed});
  }

  static const char* region_color(int r)
  {
    static const char* fill[] = {"#a6cee3", "#b2df8a", "#fdbf6f", "#cab2d6", "#fb9a99",
                                 "#ffff99", "#8dd3c7", "#bebada", "#fccde5", "#e5d8bd"};
    return r <= 0 ? "#ffffff" : fill[(r - 1) % 10];
  }
  static const char* patch_color(int p)
  {
    static const char* stroke[] = {"#1f78b4", "#e31a1c", "#33a02c", "#ff7f00", "#6a3d9a",
                                   "#b15928", "#000000", "#e7298a", "#666666", "#1b9e77"};
    return stroke[(p < 0 ? 0 : p) % 10];
  }
  static std::string num(double x)
  {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.2f", x);
    return buf;
  }
  static std::string text(const std::string& s)
  {
    std::string r;
    for(char c : s)
      r += c == '&' ? std::string("&amp;") : c == '<' ? std::string("&lt;") : c == '>' ? std::string("&gt;")
           : std::string(1, c);
    return r;
  }

  // legend: one entry per region present; names[r] when given; the poor cells last
  void write(std::ostream& os, double width, const std::string& title, bool cell_edges,
             const std::vector<std::string>& names) const
  {
    double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
    auto grow = [&](const std::array<double, 2>& p, double r) {
      x0 = (std::min)(x0, p[0] - r); x1 = (std::max)(x1, p[0] + r);
      y0 = (std::min)(y0, p[1] - r); y1 = (std::max)(y1, p[1] + r);
    };
    for(const Polygon& g : polygons) for(const auto& p : g.p) grow(p, 0);
    for(const Segment& s : segments) { grow(s.a, 0); grow(s.b, 0); }
    for(const Circle& c : circles) grow(c.c, c.r);
    if(x0 > x1) { x0 = y0 = 0; x1 = y1 = 1; }
    // the legend: one entry per region drawn (cells, or interior bubbles), wrapped into rows
    std::vector<int> regions;
    for(const Polygon& g : polygons) regions.push_back(g.region);
    for(const Circle& c : circles) if(!c.fixed) regions.push_back(c.region);
    std::sort(regions.begin(), regions.end());
    regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
    const std::size_t poor = std::size_t(std::count_if(polygons.begin(), polygons.end(),
                                                       [](const Polygon& g) { return g.poor; }));
    std::ostringstream poor_label;
    if(poor_below > 0.)
    {
      poor_label << "tetrahedra under " << poor_below << " deg (" << poor << " cut)";
      regions.push_back(-1); // the poor cells' entry
    }
    const double margin = 10, top = title.empty() ? margin : 34, row = 18;
    std::vector<std::pair<std::string, std::array<double, 2> > > entries; // name, (x, row index)
    double lx = margin, rows = regions.empty() ? 0 : 1;
    for(int r : regions)
    {
      const std::string name = r < 0 ? poor_label.str()
                               : std::size_t(r) < names.size() && !names[std::size_t(r)].empty()
                                 ? names[std::size_t(r)] : "region " + std::to_string(r);
      const double w = 28 + 7 * double(name.size());
      if(lx > margin && lx + w > width - margin) { lx = margin; rows += 1; }
      entries.push_back({name, {{lx, rows - 1}}});
      lx += w;
    }
    const double legend = 6 + row * rows;
    const double scale = (width - 2 * margin) / (std::max)(x1 - x0, 1e-300);
    const double height = top + (y1 - y0) * scale + margin + legend;
    auto X = [&](double x) { return num(margin + (x - x0) * scale); };
    auto Y = [&](double y) { return num(top + (y1 - y) * scale); };

    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
       << "\" viewBox=\"0 0 " << num(width) << ' ' << num(height) << "\" font-family=\"sans-serif\">\n"
       << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    if(!title.empty())
      os << "<text x=\"" << num(width / 2) << "\" y=\"22\" text-anchor=\"middle\" font-size=\"16\">" << text(title)
         << "</text>\n";
    os << "<g stroke=\"" << (cell_edges ? "#555555" : "none") << "\" stroke-width=\"0.4\" stroke-linejoin=\"round\">\n";
    for(const Polygon& g : polygons)
    {
      os << "<polygon class=\"cell\" fill=\"" << region_color(g.region) << "\" points=\"";
      for(const auto& p : g.p) os << X(p[0]) << ',' << Y(p[1]) << ' ';
      os << "\"/>\n";
    }
    // poor cells filled in a colour no region or surface has (a sliver's cut can be too thin to see as an outline)
    os << "</g>\n<g fill=\"#ff00ff\" stroke=\"#ff00ff\" stroke-width=\"1.6\" stroke-linejoin=\"round\">\n";
    for(const Polygon& g : polygons)
    {
      if(!g.poor) continue;
      os << "<polygon class=\"poor-cell\" points=\"";
      for(const auto& p : g.p) os << X(p[0]) << ',' << Y(p[1]) << ' ';
      os << "\"/>\n";
    }
    os << "</g>\n<g stroke-width=\"2\" stroke-linecap=\"round\">\n";
    for(const Segment& s : segments)
      os << "<line class=\"surface\" stroke=\"" << patch_color(s.patch) << "\" x1=\"" << X(s.a[0]) << "\" y1=\""
         << Y(s.a[1]) << "\" x2=\"" << X(s.b[0]) << "\" y2=\"" << Y(s.b[1]) << "\"/>\n";
    os << "</g>\n<g stroke-width=\"0.8\" fill-opacity=\"0.55\">\n";
    for(const Circle& c : circles)
    {
      os << "<circle class=\"" << (c.fixed ? "surface-bubble" : "bubble") << "\" cx=\"" << X(c.c[0]) << "\" cy=\""
         << Y(c.c[1]) << "\" r=\"" << num(c.r * scale) << "\" fill=\""
         << (c.fixed ? "#999999" : region_color(c.region)) << "\" stroke=\"" << (c.fixed ? "#444444" : "#333333")
         << "\"/>\n";
    }
    os << "</g>\n";
    const double ly = height - legend + 6;
    for(std::size_t i = 0; i < entries.size(); ++i)
    {
      const double ex = entries[i].second[0], ey = ly + row * entries[i].second[1];
      os << "<rect x=\"" << num(ex) << "\" y=\"" << num(ey) << "\" width=\"12\" height=\"12\" stroke=\""
         << (regions[i] < 0 ? "#ff00ff" : "#555555") << "\" fill=\""
         << (regions[i] < 0 ? "#ff00ff" : region_color(regions[i])) << "\"/><text x=\"" << num(ex + 16) << "\" y=\"" << num(ey + 11)
         << "\" font-size=\"12\">" << text(entries[i].first) << "</text>\n";
    }
    os << "</svg>\n";
  }
};

// a canvas for a section of cells, with the named parameters of `write_svg_section()`
// that decide which cells are poor
template <class Plane_3, class NamedParameters>
Svg_section_canvas cell_section_canvas(const Plane_3& plane, const NamedParameters& np)
{
  Svg_section_canvas canvas(plane);
  canvas.poor_below = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::highlight_dihedral_below), 0.);
  return canvas;
}
// the picture of such a canvas, with the named parameters that decide how it looks;
// `default_names` name the legend's regions unless `region_names` is given
template <class NamedParameters>
void write_cell_section(std::ostream& os, const Svg_section_canvas& canvas, const NamedParameters& np,
                        const std::vector<std::string>& default_names)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  canvas.write(os, choose_parameter(get_parameter(np, internal_np::svg_width), 900.),
               choose_parameter(get_parameter(np, internal_np::svg_title), std::string()),
               choose_parameter(get_parameter(np, internal_np::draw_cell_edges), true),
               choose_parameter(get_parameter(np, internal_np::region_names), default_names));
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

Draws the plane section of a labelled tetrahedral mesh as an SVG picture:
every cell of the complex that the plane cuts becomes a polygon (a triangle
or a quadrilateral) filled with the colour of its region (subdomain index),
and every facet of the complex that the plane cuts (the input surfaces, see
`Mesh_complex_3`) becomes a line in the colour of its surface patch. A
legend names the regions. Cells and facets that only touch the plane are
left out.

The picture is in the plane's own frame: for a plane that is not
horizontal, up in the picture is the direction of +z projected onto the
plane, and right is normal x up; a horizontal plane is seen from the side its
normal points to, x to the right. The scale is the same in both directions.

\tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3` with integral subdomain
  and surface patch indices, such as `Mesh_complex_3`
\tparam Plane_3 the plane type of the triangulation's kernel

\param os the output stream
\param c3t3 the mesh
\param plane the cutting plane
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{svg_width}
    \cgalParamDescription{width of the picture in pixels; the height follows from the section's extent}
    \cgalParamType{double}
    \cgalParamDefault{900}
  \cgalParamNEnd
  \cgalParamNBegin{svg_title}
    \cgalParamDescription{a title drawn above the section}
    \cgalParamType{std::string}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{draw_cell_edges}
    \cgalParamDescription{whether the outline of each cut cell is drawn (the mesh's edges in the plane)}
    \cgalParamType{bool}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{region_names}
    \cgalParamDescription{the legend's names, entry `r` for region `r` (for instance the names of the
      model's regions)}
    \cgalParamType{std::vector<std::string>}
    \cgalParamDefault{"region 1", "region 2", ...}
  \cgalParamNEnd
  \cgalParamNBegin{highlight_dihedral_below}
    \cgalParamDescription{cut cells whose smallest dihedral angle is under this many degrees are drawn in
      magenta (a colour no region or surface has), and the legend counts them, so that a user sees where
      the poor tetrahedra are}
    \cgalParamType{double}
    \cgalParamDefault{0 (none)}
  \cgalParamNEnd
  \cgalParamNBegin{section_bubbles}
    \cgalParamDescription{bubbles drawn over the cells: every ball the plane cuts, as the circle of the
      cut, filled with its region's colour (surface bubbles in grey)}
    \cgalParamType{`const std::vector<Bubble<K> >*`}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\sa `write_svg_bubble_section()`
*/
template <class C3T3, class Plane_3, class NamedParameters = CGAL::parameters::Default_named_parameters>
void write_svg_section(std::ostream& os, const C3T3& c3t3, const Plane_3& plane,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Bare_point Point;
  const Tr& tr = c3t3.triangulation();
  const auto bare = tr.geom_traits().construct_point_3_object();
  internal::Svg_section_canvas canvas = internal::cell_section_canvas(plane, np);
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    std::array<Point, 4> p;
    for(int i = 0; i < 4; ++i) p[std::size_t(i)] = bare(tr.point(c, i));
    canvas.add_tetrahedron(p, int(c3t3.subdomain_index(c)));
  }
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    std::array<Point, 3> p;
    for(int i = 0, k = 0; i < 4; ++i)
      if(i != f->second) p[std::size_t(k++)] = bare(tr.point(f->first, i));
    canvas.add_facet(canvas.cut(p), int(c3t3.surface_patch_index(*f)) - 1);
  }
  typedef typename CGAL::Kernel_traits<Plane_3>::Kernel K;
  const std::vector<Bubble<K> >* bubbles =
    choose_parameter(get_parameter(np, internal_np::section_bubbles), (const std::vector<Bubble<K> >*)(nullptr));
  if(bubbles)
    for(const Bubble<K>& b : *bubbles)
      canvas.add_ball(b.center, b.radius, b.region == no_index ? 0 : int(b.region), b.is_fixed);
  internal::write_cell_section(os, canvas, np, std::vector<std::string>());
}

/*!
\ingroup PkgBubbleMesh3IO

Draws the plane section of a tetrahedral mesh read from a file (any mesher's,
see `IO::read_tet_mesh()`) as `write_svg_section()` above draws a complex:
cells by region label, boundary triangles by patch label, the legend named
by `mesh.region_names` unless `region_names` is given. The named parameters
are those above except `section_bubbles`.
*/
template <class Plane_3, class NamedParameters = CGAL::parameters::Default_named_parameters>
void write_svg_section(std::ostream& os, const Labeled_tetrahedral_mesh_3& mesh, const Plane_3& plane,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Svg_section_canvas canvas = internal::cell_section_canvas(plane, np);
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
  {
    std::array<std::array<double, 3>, 4> p;
    for(int i = 0; i < 4; ++i) p[std::size_t(i)] = mesh.points[mesh.tetrahedra[t][std::size_t(i)]];
    canvas.add_tetrahedron(p, t < mesh.regions.size() ? mesh.regions[t] : 0);
  }
  for(std::size_t f = 0; f < mesh.boundary_triangles.size(); ++f)
  {
    std::array<std::array<double, 3>, 3> p;
    for(int i = 0; i < 3; ++i) p[std::size_t(i)] = mesh.points[mesh.boundary_triangles[f][std::size_t(i)]];
    canvas.add_facet(canvas.cut(p), f < mesh.boundary_patches.size() ? mesh.boundary_patches[f] - 1 : 0);
  }
  std::vector<std::string> names;
  for(const auto& rn : mesh.region_names)
    if(rn.first >= 0)
    {
      if(names.size() <= std::size_t(rn.first)) names.resize(std::size_t(rn.first) + 1);
      names[std::size_t(rn.first)] = rn.second;
    }
  internal::write_cell_section(os, canvas, np, names);
}

/*!
\ingroup PkgBubbleMesh3IO

Draws bubbles on a plane section of a geological model as an SVG picture,
before any mesh exists (for instance after `place_initial_bubbles()` and
after `relax_bubbles()`): every input triangle the plane cuts becomes a line
in the colour of its patch, every bubble whose ball the plane cuts becomes
the circle of the cut, filled with the colour of its region (as in
`write_svg_section()`), surface bubbles in grey. The frame is that of
`write_svg_section()`, so that pictures of one plane can be laid side by side.

\param os the output stream
\param model the geological model
\param bubbles the bubbles, surface and interior ones in any order
\param plane the cutting plane
\param np optional named parameters among `svg_width` and `svg_title` (see
  `write_svg_section()`); the legend uses the model's region names.
*/
template <class GeomTraits, class NamedParameters = CGAL::parameters::Default_named_parameters>
void write_svg_bubble_section(std::ostream& os, const Geological_model_3<GeomTraits>& model,
                              const std::vector<Bubble<GeomTraits> >& bubbles,
                              const typename GeomTraits::Plane_3& plane,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GeomTraits::Point_3 Point;
  internal::Svg_section_canvas canvas(plane);
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& tri = model.triangle(t);
    const std::array<Point, 3> p = {{model.point(tri[0]), model.point(tri[1]), model.point(tri[2])}};
    canvas.add_facet(canvas.cut(p), int(model.patch_of_triangle(t)));
  }
  for(const Bubble<GeomTraits>& b : bubbles)
    canvas.add_ball(b.center, b.radius, b.region == no_index ? 0 : int(b.region), b.is_fixed);
  std::vector<std::string> names(model.number_of_regions() + 1);
  for(std::size_t r = 1; r <= model.number_of_regions(); ++r) names[r] = model.region(r).name;
  canvas.write(os, choose_parameter(get_parameter(np, internal_np::svg_width), 900.),
               choose_parameter(get_parameter(np, internal_np::svg_title), std::string()), false, names);
}

} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_WRITE_SVG_SECTION_H
