// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Generates the package's synthetic layered model (layers, a thin layer, a
// through-going fault and a small fault inside a layer) and writes it as a
// multi-body OBJ file. The bundled examples/Bubble_mesh_3/data/layered_model.obj
// is this program's output with the default parameters.

#include <CGAL/Bubble_mesh_3/make_layered_model.h>
#include <CGAL/Bubble_mesh_3/geological_model_summary.h>
#include <CGAL/Bubble_mesh_3/IO/write_multibody_obj.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K> Model;

namespace {

void usage(std::ostream& os, const CGAL::Bubble_mesh_3::Layered_model_parameters& d)
{
  os << "Usage: generate_layered_model [options]\n"
        "Writes a synthetic geological model: ordinary layers and a thin layer bounded by\n"
        "undulating horizons, a fault through the whole box that offsets them, and a small\n"
        "fault that ends inside the top layer of the hanging wall.\n\n"
        "Options:\n"
        "  --size X Y Z     box size, z up (default " << d.size_x << " " << d.size_y << " " << d.size_z << ")\n"
        "  --h EDGE         target edge length of the triangles (default 0.2 * Z)\n"
        "  --layers N       number of ordinary layers, at least 2; the thin layer comes\n"
        "                   in addition (default " << d.number_of_layers << ")\n"
        "  --dip DEGREES    dip of the fault, 60 to 90 (default " << d.fault_dip << ")\n"
        "  --min-angle DEG  angle bound of the surface meshing, at most 33 (default " << d.min_angle << ")\n"
        "  --seed S         seed of the undulations (default " << d.seed << ")\n"
        "  --no-small-fault leave out the small fault\n"
        "  -o FILE          output file (default layered_model.obj)\n"
        "  -h, --help       this help\n";
}

} // namespace

int main(int argc, char** argv)
{
  CGAL::Bubble_mesh_3::Layered_model_parameters p;
  std::string output = "layered_model.obj";
  try
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      auto value = [&](int k) -> std::string {
        if(i + k >= argc) throw std::invalid_argument("option " + a + " needs " + std::to_string(k) + " value(s)");
        return argv[i + k];
      };
      auto number = [&](int k) {
        const std::string s = value(k);
        std::size_t used = 0;
        const double v = std::stod(s, &used);
        if(used != s.size()) throw std::invalid_argument("option " + a + ": '" + s + "' is not a number");
        return v;
      };
      if(a == "-h" || a == "--help") { usage(std::cout, p); return EXIT_SUCCESS; }
      else if(a == "--size") { p.size_x = number(1); p.size_y = number(2); p.size_z = number(3); i += 3; }
      else if(a == "--h") { p.edge_length = number(1); ++i; }
      else if(a == "--layers")
      {
        const double n = number(1);
        if(n < 0 || n != std::floor(n)) throw std::invalid_argument("--layers needs a whole number");
        p.number_of_layers = std::size_t(n);
        ++i;
      }
      else if(a == "--dip") { p.fault_dip = number(1); ++i; }
      else if(a == "--min-angle") { p.min_angle = number(1); ++i; }
      else if(a == "--seed")
      {
        const double s = number(1);
        if(s < 0 || s != std::floor(s) || s > 4294967295.) throw std::invalid_argument("--seed needs a whole number >= 0");
        p.seed = static_cast<unsigned int>(s);
        ++i;
      }
      else if(a == "--no-small-fault") p.small_fault = false;
      else if(a == "-o") { output = value(1); ++i; }
      else throw std::invalid_argument("unknown option '" + a + "' (see --help)");
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "generate_layered_model: " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  try
  {
    Model model;
    CGAL::Bubble_mesh_3::make_layered_model(model, p);
    CGAL::Bubble_mesh_3::write_summary_text(std::cout, CGAL::Bubble_mesh_3::summarize_geological_model(model));
    CGAL::Bubble_mesh_3::IO::write_multibody_obj(output, model);
    std::cout << "wrote " << output << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "generate_layered_model: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
