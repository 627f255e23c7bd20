// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_MAKE_BUBBLE_MESH_3_H
#define CGAL_MAKE_BUBBLE_MESH_3_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Mesh_complex_3.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>
#include <CGAL/Bubble_mesh_3/Surface_bubble_sizing_field.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>
#include <CGAL/Bubble_mesh_3/relax_bubbles.h>
#include <CGAL/Bubble_mesh_3/remesh_surfaces.h>
#include <CGAL/Bubble_mesh_3/retriangulate_planar_patches.h>
#include <CGAL/Bubble_mesh_3/snap_points_to_axis_planes.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>
#include <CGAL/Bubble_mesh_3/tetrahedralize_bubbles.h>
#include <CGAL/Bubble_mesh_3/remove_slivers.h>
#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Bubble_mesh_3/internal/stage_callback.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

What `make_bubble_mesh_3()` did, stage by stage.
*/
struct Bubble_mesh_report
{
  Axis_plane_snap_report axis_plane_snap;     ///< the model's points given back their box wall's plane (`snap_points_to_axis_planes()`), before anything else
  bool surfaces_remeshed = false;             ///< whether stage 0 ran (`remesh_input_surfaces`)
  Surface_remeshing_report surface_remeshing; ///< stage 0 (`remesh_surfaces()`), if it ran
  bool planar_patches_retriangulated = false; ///< whether planar pieces were re-triangulated (`retriangulate_planar_patches()`)
  Planar_retriangulation_report planar_retriangulation; ///< if they were
  bool tilted_refinement_coarsened = false;   ///< whether the mesh was made again with `fallback_tilted_size_factor` (2) after the surface recovery failed with the smaller factor asked for (or the default)
  bool tilted_refinement_undone = false;      ///< whether the mesh was made again without new points on tilted pieces (`refine_tilted_pieces(false)`) after the surface recovery failed with them
  std::string tilted_refinement_undone_because; ///< when either is true, the surface recovery's errors (which input triangle it could not recover, and why), one per line
  bool thickness_rule_relaxed = false;       ///< whether the surfaces were re-meshed again with fewer edges across thin layers after the surface recovery failed on those the thickness rule had refined
  double elements_across_thickness_used = 0.; ///< if so, the `elements_across_thickness` of the surfaces meshed: half the one asked for, or 0 (the rule off) if that failed too
  std::string thickness_rule_relaxed_because; ///< if so, the surface recovery's errors on the surfaces given up, one per line
  std::size_t number_of_surface_bubbles = 0;  ///< one per model point
  std::size_t number_of_initial_bubbles = 0;  ///< interior bubbles placed (stage 2)
  std::size_t number_of_relaxed_bubbles = 0;  ///< interior bubbles after relaxation and population control
  std::vector<Region_placement_statistics> placement; ///< per region (entry 0 unused)
  Relaxation_report relaxation;               ///< stages 3 and 4
  Tetrahedralization_report tetrahedralization; ///< stage 5
  Sliver_removal_report sliver_removal;       ///< stage 6 (`remove_slivers()`)
  double time_surface_remeshing = 0.;         ///< seconds
  double time_surface_bubbles = 0.;           ///< seconds
  double time_placement = 0.;                 ///< seconds, clustering included
  double time_relaxation = 0.;                ///< seconds
  double time_tetrahedralization = 0.;        ///< seconds
  double time_sliver_removal = 0.;            ///< seconds
};

namespace internal_np {
enum bubble_mesh_report_t { bubble_mesh_report };
enum remesh_input_surfaces_t { remesh_input_surfaces };
enum keep_input_triangles_t { keep_input_triangles };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgBubbleMesh3Ref
/// `make_bubble_mesh_3()` fills the `Bubble_mesh_report` pointed to
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(Bubble_mesh_report*, bubble_mesh_report)
/// \ingroup PkgBubbleMesh3Ref
/// `make_bubble_mesh_3()` re-meshes the model's surfaces with `remesh_surfaces()` first
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, remesh_input_surfaces)

/// \ingroup PkgBubbleMesh3Ref
/// `make_bubble_mesh_3()` meshes the input triangles as they are, without
/// re-triangulating planar pieces (`retriangulate_planar_patches()`) first
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, keep_input_triangles)

} // namespace parameters

/*!
\ingroup PkgBubbleMesh3Ref

Meshes a valid geological model with the clustering-based bubble method and
fills `c3t3`: surface bubbles (`place_surface_bubbles()`), clustering and
initial interior bubbles (`place_initial_bubbles()` with a
`Surface_bubble_sizing_field`), relaxation and population control
(`relax_bubbles()`), the conforming Delaunay tetrahedralization with the
input surfaces recovered and the cells labelled by region
(`tetrahedralize_bubbles()`), and sliver removal by moving interior vertices
only (`remove_slivers()`; pass `perturb_interior_vertices(false)` to skip it).

Before anything else, points written a hair off a box wall's axis plane (within
the coplanarity tolerance, a thousand rounding units of the largest
coordinate) get its coordinate back (`snap_points_to_axis_planes()`,
`Bubble_mesh_report::axis_plane_snap`): the stages run on that copy.

With `remesh_input_surfaces(true)`, the surfaces are first re-meshed with
bubbles (`remesh_surfaces()`, stage 0) and the stages run on the re-meshed
model: same regions and patches, so the mesh is labelled as the input is.
Use it when the input triangles are poor: tetrahedra at a triangle with a
tiny angle are poor whatever the bubbles do inside. If the surface recovery
fails on re-meshed surfaces that the thickness rule refined (down to a
pinch-out, say), they are re-meshed with half as many edges across thin
layers, then without the rule, and the stages run again
(`Bubble_mesh_report::thickness_rule_relaxed`). On re-meshed surfaces the
sizing field also takes `area_weighted_radius_floor(true)` unless `np` says
otherwise: refined patches must not set the size deep inside the bodies; and
`size_gradation(Surface_bubble_sizing_field::default_remeshed_size_gradation)`
(touching bubbles' radii within a ratio of 1.25, not 3): the bodies beside a
thin layer's fine surfaces then keep small, well-shaped tetrahedra further in
(bundled model re-meshed: aspect-ratio median 1.85 -> 1.78). With the surfaces
kept it would keep the bubbles small deep inside beside the input's needles,
which only adds tetrahedra there.

The model must be valid (`validate_geological_model()`); the stages assume
it. Each stage is a free function that can be called alone; this function
only chains them, passing `np` to each, so every named parameter of the
stages is accepted here too.

\cgalNamedParamsBegin
  \cgalParamNBegin{bubble_mesh_report}
    \cgalParamDescription{receives the figures of every stage}
    \cgalParamType{`Bubble_mesh_report*`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{remesh_input_surfaces}
    \cgalParamDescription{re-mesh the surfaces first (`remesh_surfaces()`, which takes its named parameters, e.g. `edge_length`, from `np` too)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{stage_callback}
    \cgalParamDescription{called with the stage's name when it starts}
    \cgalParamType{`std::function<void(const std::string&)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNExtra{the named parameters of `remesh_surfaces()` (when asked), `place_surface_bubbles()`, `Surface_bubble_sizing_field`,
    `place_initial_bubbles()`, `relax_bubbles()`, `tetrahedralize_bubbles()` and `remove_slivers()`}
\cgalNamedParamsEnd

\throws Geological_model_error or Tetrahedralization_error, naming the element at fault
(also when the re-meshed surfaces are not a valid model)
*/
template <class GeomTraits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Bubble_mesh_report make_bubble_mesh_3(const Geological_model_3<GeomTraits>& given_model,
                                      Mesh_complex_3<GeomTraits>& c3t3,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Bubble_mesh_report local;
  Bubble_mesh_report* report = choose_parameter(get_parameter(np, internal_np::bubble_mesh_report), &local);
  const std::function<void(const std::string&)> stage =
    choose_parameter(get_parameter(np, internal_np::stage_callback), std::function<void(const std::string&)>());
  auto start = [&](const char* name) { if(stage) stage(name); };

  // box walls whose points were written a hair off their planes get them
  // back: every later stage keeps axis planes exactly planar
  Geological_model_3<GeomTraits> snapped = given_model;
  report->axis_plane_snap = snap_points_to_axis_planes(snapped);
  const Geological_model_3<GeomTraits>& input_model =
    report->axis_plane_snap.number_of_points > 0 ? snapped : given_model;

  Real_timer timer;
  // runs one stage, its seconds added to `seconds` (also when it throws: a
  // stage run twice counts both runs)
  auto timed = [&](const char* name, double& seconds, const auto& run) {
    start(name);
    timer.reset();
    timer.start();
    try { run(); }
    catch(...)
    {
      timer.stop();
      seconds += timer.time();
      throw;
    }
    timer.stop();
    seconds += timer.time();
  };
  // the stages below see the re-meshed model: same regions and patches, new points and triangles
  Geological_model_3<GeomTraits> remeshed;
  report->surfaces_remeshed = choose_parameter(get_parameter(np, internal_np::remesh_input_surfaces), false);
  auto remesh = [&](const auto& remesh_np) {
    timed("surface remeshing", report->time_surface_remeshing,
          [&] { report->surface_remeshing = remesh_surfaces(input_model, remeshed, remesh_np); });
    // the later stages assume a valid model: a re-meshing that broke it is an error, not a wrong mesh
    try { validate_geological_model(remeshed); }
    catch(const Geological_model_error& e)
    {
      throw Geological_model_error(std::string("the re-meshed surfaces (remesh_surfaces()) are not a valid model; "
                                               "mesh without re-meshing or with another size: ") + e.what());
    }
  };
  if(report->surfaces_remeshed) remesh(np);
  // Planar pieces (box walls, flat tops) as fans of needles would force poor
  // tetrahedra and thousands of Steiner points; their own Delaunay
  // triangulation covers the same polygon. Re-meshed surfaces need none.
  Geological_model_3<GeomTraits> retriangulated;
  report->planar_patches_retriangulated =
    !report->surfaces_remeshed && !choose_parameter(get_parameter(np, internal_np::keep_input_triangles), false);
  if(report->planar_patches_retriangulated)
    report->planar_retriangulation = retriangulate_planar_patches(input_model, retriangulated, np);
  const Geological_model_3<GeomTraits>& model =
    report->surfaces_remeshed ? remeshed : report->planar_patches_retriangulated ? retriangulated : input_model;

  // which surface vertices are Steiner points, and on which input triangles
  // they lie: the sliver removal may collapse them again
  Surface_vertex_supports<typename Mesh_complex_3<GeomTraits>::Triangulation> supports;
  auto stages_1_to_5 = [&](const Geological_model_3<GeomTraits>& meshed) {
    std::vector<Bubble<GeomTraits> > surface_bubbles;
    std::optional<Surface_bubble_sizing_field<GeomTraits> > sizing; // built with the surface bubbles, in their time
    timed("surface bubbles", report->time_surface_bubbles, [&] {
      surface_bubbles = place_surface_bubbles(meshed, np);
      // re-meshed surfaces have no huge triangles: R0 may then look at the area the sizes cover
      const double gradation =
        choose_parameter(get_parameter(np, internal_np::size_gradation),
                         Surface_bubble_sizing_field<GeomTraits>::default_size_gradation_for(report->surfaces_remeshed));
      sizing.emplace(meshed, surface_bubbles,
                     parameters::area_weighted_radius_floor(
                       choose_parameter(get_parameter(np, internal_np::area_weighted_radius_floor),
                                        report->surfaces_remeshed),
                       parameters::size_gradation(gradation, np)));
    });
    report->number_of_surface_bubbles = surface_bubbles.size();

    std::vector<Bubble<GeomTraits> > bubbles;
    timed("clustering and initial bubbles", report->time_placement, [&] {
      bubbles = place_initial_bubbles(meshed, surface_bubbles, *sizing,
                                      parameters::placement_statistics(&report->placement, np));
    });
    report->number_of_initial_bubbles = bubbles.size();

    timed("relaxation", report->time_relaxation,
          [&] { report->relaxation = relax_bubbles(meshed, surface_bubbles, bubbles, *sizing, np); });
    report->number_of_relaxed_bubbles = bubbles.size();

    timed("tetrahedralization", report->time_tetrahedralization, [&] {
      std::vector<typename GeomTraits::Point_3> centres;
      centres.reserve(bubbles.size());
      for(const Bubble<GeomTraits>& b : bubbles) centres.push_back(b.center);
      report->tetrahedralization =
        tetrahedralize_bubbles(meshed, centres, c3t3, parameters::surface_vertex_supports(&supports, np));
    });
  };
  try { stages_1_to_5(model); }
  catch(const Tetrahedralization_error& error)
  {
    if(report->surfaces_remeshed)
    {
      // Where the thickness rule refines the surfaces down to a pinch-out
      // (two surfaces meeting at a few degrees), the points of the two are
      // close and not aligned; each encroaches on the other's facets and the
      // recovery may refine towards the contact until it gives up (a layer
      // pinching out at 1.7 degrees, re-meshed at 40 with 2 edges across).
      // Fewer edges across leave fewer points there: half as many, then the
      // rule off.
      const Surface_remeshing_report& first = report->surface_remeshing;
      if(first.smallest_thickness_size <= 0. || first.smallest_thickness_size >= first.target_size) throw;
      const double asked = choose_parameter(get_parameter(np, internal_np::elements_across_thickness),
                                            Remeshing_sizing_field<GeomTraits>::default_elements_across_thickness);
      report->thickness_rule_relaxed = true;
      report->thickness_rule_relaxed_because = error.what();
      report->elements_across_thickness_used = 0.5 * asked;
      remesh(parameters::elements_across_thickness(0.5 * asked, np));
      try { stages_1_to_5(remeshed); }
      catch(const Tetrahedralization_error& again)
      {
        report->thickness_rule_relaxed_because += std::string("\n") + again.what();
        report->elements_across_thickness_used = 0.;
        remesh(parameters::elements_across_thickness(0., np));
        stages_1_to_5(remeshed);
      }
    }
    else
    {
      // The points rounded onto tilted pieces are the one thing here the
      // recovery has not met in the input: rather than fail, mesh again
      // without them (axis-plane pieces still refined).
      if(!report->planar_patches_retriangulated || report->planar_retriangulation.number_of_refined_tilted_pieces == 0)
        throw;
      report->tilted_refinement_undone_because = error.what();
      // A smaller factor refines more pieces, each one more chance of a point
      // the recovery cannot handle: twice the size wanted comes next (the
      // default until every model in ../shared recovered at 1.5).
      bool made = false;
      if(choose_parameter(get_parameter(np, internal_np::tilted_size_factor), default_tilted_size_factor) <
         fallback_tilted_size_factor)
      {
        report->tilted_refinement_coarsened = true;
        report->planar_retriangulation = retriangulate_planar_patches(
          input_model, retriangulated, parameters::tilted_size_factor(fallback_tilted_size_factor, np));
        if(report->planar_retriangulation.number_of_refined_tilted_pieces > 0)
        {
          try { stages_1_to_5(retriangulated); made = true; }
          catch(const Tetrahedralization_error& again)
          {
            report->tilted_refinement_undone_because += std::string("\n") + again.what();
          }
        }
      }
      if(!made)
      {
        report->tilted_refinement_undone = true;
        report->planar_retriangulation =
          retriangulate_planar_patches(input_model, retriangulated, parameters::refine_tilted_pieces(false, np));
        stages_1_to_5(retriangulated);
      }
    }
  }

  // Surfaces and their points never move here: only bubbles do, and only where
  // the cells they make are better, so the guarantees of stage 5 still hold.
  timed("sliver removal", report->time_sliver_removal, [&] {
    report->sliver_removal = remove_slivers(c3t3, parameters::surface_vertex_supports(&supports, np));
  });
  return *report;
}

/*!
\ingroup PkgBubbleMesh3Ref

Same as above, returning the mesh.
*/
template <class GeomTraits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_complex_3<GeomTraits> make_bubble_mesh_3(const Geological_model_3<GeomTraits>& model,
                                              const NamedParameters& np = CGAL::parameters::default_values())
{
  Mesh_complex_3<GeomTraits> c3t3;
  make_bubble_mesh_3(model, c3t3, np);
  return c3t3;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_MAKE_BUBBLE_MESH_3_H
