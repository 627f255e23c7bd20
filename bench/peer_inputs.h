// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Benchmark helpers (not part of the package): what the peer meshers need to
// mesh a geological model with its surfaces - a TetGen PLC (.poly) with patch
// markers and one seed point per region, TetGen's additional points (.a.node
// for -i), a Gmsh discrete mesh (.msh 4.1, one surface entity per patch) with
// the shells of each region - and the count of input triangles that a peer's
// mesh keeps whole. Used by bench/export_peer_inputs.cpp and
// bench/bench_tetrahedralization.cpp.

#ifndef CGAL_BUBBLE_MESH_3_BENCH_PEER_INPUTS_H
#define CGAL_BUBBLE_MESH_3_BENCH_PEER_INPUTS_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/mesh_quality.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>

#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <numeric>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace bench {

/// the file name of `path` without folder and extension ("a/b/model.ml" -> "model")
inline std::string base_name(const std::string& path)
{
  const std::size_t slash = path.find_last_of("/\\");
  std::string f = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = f.find_last_of('.');
  if(dot != std::string::npos && dot > 0) f = f.substr(0, dot);
  return f;
}

/// A point strictly inside one region, and how it was found.
template <class GeomTraits>
struct Region_seed
{
  typename GeomTraits::Point_3 point;
  bool found = false;
  std::size_t triangle = std::size_t(-1); ///< the boundary triangle it was stepped from
  double step = 0.;                       ///< distance from that triangle
};

/*!
One seed point per region (index 1 ... number_of_regions(); entry 0 unused):
from the centroid of one of the region's boundary triangles (largest first),
a step along the normal into the region, of the triangle's inradius or a
fraction of it, accepted when

- no triangle of the region (boundary or surface inside it) is closer to the
  point than the step (so the step crosses no surface and the point lies on
  none), and
- `CGAL::Side_of_triangle_mesh` on the region's boundary says ON_BOUNDED_SIDE

(both tests by `internal::Region_surfaces`, the inside and clearance tests
of `place_initial_bubbles()`).

A region without a seed (`found == false`) is reported by the caller.
*/
template <class GeomTraits>
std::vector<Region_seed<GeomTraits> > region_seed_points(const Geological_model_3<GeomTraits>& model,
                                                         std::size_t candidates_per_region = 200)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef typename GeomTraits::Triangle_3 Triangle_3;

  const std::size_t nr = model.number_of_regions();
  std::vector<Region_seed<GeomTraits> > seeds(nr + 1);
  for(std::size_t r = 1; r <= nr; ++r)
  {
    // the region's boundary (inside test) and all its triangles (distance), as placement uses them
    const internal::Region_surfaces<GeomTraits> surfaces(model, r);
    std::vector<std::pair<double, std::size_t> > by_area;
    for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    {
      const auto& patch = model.patch(model.patch_of_triangle(t));
      if(patch.is_inside_region() || (patch.positive_region != r && patch.negative_region != r)) continue;
      const auto& tri = model.triangle(t);
      by_area.emplace_back(
        std::sqrt(CGAL::to_double(CGAL::squared_area(model.point(tri[0]), model.point(tri[1]), model.point(tri[2])))),
        t);
    }
    if(by_area.empty()) continue;
    const std::size_t n = (std::min)(candidates_per_region, by_area.size());
    std::partial_sort(by_area.begin(), by_area.begin() + n, by_area.end(),
                      [](const auto& a, const auto& b) {
                        return a.first > b.first || (a.first == b.first && a.second < b.second);
                      });
    for(std::size_t k = 0; k < n && !seeds[r].found; ++k)
    {
      const std::size_t t = by_area[k].second;
      const auto& patch = model.patch(model.patch_of_triangle(t));
      const auto& ids = model.triangle(t);
      const Triangle_3 tri(model.point(ids[0]), model.point(ids[1]), model.point(ids[2]));
      Vector_3 normal = CGAL::cross_product(tri[1] - tri[0], tri[2] - tri[0]);
      const double len = std::sqrt(CGAL::to_double(normal.squared_length()));
      if(!(len > 0.)) continue;
      normal = normal / len;
      if(patch.negative_region == r) normal = -normal; // the normal points to the positive region
      const double perimeter = std::sqrt(CGAL::to_double(CGAL::squared_distance(tri[0], tri[1]))) +
                               std::sqrt(CGAL::to_double(CGAL::squared_distance(tri[1], tri[2]))) +
                               std::sqrt(CGAL::to_double(CGAL::squared_distance(tri[2], tri[0])));
      const double inradius = len / perimeter; // 2 * area / perimeter, with len = 2 * area
      const Point_3 c = CGAL::centroid(tri[0], tri[1], tri[2]);
      for(int halving = 0; halving < 6; ++halving)
      {
        const double d = inradius * std::ldexp(1., -halving);
        const Point_3 p = c + d * normal;
        // no triangle of r closer than the step: the step crosses no surface, p lies on none
        if(!(std::sqrt(surfaces.squared_distance(p)) >= d * (1. - 1e-6))) continue;
        if(!surfaces.is_inside(p)) continue;
        seeds[r].point = p;
        seeds[r].found = true;
        seeds[r].triangle = t;
        seeds[r].step = d;
        break;
      }
    }
  }
  return seeds;
}

inline void write_coordinate(std::ostream& os, double x)
{
  os << std::setprecision(17) << x;
}

/*!
Writes a TetGen PLC: every model point that a triangle uses (numbered from 1
in the model's order), one facet per triangle with boundary marker patch + 1,
no holes, and a region attribute (the region index) at each found seed.
*/
template <class GeomTraits>
void write_tetgen_poly(std::ostream& os, const Geological_model_3<GeomTraits>& model,
                       const std::vector<Region_seed<GeomTraits> >& seeds)
{
  std::vector<std::size_t> number(model.number_of_points(), 0);
  for(const auto& t : model.triangles())
    for(std::size_t v : t) number[v] = 1;
  std::size_t n = 0;
  for(std::size_t& x : number)
    if(x) x = ++n;
  os << "# TetGen PLC written by Bubble_mesh_3's export_peer_inputs: facet marker = patch index + 1,\n"
     << "# region attribute = region index\n";
  os << "# Part 1 - nodes\n" << n << " 3 0 0\n";
  for(std::size_t i = 0; i < model.number_of_points(); ++i)
    if(number[i])
    {
      const auto& p = model.point(i);
      os << number[i] << ' ';
      write_coordinate(os, CGAL::to_double(p.x()));
      os << ' ';
      write_coordinate(os, CGAL::to_double(p.y()));
      os << ' ';
      write_coordinate(os, CGAL::to_double(p.z()));
      os << '\n';
    }
  os << "# Part 2 - facets (one triangle each)\n" << model.number_of_triangles() << " 1\n";
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& tri = model.triangle(t);
    os << "1 0 " << model.patch_of_triangle(t) + 1 << "\n3 " << number[tri[0]] << ' ' << number[tri[1]] << ' '
       << number[tri[2]] << '\n';
  }
  os << "# Part 3 - holes\n0\n";
  std::size_t found = 0;
  for(std::size_t r = 1; r < seeds.size(); ++r) found += seeds[r].found ? 1 : 0;
  os << "# Part 4 - regions: number, seed point, attribute (region index), volume bound (none)\n" << found << '\n';
  for(std::size_t r = 1; r < seeds.size(); ++r)
    if(seeds[r].found)
    {
      const auto& p = seeds[r].point;
      os << r << ' ';
      write_coordinate(os, CGAL::to_double(p.x()));
      os << ' ';
      write_coordinate(os, CGAL::to_double(p.y()));
      os << ' ';
      write_coordinate(os, CGAL::to_double(p.z()));
      os << ' ' << r << " -1\n";
    }
}

/// Writes points as a TetGen .node file (numbered from 1), e.g. B.a.node for `tetgen -i`.
template <class Point_3>
void write_tetgen_node(std::ostream& os, const std::vector<Point_3>& points)
{
  os << "# additional points written by Bubble_mesh_3's benchmarks\n" << points.size() << " 3 0 0\n";
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    os << i + 1 << ' ';
    write_coordinate(os, CGAL::to_double(points[i].x()));
    os << ' ';
    write_coordinate(os, CGAL::to_double(points[i].y()));
    os << ' ';
    write_coordinate(os, CGAL::to_double(points[i].z()));
    os << '\n';
  }
}

/// The shells of one region for Gmsh: patches (1-based surface tags) grouped
/// by connectivity, the outer shell first, and the surfaces inside the region.
struct Region_shells
{
  std::vector<std::vector<std::size_t> > shells; ///< surface tags (patch + 1), outer shell first
  std::vector<std::size_t> inside;               ///< surface tags of patches inside the region
};

template <class GeomTraits>
std::vector<Region_shells> region_shells(const Geological_model_3<GeomTraits>& model)
{
  const std::size_t np = model.number_of_patches();
  // union-find over patches joined by common points, region by region
  std::vector<std::vector<std::size_t> > patches_of_point(model.number_of_points());
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    for(std::size_t v : model.triangle(t)) patches_of_point[v].push_back(model.patch_of_triangle(t));
  for(auto& l : patches_of_point)
  {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
  }
  std::vector<double> box_diag(np, 0.);
  {
    std::vector<CGAL::Bbox_3> box(np);
    for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
      for(std::size_t v : model.triangle(t)) box[model.patch_of_triangle(t)] += model.point(v).bbox();
    for(std::size_t p = 0; p < np; ++p)
      if(box[p].xmin() <= box[p].xmax())
        box_diag[p] = std::sqrt(CGAL::square(box[p].xmax() - box[p].xmin()) +
                                CGAL::square(box[p].ymax() - box[p].ymin()) +
                                CGAL::square(box[p].zmax() - box[p].zmin()));
  }
  std::vector<char> used(np, 0);
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t) used[model.patch_of_triangle(t)] = 1;

  const std::size_t nr = model.number_of_regions();
  std::vector<Region_shells> result(nr + 1);
  std::vector<std::size_t> parent(np);
  auto find = [&](std::size_t x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for(std::size_t r = 1; r <= nr; ++r)
  {
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    std::vector<char> on_boundary(np, 0);
    for(std::size_t p = 0; p < np; ++p)
    {
      if(!used[p]) continue;
      const auto& patch = model.patch(p);
      if(patch.positive_region != r && patch.negative_region != r) continue;
      if(patch.is_inside_region()) result[r].inside.push_back(p + 1);
      else on_boundary[p] = 1;
    }
    for(const auto& l : patches_of_point)
    {
      std::size_t first = std::size_t(-1);
      for(std::size_t p : l)
        if(on_boundary[p])
        {
          if(first == std::size_t(-1)) first = p;
          else parent[find(p)] = find(first);
        }
    }
    std::vector<std::vector<std::size_t> > groups(np);
    for(std::size_t p = 0; p < np; ++p)
      if(on_boundary[p]) groups[find(p)].push_back(p);
    std::vector<std::pair<double, std::size_t> > order; // by size of the shell's box, largest first
    for(std::size_t g = 0; g < np; ++g)
      if(!groups[g].empty())
      {
        double d = 0.;
        for(std::size_t p : groups[g]) d = (std::max)(d, box_diag[p]);
        order.emplace_back(-d, g);
      }
    std::sort(order.begin(), order.end());
    for(const auto& o : order)
    {
      std::vector<std::size_t> tags;
      for(std::size_t p : groups[o.second]) tags.push_back(p + 1);
      result[r].shells.push_back(tags);
    }
  }
  return result;
}

/*!
Writes the model's surfaces as a Gmsh 4.1 ASCII discrete mesh: one surface
entity per patch (tag = patch + 1) holding its triangles; a node belongs to
the entity of the first patch that uses it, its tag is the model point
index + 1. No curves, no volumes, no physical groups: the caller adds them.
*/
template <class GeomTraits>
void write_gmsh_discrete_surfaces(std::ostream& os, const Geological_model_3<GeomTraits>& model)
{
  const std::size_t np = model.number_of_patches();
  std::vector<std::vector<std::size_t> > triangles_of_patch(np);
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    triangles_of_patch[model.patch_of_triangle(t)].push_back(t);
  std::vector<std::size_t> owner(model.number_of_points(), std::size_t(-1));
  std::vector<std::vector<std::size_t> > nodes_of_patch(np);
  std::vector<CGAL::Bbox_3> box(np);
  for(std::size_t p = 0; p < np; ++p)
    for(std::size_t t : triangles_of_patch[p])
      for(std::size_t v : model.triangle(t))
      {
        box[p] += model.point(v).bbox();
        if(owner[v] == std::size_t(-1))
        {
          owner[v] = p;
          nodes_of_patch[p].push_back(v);
        }
      }
  std::size_t surfaces = 0, nodes = 0, max_node = 0;
  for(std::size_t p = 0; p < np; ++p)
    if(!triangles_of_patch[p].empty()) ++surfaces;
  for(std::size_t v = 0; v < owner.size(); ++v)
    if(owner[v] != std::size_t(-1))
    {
      ++nodes;
      max_node = v + 1;
    }
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  os << "$Entities\n0 0 " << surfaces << " 0\n";
  for(std::size_t p = 0; p < np; ++p)
    if(!triangles_of_patch[p].empty())
    {
      os << p + 1;
      for(double x : {box[p].xmin(), box[p].ymin(), box[p].zmin(), box[p].xmax(), box[p].ymax(), box[p].zmax()})
      {
        os << ' ';
        write_coordinate(os, x);
      }
      os << " 0 0\n";
    }
  os << "$EndEntities\n";
  os << "$Nodes\n" << surfaces << ' ' << nodes << ' ' << (nodes ? 1 : 0) << ' ' << max_node << '\n';
  for(std::size_t p = 0; p < np; ++p)
    if(!triangles_of_patch[p].empty())
    {
      os << "2 " << p + 1 << " 0 " << nodes_of_patch[p].size() << '\n';
      for(std::size_t v : nodes_of_patch[p]) os << v + 1 << '\n';
      for(std::size_t v : nodes_of_patch[p])
      {
        const auto& q = model.point(v);
        write_coordinate(os, CGAL::to_double(q.x()));
        os << ' ';
        write_coordinate(os, CGAL::to_double(q.y()));
        os << ' ';
        write_coordinate(os, CGAL::to_double(q.z()));
        os << '\n';
      }
    }
  os << "$EndNodes\n";
  os << "$Elements\n" << surfaces << ' ' << model.number_of_triangles() << " 1 " << model.number_of_triangles() << '\n';
  std::size_t tag = 0;
  for(std::size_t p = 0; p < np; ++p)
    if(!triangles_of_patch[p].empty())
    {
      os << "2 " << p + 1 << " 2 " << triangles_of_patch[p].size() << '\n';
      for(std::size_t t : triangles_of_patch[p])
      {
        const auto& tri = model.triangle(t);
        os << ++tag << ' ' << tri[0] + 1 << ' ' << tri[1] + 1 << ' ' << tri[2] + 1 << '\n';
      }
    }
  os << "$EndElements\n";
}

/// How many input triangles a tetrahedral mesh keeps whole.
struct Kept_whole_count
{
  std::size_t triangles = 0;      ///< input triangles
  std::size_t kept_whole = 0;     ///< whose three corners are mesh vertices and which are a face of a mesh tet
  std::size_t points = 0;         ///< input points used by triangles
  std::size_t points_found = 0;   ///< input points that are mesh vertices (within the tolerance)
};

/*!
Counts the input triangles that are a single face of a tetrahedron of
`mesh`: each input point is matched to the nearest mesh vertex if it is
closer than `tolerance` times the model's bounding-box diagonal (peers write
coordinates with 16 or 17 digits), then each triangle's three vertices are
looked up among the tetrahedra's faces.
*/
template <class GeomTraits>
Kept_whole_count count_triangles_kept_whole(const Geological_model_3<GeomTraits>& model,
                                            const Labeled_tetrahedral_mesh_3& mesh, double tolerance = 1e-9)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Point_3 P;
  typedef CGAL::Search_traits_3<K> Base_traits;
  typedef boost::iterator_property_map<const P*, CGAL::Identity_property_map<std::size_t>, P, const P&> Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef typename Search::Tree Tree;
  typedef typename Search::Distance Distance;

  Kept_whole_count count;
  count.triangles = model.number_of_triangles();
  std::vector<P> mesh_points;
  mesh_points.reserve(mesh.points.size());
  for(const auto& p : mesh.points) mesh_points.emplace_back(p[0], p[1], p[2]);
  CGAL::Bbox_3 box;
  for(const auto& p : model.points()) box += p.bbox();
  const double diag = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                CGAL::square(box.zmax() - box.zmin()));
  const double tol2 = CGAL::square(tolerance * diag);

  std::vector<std::size_t> match(model.number_of_points(), std::size_t(-1));
  std::vector<char> used(model.number_of_points(), 0);
  for(const auto& t : model.triangles())
    for(std::size_t v : t) used[v] = 1;
  if(!mesh_points.empty())
  {
    const Point_map pmap(mesh_points.data());
    std::vector<std::size_t> ids(mesh_points.size());
    std::iota(ids.begin(), ids.end(), std::size_t(0));
    Tree tree(ids.begin(), ids.end(), typename Tree::Splitter(), Traits(pmap));
    const Distance distance(pmap);
    for(std::size_t v = 0; v < model.number_of_points(); ++v)
    {
      if(!used[v]) continue;
      ++count.points;
      const auto& q = model.point(v);
      const P p(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
      Search search(tree, p, 1, 0, true, distance);
      const auto it = search.begin();
      if(it != search.end() && it->second <= tol2)
      {
        match[v] = it->first;
        ++count.points_found;
      }
    }
  }
  else
    for(char u : used) count.points += u ? 1 : 0;

  std::vector<std::array<std::size_t, 3> > faces;
  faces.reserve(4 * mesh.tetrahedra.size());
  for(const auto& t : mesh.tetrahedra)
    for(int i = 0; i < 4; ++i)
    {
      std::array<std::size_t, 3> f = {{t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4]}};
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  for(const auto& t : model.triangles())
  {
    std::array<std::size_t, 3> f = {{match[t[0]], match[t[1]], match[t[2]]}};
    if(f[0] == std::size_t(-1) || f[1] == std::size_t(-1) || f[2] == std::size_t(-1)) continue;
    std::sort(f.begin(), f.end());
    if(std::binary_search(faces.begin(), faces.end(), f)) ++count.kept_whole;
  }
  return count;
}

} // namespace bench
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_BENCH_PEER_INPUTS_H
