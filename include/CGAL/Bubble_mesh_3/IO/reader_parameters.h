// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_READER_PARAMETERS_H
#define CGAL_BUBBLE_MESH_3_IO_READER_PARAMETERS_H

#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <map>
#include <string>
#include <utility>

namespace CGAL {
namespace Bubble_mesh_3 {

/// \ingroup PkgBubbleMesh3IO
/// the two regions an object of a surface file separates: (positive side, negative side),
/// by region name; the name `outside` stands for region 0
typedef std::map<std::string, std::pair<std::string, std::string> > Region_assignment;

namespace internal_np {
enum merge_tolerance_t { merge_tolerance };
enum region_assignment_t { region_assignment };
enum region_assignment_file_t { region_assignment_file };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgBubbleMesh3IO
/// readers merge points closer than this fraction of the bounding-box diagonal;
/// 0 (the default) merges identical coordinates only
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, merge_tolerance)
/// \ingroup PkgBubbleMesh3IO
/// `read_gocad_tsurf()`: the regions each TSurf object separates, instead of one body per object
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(Region_assignment, region_assignment)
/// \ingroup PkgBubbleMesh3IO
/// `read_gocad_tsurf()`: a text file giving the region assignment, see `read_region_assignment()`
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::string, region_assignment_file)


} // namespace parameters

namespace IO {
namespace internal {

template <class NP>
double merge_tolerance(const NP& np)
{
  return CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, Bubble_mesh_3::internal_np::merge_tolerance), 0.);
}

} // namespace internal
} // namespace IO

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_READER_PARAMETERS_H
