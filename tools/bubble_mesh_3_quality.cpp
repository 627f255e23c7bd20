// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// bubble_mesh_3_quality: the quality report of tetrahedral meshes written by
// any mesher (this package, TetGen, Gmsh, ...), alone or side by side.

#include <CGAL/Bubble_mesh_3/mesh_quality.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>
#include <CGAL/Bubble_mesh_3/IO/read_tet_mesh.h>
#include <CGAL/Bubble_mesh_3/IO/write_quality_report.h>
#include <CGAL/Bubble_mesh_3/IO/write_svg_histograms.h>
#include <CGAL/Bubble_mesh_3/IO/write_svg_section.h>
#include <CGAL/Simple_cartesian.h>

#include "section_plane.h"

#include <algorithm>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace BM = CGAL::Bubble_mesh_3;

namespace {

const char* usage =
  "Usage: bubble_mesh_3_quality MESH [MESH2 ...] [--json FILE] [--svg FILE] [--names A,B,...]\n"
  "                             [--worst N] [--section-svg FILE [--section AXIS=V]]\n"
  "\n"
  "Reads labelled tetrahedral meshes and reports their quality per region and for\n"
  "the whole model: tet and vertex counts, volume, dihedral angles (min, max, mean,\n"
  "mean smallest, % of tets whose smallest dihedral is under 5/10/15/20 degrees),\n"
  "face angles, aspect ratio (longest edge / shortest altitude: 1.2247 for the\n"
  "regular tetrahedron; the paper's 0.81 is the reciprocal) with its median and\n"
  "the % above 10 and 40, and the worst tetrahedra with their location.\n"
  "With several meshes: one column per mesh, and their histograms side by side.\n"
  "\n"
  "Formats (by extension):\n"
  "  .mesh        Medit ASCII; tetrahedron reference = region, triangles = surfaces\n"
  "  .msh         Gmsh ASCII 4.1 or 2.2; region = physical tag (entity tag without one)\n"
  "  .node, .ele  TetGen (B.node + B.ele [+ B.face]); region = first tet attribute (-A)\n"
  "  .vtu         VTK XML, ascii / base64 / raw appended; region = cell array MeshDomain,\n"
  "               gmsh:physical, CellEntityIds, cell_scalars, ... or the first one\n"
  "  .vtk         legacy VTK ASCII (Gmsh, TetGen -k)\n"
  "\n"
  "Options:\n"
  "  --json FILE     write the report(s) as JSON\n"
  "  --svg FILE      write the aspect-ratio, face-angle and dihedral-angle histograms\n"
  "                  (one curve per region, or one per mesh with several meshes)\n"
  "  --names A,B     names of the meshes in tables and pictures (default: file names)\n"
  "  --worst N       how many worst tetrahedra to list (default 10)\n"
"  --section-svg FILE  draw a section of each mesh (one above the other): the cut\n"
"                  tetrahedra coloured by region, those with a dihedral angle under\n"
"                  10 degrees in magenta, boundary triangles as lines; by default a\n"
"                  vertical plane through the middle of the meshes along their\n"
"                  longer horizontal side\n"
"  --section AXIS=V  the plane of --section-svg: x=V, y=V (vertical) or z=V\n"
"                  (horizontal, seen from above)\n"
  "  -h, --help      this help\n"
  "\n"
  "Exit status: 0 on success, 1 when a file cannot be read or written, 2 on bad usage.\n";

int usage_error(const std::string& what)
{
  std::cerr << "bubble_mesh_3_quality: " << what << "\n(see bubble_mesh_3_quality --help)\n";
  return 2;
}

std::vector<std::string> split(const std::string& s, char sep)
{
  std::vector<std::string> r;
  std::string item;
  std::istringstream is(s);
  while(std::getline(is, item, sep)) r.push_back(item);
  return r;
}

// writes through a temporary name so that a failed run leaves no half file
template <class Write>
bool write_file(const std::string& filename, Write write)
{
  try
  {
    BM::IO::internal::write_atomically(filename, write);
  }
  catch(const std::exception& e)
  {
    std::cerr << "bubble_mesh_3_quality: error: " << e.what() << "\n";
    return false;
  }
  return true;
}

// the pictures one above the other in one picture (each a nested <svg> element)
void write_stacked_svg(std::ostream& os, const std::vector<std::string>& parts)
{
  auto attribute = [](const std::string& svg, const std::string& name) {
    const std::size_t at = svg.find(" " + name + "=\"");
    return at == std::string::npos ? 0. : std::atof(svg.c_str() + at + name.size() + 3);
  };
  double width = 0., height = 0.;
  for(const std::string& p : parts)
  {
    width = (std::max)(width, attribute(p, "width"));
    height += attribute(p, "height");
  }
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
     << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n";
  double y = 0.;
  for(const std::string& p : parts)
  {
    os << "<svg x=\"0\" y=\"" << y << "\" " << p.substr(5); // after "<svg "
    y += attribute(p, "height");
  }
  os << "</svg>\n";
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> meshes, names;
  std::string json, svg, section_svg;
  Section_choice section;
  bool section_given = false;
  std::size_t worst = 10;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if(i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    if(a == "-h" || a == "--help")
    {
      std::cout << usage;
      return EXIT_SUCCESS;
    }
    else if(a == "--json") { if(!value(json)) return usage_error("--json needs a file name"); }
    else if(a == "--svg") { if(!value(svg)) return usage_error("--svg needs a file name"); }
    else if(a == "--names")
    {
      std::string n;
      if(!value(n)) return usage_error("--names needs a comma-separated list");
      names = split(n, ',');
    }
    else if(a == "--worst")
    {
      std::string n;
      if(!value(n)) return usage_error("--worst needs a number");
      char* end = nullptr;
      const long v = std::strtol(n.c_str(), &end, 10);
      if(end == n.c_str() || *end != '\0' || v < 0) return usage_error("--worst: '" + n + "' is not a count");
      worst = std::size_t(v);
    }
    else if(a == "--section-svg") { if(!value(section_svg)) return usage_error("--section-svg needs a file name"); }
    else if(a == "--section")
    {
      std::string v;
      if(!value(v) || !parse_section_choice(v, section))
        return usage_error(std::string("--section takes ") + section_choice_syntax() + ", got '" + v + "'");
      section_given = true;
    }
    else if(a.size() > 1 && a[0] == '-')
      return usage_error("unknown option '" + a + "'");
    else
      meshes.push_back(a);
  }
  if(meshes.empty()) return usage_error("no mesh file given");
  if(section_given && section_svg.empty()) return usage_error("--section chooses the plane of --section-svg: give both");
  if(!names.empty() && names.size() != meshes.size())
    return usage_error("--names gives " + std::to_string(names.size()) + " names for " +
                       std::to_string(meshes.size()) + " meshes");

  std::vector<BM::Mesh_quality_report> reports;
  std::vector<BM::Labeled_tetrahedral_mesh_3> kept; // for the sections
  CGAL::Bbox_3 box;
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    try
    {
      BM::Labeled_tetrahedral_mesh_3 mesh = BM::IO::read_tet_mesh(meshes[i]);
      reports.push_back(BM::compute_mesh_quality(mesh, BM::parameters::number_of_worst_tetrahedra(worst)));
      reports.back().name = names.empty() ? meshes[i] : names[i];
      if(!section_svg.empty())
      {
        for(const auto& p : mesh.points) box += CGAL::Bbox_3(p[0], p[1], p[2], p[0], p[1], p[2]);
        kept.push_back(std::move(mesh));
      }
    }
    catch(const std::exception& e)
    {
      std::cerr << "bubble_mesh_3_quality: error: " << e.what() << "\n";
      return 1;
    }
  }

  // the section's plane, checked before anything is written
  CGAL::Simple_cartesian<double>::Plane_3 plane;
  std::string description;
  if(!section_svg.empty())
  {
    std::string error;
    if(!section_plane(box, section, plane, description, error))
    {
      std::cerr << "bubble_mesh_3_quality: " << error << "\n";
      return 2;
    }
  }

  if(reports.size() == 1) BM::IO::write_quality_report_text(std::cout, reports[0]);
  else BM::IO::write_quality_comparison_text(std::cout, reports);

  if(!json.empty() && !write_file(json, [&](std::ostream& os) {
       if(reports.size() == 1) BM::IO::write_quality_report_json(os, reports[0]);
       else BM::IO::write_quality_reports_json(os, reports);
     }))
    return 1;
  if(!svg.empty() && !write_file(svg, [&](std::ostream& os) {
       if(reports.size() == 1) BM::IO::write_svg_histograms(os, reports[0]);
       else BM::IO::write_svg_histogram_comparison(os, reports);
     }))
    return 1;
  if(!section_svg.empty())
  {
    std::vector<std::string> parts;
    for(std::size_t i = 0; i < kept.size(); ++i)
    {
      std::ostringstream part;
      BM::IO::write_svg_section(part, kept[i], plane,
                                BM::parameters::svg_title(reports[i].name + ": " + description,
                                BM::parameters::highlight_dihedral_below(10.)));
      parts.push_back(part.str());
    }
    if(!write_file(section_svg, [&](std::ostream& os) {
         if(parts.size() == 1) os << parts[0];
         else write_stacked_svg(os, parts);
       }))
      return 1;
  }
  return EXIT_SUCCESS;
}
