// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Meshes a model given as CGAL::Surface_mesh bodies and writes the mesh in
// every format the package writes.
//
// The model: a "core" ball inside a "mantle" shell. Each body is given by its
// closed surface; the core's surface is also the mantle's inner boundary (the
// same triangles, reversed), which makes it the interface of the two regions.
//
// Usage: mesh_surface_mesh_bodies [output_basename]
// Writes output_basename (default "core_and_mantle") with the extensions
// .mesh (Medit), .vtu (VTK), .msh (Gmsh), .node/.ele/.face (TetGen),
// .inp (Abaqus) and .f3grid (FLAC3D).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <CGAL/Bubble_mesh_3/IO/read_face_graphs.h>
#include <CGAL/Bubble_mesh_3/IO/write_mesh.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>
#include <CGAL/make_bubble_mesh_3.h>

#include <cassert>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
namespace BM = CGAL::Bubble_mesh_3;
namespace PMP = CGAL::Polygon_mesh_processing;

// A triangulated sphere: an icosahedron refined twice (320 triangles), its
// points pushed back onto the sphere.
Surface_mesh sphere(double radius)
{
  Surface_mesh sm;
  CGAL::make_icosahedron(sm, Point_3(0, 0, 0), radius);
  CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(2));
  for(Surface_mesh::Vertex_index v : sm.vertices())
  {
    const K::Vector_3 d = sm.point(v) - CGAL::ORIGIN;
    sm.point(v) = CGAL::ORIGIN + d * (radius / std::sqrt(d.squared_length()));
  }
  return sm;
}

int main(int argc, char** argv)
{
  const std::string base = argc > 1 ? argv[1] : "core_and_mantle";

  // 1. The bodies, outward oriented. The mantle is the big sphere plus the
  //    core's sphere turned inside out (its cavity).
  const Surface_mesh core = sphere(1.);
  Surface_mesh mantle = sphere(2.);
  Surface_mesh cavity = core;
  PMP::reverse_face_orientations(cavity);
  CGAL::copy_face_graph(cavity, mantle);

  // 2. The geological model: region 1 "core", region 2 "mantle". A triangle
  //    found in both bodies is their interface.
  BM::Geological_model_3<K> model;
  BM::geological_model_from_face_graphs(std::vector<Surface_mesh>{core, mantle}, model,
                                        std::vector<std::string>{"core", "mantle"});
  BM::validate_geological_model(model); // throws Geological_model_error on a bad model
  std::cout << "model: " << model.number_of_regions() << " regions, " << model.number_of_triangles()
            << " triangles\n";

  // 3. Mesh it. The report tells what every stage did.
  BM::Mesh_complex_3<K> c3t3;
  BM::Bubble_mesh_report report;
  BM::make_bubble_mesh_3(model, c3t3, BM::parameters::bubble_mesh_report(&report));
  std::cout << "mesh: " << c3t3.number_of_cells_in_complex() << " tetrahedra, "
            << report.number_of_relaxed_bubbles << " interior bubbles\n";

  // The input surfaces are kept: each region of the mesh has the volume of its body.
  const std::vector<double> volumes = BM::region_volumes(model);
  std::vector<double> mesh_volumes(model.number_of_regions() + 1, 0.);
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    mesh_volumes[std::size_t(c3t3.subdomain_index(c))] += c3t3.triangulation().tetrahedron(c).volume();
  for(std::size_t r = 1; r <= model.number_of_regions(); ++r)
  {
    std::cout << "  " << model.region_label(r) << ": volume " << mesh_volumes[r] << " (bodies: " << volumes[r] << ")\n";
    assert(std::abs(mesh_volumes[r] - volumes[r]) <= 1e-9 * volumes[r]);
  }

  // 4. Write the mesh with every writer; write_mesh() picks it by extension
  //    (write_medit(), write_vtu(), write_gmsh_msh(), write_tetgen(),
  //    write_abaqus_inp(), write_flac3d_f3grid() can also be called directly).
  for(const char* ext : {".mesh", ".vtu", ".msh", ".node", ".inp", ".f3grid"})
  {
    const std::string file = base + ext;
    BM::IO::write_mesh(file, c3t3, model);
    std::ifstream in(file);
    assert(in && in.peek() != std::ifstream::traits_type::eof());
    std::cout << "wrote " << file << "\n";
  }
  return EXIT_SUCCESS;
}
