// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Meshes a multi-body GOCAD Model3d (.ml) file stage by stage, calling each
// free function that make_bubble_mesh_3() chains, with the last region made
// denser through the sizing field, then writes the quality report of the
// mesh as text, JSON and SVG histograms.
//
// Usage: mesh_gocad_model [model.ml|.ts|.obj] [output_basename]
// Default: data/two_layers_and_fault.ml (two layers, a fault ending inside
// the upper one), output basename "gocad_model". Writes BASE.vtu,
// BASE_quality.txt, BASE_quality.json and BASE_quality.svg.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/IO/write_mesh.h>
#include <CGAL/Bubble_mesh_3/IO/write_quality_report.h>
#include <CGAL/Bubble_mesh_3/IO/write_svg_histograms.h>
#include <CGAL/Bubble_mesh_3/geological_model_summary.h>
#include <CGAL/Bubble_mesh_3/mesh_quality.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>
#include <CGAL/Bubble_mesh_3/relax_bubbles.h>
#include <CGAL/Bubble_mesh_3/remove_slivers.h>
#include <CGAL/Bubble_mesh_3/Surface_bubble_sizing_field.h>
#include <CGAL/Bubble_mesh_3/tetrahedralize_bubbles.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>

#include <cassert>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Bubble<K> Bubble;
namespace BM = CGAL::Bubble_mesh_3;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : "data/two_layers_and_fault.ml";
  const std::string base = argc > 2 ? argv[2] : "gocad_model";
  try
  {
    // Read (the reader follows the extension) and check the model: closed,
    // conforming, non-intersecting surfaces, regions consistent.
    BM::Geological_model_3<K> model;
    BM::IO::read_geological_model(input, model);
    BM::validate_geological_model(model);
    BM::write_summary_text(std::cout, BM::summarize_geological_model(model));

    // Stage 1: one fixed bubble on every model point; their radii define the
    // sizing field of the interior bubbles. Here the last region is wanted
    // denser than its surfaces imply: its bubble radii are scaled by 0.6.
    const std::vector<Bubble> surface = BM::place_surface_bubbles(model);
    std::vector<double> scale(model.number_of_regions() + 1, 1.);
    scale.back() = 0.6;
    const BM::Surface_bubble_sizing_field<K> sizing(model, surface, BM::parameters::region_scale_factors(scale));

    // Stage 2: k-means clustering of each region's surface points, then
    // initial interior bubbles on a lattice per cluster.
    std::vector<Bubble> interior = BM::place_initial_bubbles(model, surface, sizing,
                                                             CGAL::parameters::random_seed(0));
    const std::size_t initial = interior.size();

    // Stages 3 and 4: relaxation with population control (bubbles are added
    // or removed where the overlap ratio says the packing is too sparse or
    // too dense). The result does not depend on the number of threads.
    const BM::Relaxation_report relaxation = BM::relax_bubbles(model, surface, interior, sizing);
    std::cout << initial << " initial interior bubbles, " << interior.size() << " after relaxation ("
              << relaxation.steps << " steps)\n";

    // Stage 5: conforming Delaunay tetrahedralization of all bubble centres;
    // every input triangle is recovered, cells are labelled by region.
    std::vector<K::Point_3> centres;
    for(const Bubble& b : interior) centres.push_back(b.center);
    BM::Mesh_complex_3<K> c3t3;
    const BM::Tetrahedralization_report tr = BM::tetrahedralize_bubbles(model, centres, c3t3);

    // Stage 6: move interior vertices of slivers (surfaces never move).
    const BM::Sliver_removal_report sr = BM::remove_slivers(c3t3);
    std::cout << c3t3.number_of_cells_in_complex() << " tetrahedra; smallest dihedral angle "
              << sr.min_dihedral_angle_before << " -> " << sr.min_dihedral_angle_after << " degrees\n";

    // The quality report: per region and for the whole model, with the
    // histograms of aspect ratio, face angles and dihedral angles.
    BM::Mesh_quality_report quality = BM::compute_c3t3_quality(c3t3,
      BM::parameters::number_of_steiner_points(tr.number_of_steiner_points(),
      BM::parameters::number_of_input_triangles(model.number_of_triangles(),
      BM::parameters::number_of_input_triangles_kept_whole(tr.number_of_triangles_kept_whole))));
    quality.name = input;
    for(BM::Region_quality& q : quality.regions) // name the regions as the model does
      if(q.region >= 1 && std::size_t(q.region) <= model.number_of_regions())
        q.name = model.region(std::size_t(q.region)).name;

    BM::IO::write_quality_report_text(std::cout, quality);
    {
      std::ofstream txt(base + "_quality.txt"), json(base + "_quality.json"), svg(base + "_quality.svg");
      BM::IO::write_quality_report_text(txt, quality);
      BM::IO::write_quality_report_json(json, quality);
      BM::IO::write_svg_histograms(svg, quality);
      assert(txt && json && svg);
    }
    BM::IO::write_mesh(base + ".vtu", c3t3, model);

    // Checks: every region is meshed, no tetrahedron is flat or inverted.
    assert(quality.all.number_of_tetrahedra == c3t3.number_of_cells_in_complex());
    assert(quality.all.number_of_degenerate_tetrahedra == 0);
    assert(quality.all.number_of_negatively_oriented_tetrahedra == 0);
    std::size_t meshed_regions = 0;
    for(const BM::Region_quality& q : quality.regions) meshed_regions += (q.number_of_tetrahedra > 0);
    assert(meshed_regions == model.number_of_regions());
    // the denser region has smaller tetrahedra on average than the first one
    const BM::Region_quality& first = quality.regions.front();
    const BM::Region_quality& denser = quality.regions.back();
    std::cout << "mean tetrahedron volume: " << first.volume / double(first.number_of_tetrahedra) << " in region "
              << first.region << ", " << denser.volume / double(denser.number_of_tetrahedra) << " in region "
              << denser.region << " (radii x 0.6)\n";
    assert(model.number_of_regions() < 2 ||
           denser.volume / double(denser.number_of_tetrahedra) < first.volume / double(first.number_of_tetrahedra));
    std::cout << "wrote " << base << ".vtu and " << base << "_quality.{txt,json,svg}\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "mesh_gocad_model: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
