// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Stages 1 and 2: the fixed surface bubbles and the initial interior bubbles
// of a geological model, written as a legacy VTK point set with the point
// data `radius`, `region` (0 for surface bubbles) and `fixed` (in ParaView:
// Glyph filter, sphere, scale by `radius`, scale factor 2).
//
// Usage: place_initial_bubbles [model.ml|.ts|.obj] [out.vtk] [cell_edge_factor] [seed]
// Without a model, the package's default layered model is generated.

#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/make_layered_model.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>

#include <cstdlib>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Bubble<K> Bubble;
namespace BM = CGAL::Bubble_mesh_3;

static void write_vtk(const std::string& file, const std::vector<Bubble>& bubbles)
{
  std::ofstream os(file);
  os << std::setprecision(17);
  os << "# vtk DataFile Version 3.0\nbubbles (centre, radius, region, fixed)\nASCII\nDATASET POLYDATA\nPOINTS "
     << bubbles.size() << " double\n";
  for(const Bubble& b : bubbles) os << b.center.x() << ' ' << b.center.y() << ' ' << b.center.z() << '\n';
  os << "VERTICES " << bubbles.size() << ' ' << 2 * bubbles.size() << '\n';
  for(std::size_t i = 0; i < bubbles.size(); ++i) os << "1 " << i << '\n';
  os << "POINT_DATA " << bubbles.size() << "\nSCALARS radius double 1\nLOOKUP_TABLE default\n";
  for(const Bubble& b : bubbles) os << b.radius << '\n';
  os << "SCALARS region int 1\nLOOKUP_TABLE default\n";
  for(const Bubble& b : bubbles) os << (b.region == BM::no_index ? 0 : b.region) << '\n';
  os << "SCALARS fixed int 1\nLOOKUP_TABLE default\n";
  for(const Bubble& b : bubbles) os << (b.is_fixed ? 1 : 0) << '\n';
  if(!os) throw std::runtime_error("cannot write " + file);
}

int main(int argc, char** argv)
{
  try
  {
    BM::Geological_model_3<K> model;
    if(argc > 1) BM::IO::read_geological_model(argv[1], model);
    else BM::make_layered_model(model);
    const std::string out = argc > 2 ? argv[2] : "initial_bubbles.vtk";
    const double cell_edge_factor = argc > 3 ? std::stod(argv[3]) : 1.;
    const unsigned int seed = argc > 4 ? unsigned(std::stoul(argv[4])) : 0u;

    CGAL::Real_timer timer;
    timer.start();
    const std::vector<Bubble> surface = BM::place_surface_bubbles(model);
    std::cout << surface.size() << " surface bubbles (" << timer.time() << " s)\n";

    timer.reset();
    std::vector<BM::Region_placement_statistics> stats;
    const std::vector<Bubble> interior = BM::place_initial_bubbles(
      model, surface,
      BM::parameters::placement_statistics(&stats, BM::parameters::cell_edge_factor(cell_edge_factor).random_seed(seed)));
    std::cout << interior.size() << " initial interior bubbles (" << timer.time() << " s)\n";
    for(std::size_t r = 1; r < stats.size(); ++r)
    {
      const BM::Region_placement_statistics& s = stats[r];
      std::cout << "  " << model.region_label(r) << ": " << s.number_of_surface_points << " surface points, k = "
                << s.number_of_clusters << ", cell edge " << s.cell_edge << ", " << s.number_of_cells << " cells ("
                << s.rejected_outside << " outside, " << s.rejected_near_surface << " too near a surface), "
                << s.number_of_bubbles << " bubbles\n";
    }

    std::vector<Bubble> all = surface;
    all.insert(all.end(), interior.begin(), interior.end());
    write_vtk(out, all);
    std::cout << "wrote " << all.size() << " bubbles to " << out << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "place_initial_bubbles: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
