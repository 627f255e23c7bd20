// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Draws plane sections as SVG pictures: the bubbles of a model on a vertical
// plane before and after relaxation, then the mesh on the same plane, cells
// coloured by region and input surfaces drawn as lines. The manual's figures
// (doc/Bubble_mesh_3/fig/) are made with this program:
//
//   draw_mesh_sections examples/Bubble_mesh_3/data/layered_model.obj doc/Bubble_mesh_3/fig
//
// Usage: draw_mesh_sections [model.ml|.ts|.obj] [output_folder] [y]
// The plane is y = const, through the middle of the model unless given.
// Without a model the default layered model is generated. Writes
// bubbles_initial.svg, bubbles_relaxed.svg and mesh_section.svg.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/IO/write_svg_section.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/make_layered_model.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>
#include <CGAL/Bubble_mesh_3/relax_bubbles.h>
#include <CGAL/Bubble_mesh_3/Surface_bubble_sizing_field.h>
#include <CGAL/Bubble_mesh_3/tetrahedralize_bubbles.h>

#include <cassert>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Bubble<K> Bubble;
namespace BM = CGAL::Bubble_mesh_3;

static std::size_t count(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

// writes `svg` to `folder/name` and returns it, for the checks
static std::string save(const std::string& folder, const std::string& name, const std::ostringstream& svg)
{
  std::ofstream(folder + "/" + name) << svg.str();
  std::cout << "wrote " << folder << "/" << name << "\n";
  return svg.str();
}

int main(int argc, char** argv)
{
  try
  {
    BM::Geological_model_3<K> model;
    if(argc > 1) BM::IO::read_geological_model(argv[1], model);
    else BM::make_layered_model(model);
    const std::string folder = argc > 2 ? argv[2] : ".";
    std::filesystem::create_directories(folder);
    const CGAL::Bbox_3 box = BM::bbox(model);
    const double y = argc > 3 ? std::stod(argv[3]) : 0.5 * (box.ymin() + box.ymax());
    const K::Plane_3 plane(K::Point_3(0, y, 0), K::Vector_3(0, 1, 0)); // seen from +y: x right, z up

    // the stages, as make_bubble_mesh_3() runs them
    const std::vector<Bubble> surface = BM::place_surface_bubbles(model);
    const BM::Surface_bubble_sizing_field<K> sizing(model, surface);
    std::vector<Bubble> interior = BM::place_initial_bubbles(model, surface, sizing);

    std::vector<Bubble> all = surface;
    all.insert(all.end(), interior.begin(), interior.end());
    std::ostringstream before;
    BM::IO::write_svg_bubble_section(before, model, all, plane,
                                     BM::parameters::svg_title("Initial bubbles, plane y = " + std::to_string(int(y))));
    const std::string before_svg = save(folder, "bubbles_initial.svg", before);

    BM::relax_bubbles(model, surface, interior, sizing);
    all = surface;
    all.insert(all.end(), interior.begin(), interior.end());
    std::ostringstream after;
    BM::IO::write_svg_bubble_section(after, model, all, plane,
                                     BM::parameters::svg_title("Relaxed bubbles, plane y = " + std::to_string(int(y))));
    const std::string after_svg = save(folder, "bubbles_relaxed.svg", after);

    std::vector<K::Point_3> centres;
    for(const Bubble& b : interior) centres.push_back(b.center);
    BM::Mesh_complex_3<K> c3t3;
    BM::tetrahedralize_bubbles(model, centres, c3t3);

    std::vector<std::string> names(model.number_of_regions() + 1);
    for(std::size_t r = 1; r <= model.number_of_regions(); ++r) names[r] = model.region(r).name;
    std::ostringstream section;
    BM::IO::write_svg_section(section, c3t3, plane,
                              BM::parameters::region_names(names,
                              BM::parameters::svg_title("Mesh section, plane y = " + std::to_string(int(y)))));
    const std::string section_svg = save(folder, "mesh_section.svg", section);

    // Checks: the plane cuts cells, surfaces and bubbles, and the legend names
    // every region the plane crosses in the mesh.
    const std::size_t cells = count(section_svg, "class=\"cell\""), lines = count(section_svg, "class=\"surface\"");
    std::cout << "section: " << cells << " cut cells, " << lines << " surface segments; bubbles cut: "
              << count(before_svg, "class=\"bubble\"") << " before, " << count(after_svg, "class=\"bubble\"")
              << " after relaxation\n";
    assert(cells > 0 && lines > 0);
    assert(count(before_svg, "class=\"bubble\"") > 0 && count(after_svg, "class=\"bubble\"") > 0);
    assert(count(before_svg, "class=\"surface\"") == count(after_svg, "class=\"surface\""));
    for(std::size_t r = 1; r <= model.number_of_regions() && r <= 10; ++r) // colours repeat after ten
      if(count(section_svg, "class=\"cell\" fill=\"" +
                              std::string(BM::IO::internal::Svg_section_canvas::region_color(int(r)))) > 0)
        assert(section_svg.find(">" + names[r] + "<") != std::string::npos);
  }
  catch(const std::exception& e)
  {
    std::cerr << "draw_mesh_sections: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
