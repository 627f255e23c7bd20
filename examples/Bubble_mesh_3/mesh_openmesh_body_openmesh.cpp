// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Meshes a body given as an OpenMesh triangle mesh (built only when OpenMesh
// is found). OpenMesh meshes are CGAL face graphs through
// <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>, so
// geological_model_from_face_graphs() reads them like CGAL::Surface_mesh.
//
// Usage: mesh_openmesh_body_openmesh [output.mesh|.vtu|.msh|.node|.inp|.f3grid]
// (default cube.vtu)

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bubble_mesh_3/IO/read_face_graphs.h>
#include <CGAL/Bubble_mesh_3/IO/write_mesh.h>
#include <CGAL/Bubble_mesh_3/mesh_quality.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>
#include <CGAL/make_bubble_mesh_3.h>

#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace BM = CGAL::Bubble_mesh_3;

// Double precision points: OpenMesh's default (float) loses digits of real
// coordinates.
struct Double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::TriMesh_ArrayKernelT<Double_traits> Mesh;

// The surface of the cube [0,size]^3, each face an n x n grid of squares split
// into two triangles, oriented outward.
Mesh cube(double size, int n)
{
  Mesh m;
  std::map<std::array<int, 3>, Mesh::VertexHandle> vertex;
  auto at = [&](std::array<int, 3> c) {
    auto it = vertex.find(c);
    if(it != vertex.end()) return it->second;
    const Mesh::VertexHandle v = m.add_vertex(Mesh::Point(size * c[0] / n, size * c[1] / n, size * c[2] / n));
    return vertex[c] = v;
  };
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side <= n; side += n)
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j)
        {
          // corners of the square (i, j) on the face; axes a and b span the face
          const int a = (axis + 1) % 3, b = (axis + 2) % 3;
          std::array<int, 3> c00{}, c10{}, c11{}, c01{};
          for(std::array<int, 3>* c : {&c00, &c10, &c11, &c01}) (*c)[axis] = side;
          c00[a] = i;     c00[b] = j;
          c10[a] = i + 1; c10[b] = j;
          c11[a] = i + 1; c11[b] = j + 1;
          c01[a] = i;     c01[b] = j + 1;
          // (a, b, axis) is right-handed: counter-clockwise in (a, b) points to +axis
          if(side == n) { m.add_face(at(c00), at(c10), at(c11)); m.add_face(at(c00), at(c11), at(c01)); }
          else          { m.add_face(at(c00), at(c11), at(c10)); m.add_face(at(c00), at(c01), at(c11)); }
        }
  return m;
}

int main(int argc, char** argv)
{
  const std::string output = argc > 1 ? argv[1] : "cube.vtu";
  const double size = 100.;

  BM::Geological_model_3<K> model;
  BM::geological_model_from_face_graphs(std::vector<Mesh>{cube(size, 6)}, model, std::vector<std::string>{"cube"});
  BM::validate_geological_model(model);

  BM::Mesh_complex_3<K> c3t3;
  BM::make_bubble_mesh_3(model, c3t3);
  const BM::Mesh_quality_report quality = BM::compute_c3t3_quality(c3t3);
  std::cout << "cube: " << quality.all.number_of_tetrahedra << " tetrahedra, volume " << quality.all.volume
            << ", smallest dihedral angle " << quality.all.min_dihedral_angle << " degrees\n";
  BM::IO::write_mesh(output, c3t3, model);
  std::cout << "wrote " << output << "\n";

  // the surface is kept: the tetrahedra fill the cube exactly, none is inverted
  assert(std::abs(quality.all.volume - size * size * size) <= 1e-9 * size * size * size);
  assert(quality.all.number_of_negatively_oriented_tetrahedra == 0);
  return EXIT_SUCCESS;
}
