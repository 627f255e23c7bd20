// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_3_H
#define CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_3_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

A geological model as a polyhedral complex: points, triangles, the patch
(surface piece) each triangle belongs to, and for each patch the two regions
it separates.

Orientation convention: a triangle `(a,b,c)` has the normal
`(b-a) x (c-a)` (right-hand rule). Its patch's `positive_region` lies on the
side the normal points to, `negative_region` on the other side. Region `0` is
the outside of the model. A patch with the same region on both sides is a
surface inside that region (for instance a fault that ends inside a body).

Every region `r > 0` is bounded by the triangles of the patches that have `r`
on exactly one side; seen from `r` these are oriented outward when `r` is the
negative region of the patch.

The class is plain data with checked builders; it does not validate the
complex as a whole: `validate_geological_model()` does.

\tparam GeomTraits a model of `Kernel`.
*/
template <class GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel>
class Geological_model_3
{
public:
  typedef GeomTraits                     Geom_traits; ///< the geometric traits
  typedef typename GeomTraits::FT        FT;          ///< number type
  typedef typename GeomTraits::Point_3   Point_3;     ///< point type
  typedef std::array<std::size_t, 3>     Triangle;    ///< three point indices

  /// a surface piece: all its triangles separate the same two regions
  struct Patch
  {
    std::string name;                ///< name, e.g. the surface it comes from
    std::size_t positive_region = 0; ///< region on the side the triangle normals point to
    std::size_t negative_region = 0; ///< region on the other side
    /// `true` for a surface inside one region (same region on both sides)
    bool is_inside_region() const { return positive_region == negative_region; }
  };

  /// a rock body (region 0 is the outside of the model)
  struct Region
  {
    std::string name; ///< name of the body, e.g. the formation
  };

  /// where an element came from, for error messages (file and line, 0 = unknown)
  struct Source
  {
    std::string file;      ///< file name, empty when built in memory
    std::size_t line = 0;  ///< line number, 0 when unknown
  };

  /// an empty model: no points, only region 0 (the outside)
  Geological_model_3() { regions_.push_back(Region{"outside"}); }

  // ---- building -------------------------------------------------------------

  /// adds a region and returns its index (the first added region gets index 1)
  std::size_t add_region(const std::string& name)
  {
    regions_.push_back(Region{name});
    return regions_.size() - 1;
  }

  /// adds a patch separating `positive_region` and `negative_region`, returns its index
  std::size_t add_patch(const std::string& name, std::size_t positive_region, std::size_t negative_region)
  {
    if(positive_region >= regions_.size() || negative_region >= regions_.size())
      throw Geological_model_error("patch '" + name + "' refers to region " +
                                   std::to_string(std::max(positive_region, negative_region)) +
                                   " but the model has only " + std::to_string(regions_.size() - 1) +
                                   " regions");
    Patch p;
    p.name = name;
    p.positive_region = positive_region;
    p.negative_region = negative_region;
    patches_.push_back(p);
    return patches_.size() - 1;
  }

  /// adds a point and returns its index
  std::size_t add_point(const Point_3& p, const Source& src = Source())
  {
    points_.push_back(p);
    point_sources_.push_back(src);
    return points_.size() - 1;
  }

  /// adds the triangle `(a,b,c)` to patch `patch` and returns its index
  std::size_t add_triangle(std::size_t a, std::size_t b, std::size_t c, std::size_t patch,
                           const Source& src = Source())
  {
    const std::size_t n = points_.size();
    if(patch >= patches_.size())
      throw Geological_model_error(where(src) + "triangle " + std::to_string(triangles_.size()) +
                                   " refers to patch " + std::to_string(patch) +
                                   " which does not exist");
    for(std::size_t v : {a, b, c})
      if(v >= n)
        throw Geological_model_error(where(src) + "triangle " + std::to_string(triangles_.size()) +
                                     " of patch '" + patches_[patch].name + "' refers to vertex " +
                                     std::to_string(v) + " which does not exist (" +
                                     std::to_string(n) + " points)");
    triangles_.push_back(Triangle{{a, b, c}});
    triangle_patch_.push_back(patch);
    triangle_sources_.push_back(src);
    return triangles_.size() - 1;
  }

  /// sets the region a patch lies in on each side
  void set_patch_regions(std::size_t patch, std::size_t positive_region, std::size_t negative_region)
  {
    patches_.at(patch).positive_region = positive_region;
    patches_.at(patch).negative_region = negative_region;
  }

  /// renames region `r`
  void set_region_name(std::size_t r, const std::string& name) { regions_.at(r).name = name; }
  /// renames patch `p`
  void set_patch_name(std::size_t p, const std::string& name) { patches_.at(p).name = name; }

  /// replaces the point at `i` (readers use it when merging coincident points)
  void set_point(std::size_t i, const Point_3& p) { points_.at(i) = p; }

  /// replaces the vertex indices of triangle `t`
  void set_triangle(std::size_t t, const Triangle& tri) { triangles_.at(t) = tri; }

  /// the name of the file the model was read from (empty if built in memory)
  void set_file_name(const std::string& f) { file_name_ = f; }
  /// the name of the file the model was read from
  const std::string& file_name() const { return file_name_; }

  /// records a remark of a reader about the input: something it left out, for instance
  void add_note(const std::string& note) { notes_.push_back(note); }
  /// the readers' remarks, in the order they were made (the program prints them)
  const std::vector<std::string>& notes() const { return notes_; }

  // ---- access ---------------------------------------------------------------

  /// number of points
  std::size_t number_of_points() const { return points_.size(); }
  /// number of triangles
  std::size_t number_of_triangles() const { return triangles_.size(); }
  /// number of patches
  std::size_t number_of_patches() const { return patches_.size(); }
  /// number of regions, not counting the outside (region 0)
  std::size_t number_of_regions() const { return regions_.size() - 1; }

  /// all points
  const std::vector<Point_3>& points() const { return points_; }
  /// point `i`
  const Point_3& point(std::size_t i) const { return points_[i]; }
  /// all triangles
  const std::vector<Triangle>& triangles() const { return triangles_; }
  /// triangle `t`
  const Triangle& triangle(std::size_t t) const { return triangles_[t]; }
  /// the patch triangle `t` belongs to
  std::size_t patch_of_triangle(std::size_t t) const { return triangle_patch_[t]; }
  /// the patch of every triangle
  const std::vector<std::size_t>& triangle_patches() const { return triangle_patch_; }
  /// all patches
  const std::vector<Patch>& patches() const { return patches_; }
  /// patch `p`
  const Patch& patch(std::size_t p) const { return patches_[p]; }
  /// regions, index 0 being the outside
  const std::vector<Region>& regions() const { return regions_; }
  /// region `r` (0 is the outside)
  const Region& region(std::size_t r) const { return regions_[r]; }
  /// where triangle `t` was read from
  const Source& triangle_source(std::size_t t) const { return triangle_sources_[t]; }
  /// where point `i` was read from
  const Source& point_source(std::size_t i) const { return point_sources_[i]; }

  /// "file:line: " for an element's source, or the model's file name, or nothing
  std::string where(const Source& src) const
  {
    const std::string& f = src.file.empty() ? file_name_ : src.file;
    if(f.empty()) return std::string();
    if(src.line == 0) return f + ": ";
    return f + ":" + std::to_string(src.line) + ": ";
  }

  /// a readable name for region `r`, e.g. `region 2 'Layer_1'`
  std::string region_label(std::size_t r) const
  {
    if(r == 0) return "the outside (region 0)";
    return "region " + std::to_string(r) + " '" + regions_.at(r).name + "'";
  }

  /// a readable name for patch `p`, e.g. `patch 4 'Fault_A'`
  std::string patch_label(std::size_t p) const
  {
    return "patch " + std::to_string(p) + " '" + patches_.at(p).name + "'";
  }

  /// removes points no triangle uses and renumbers the rest in their order
  void remove_unused_points()
  {
    std::vector<std::size_t> new_index(points_.size(), std::size_t(-1));
    for(const Triangle& t : triangles_)
      for(std::size_t v : t) new_index[v] = 0;
    std::size_t n = 0;
    std::vector<Point_3> pts;
    std::vector<Source> srcs;
    for(std::size_t i = 0; i < points_.size(); ++i)
      if(new_index[i] == 0)
      {
        new_index[i] = n++;
        pts.push_back(points_[i]);
        srcs.push_back(point_sources_[i]);
      }
    for(Triangle& t : triangles_)
      for(std::size_t& v : t) v = new_index[v];
    points_.swap(pts);
    point_sources_.swap(srcs);
  }

private:
  std::vector<Point_3> points_;
  std::vector<Source> point_sources_;
  std::vector<Triangle> triangles_;
  std::vector<std::size_t> triangle_patch_;
  std::vector<Source> triangle_sources_;
  std::vector<Patch> patches_;
  std::vector<Region> regions_;
  std::string file_name_;
  std::vector<std::string> notes_;
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_GEOLOGICAL_MODEL_3_H
