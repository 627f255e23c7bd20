// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bubble_mesh_3: the command-line program. It only parses options and calls the
// package; every stage it runs is a free function of the library.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/orient_patch_sides.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/geological_model_summary.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>
#include <CGAL/Bubble_mesh_3/IO/write_mesh.h>
#include <CGAL/Bubble_mesh_3/IO/write_quality_report.h>
#include <CGAL/Bubble_mesh_3/IO/write_svg_histograms.h>
#include <CGAL/Bubble_mesh_3/IO/write_svg_section.h>
#include <CGAL/Bubble_mesh_3/Remeshing_sizing_field.h>
#include <CGAL/Bubble_mesh_3/Repulsive_bubble_force.h>
#include <CGAL/Bubble_mesh_3/Corner_forced_facet_angle.h>
#include <CGAL/Bubble_mesh_3/mesh_quality.h>
#include <CGAL/make_bubble_mesh_3.h>
#include <CGAL/Real_timer.h>

#include "section_plane.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <thread>
#endif

#include <algorithm>
#include <iomanip>
#include <map>
#include <memory>

#include <cmath>
#include <cstdio>
#include <unistd.h>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace BM = CGAL::Bubble_mesh_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

namespace {

const char* usage_text =
"Usage: bubble_mesh_3 INPUT [options]\n"
"\n"
"Meshes a geological model (rock bodies, layers and faults given as triangulated\n"
"surfaces) into a conforming, region-labelled tetrahedral mesh with the\n"
"clustering-based bubble method.\n"
"\n"
"INPUT  a GOCAD Model3d (.ml), GOCAD TSurf (.ts) or multi-body OBJ (.obj) file, or\n"
"       the closed surface of a single body as OFF, PLY or STL (.off, .ply, .stl).\n"
"\n"
"Options:\n"
"  -h, --help                 show this help and exit\n"
"  -o, --output FILE          write the mesh to FILE; the format follows the extension:\n"
"                             .mesh (Medit), .vtu (VTK), .msh (Gmsh 4.1), .node (TetGen\n"
"                             .node/.ele/.face), .inp (Abaqus), .f3grid (FLAC3D).\n"
"                             May be given several times. Regions and surfaces are labelled.\n"
"  --check                    read and validate the model, print its summary, do not mesh\n"
"  --quality-json FILE        write the mesh quality report (per region) as JSON\n"
"  --quality-svg FILE         draw the quality histograms (aspect ratio, face and\n"
"                             dihedral angles, per region) as SVG\n"
"  --section-svg FILE         draw a section of the mesh as SVG: the cut tetrahedra\n"
"                             coloured by region (in magenta: a dihedral angle\n"
"                             under 10 degrees), the input surfaces as lines; by\n"
"                             default a vertical plane through the middle of the model,\n"
"                             along its longer horizontal side\n"
"  --section AXIS=V           the plane of --section-svg: x=V or y=V (vertical), z=V\n"
"                             (horizontal, seen from above), V in model units\n"
"  --threads N                number of threads (default: all cores); the mesh is the\n"
"                             same whatever N\n"
"  --seed S                   seed of the k-means clustering and of the sliver\n"
"                             removal's trial moves (default 0)\n"
"  --sliver-bound D           move bubbles of tetrahedra whose smallest dihedral angle\n"
"                             is under D degrees (default 15); surfaces never move\n"
"  --no-sliver-removal        keep the tetrahedralization as it is\n"
"  --force-law L              the bubbles' pair force: cubic (default, the paper's: repels\n"
"                             closer than touching, attracts a little up to 1.5 times) or\n"
"                             repulsive (the same without the attraction: bubbles do not\n"
"                             stack where they are sparse; better tetrahedra on models\n"
"                             with graded sizes, longer relaxation)\n"
"  --paper-overlap-ratio      population control with the paper's overlap ratio, which\n"
"                             counts neighbours whatever their size; by default each\n"
"                             interior one counts by the solid angle it takes, so that\n"
"                             graded sizes are not traded by the thousand round after\n"
"                             round, and a surface triangle much wider than the bubbles\n"
"                             counts as the bubbles it could hold\n"
"  --paper-dynamics           relax the bubbles with the paper's damped dynamics\n"
"                             (m x'' + c x' = F, Heun's scheme) instead of FIRE, the\n"
"                             fast inertial relaxation engine (the default: the same\n"
"                             kind of rest in about half the time on large models)\n"
"  --smooth N                 sliver removal also smooths all interior vertices, at most\n"
"                             N passes (default 0: off): each moves towards the\n"
"                             optimal-Delaunay point of its star (or the centroid of its\n"
"                             neighbours) where the tetrahedra around it get a lower mean\n"
"                             aspect ratio, no smaller dihedral angle and no more slivers\n"
"  --keep-steiner-points      sliver removal leaves the Steiner points of the surface\n"
"                             recovery; by default it collapses them onto neighbours on\n"
"                             the same input triangles where the tetrahedra get better\n"
"  --remesh-surfaces          re-mesh the input surfaces with bubbles before meshing the\n"
"                             volume (for inputs with poor triangles: tiny angles, edge\n"
"                             lengths spread over orders of magnitude); contact curves,\n"
"                             corners and the region and surface labels are kept\n"
"  --keep-input-triangles     mesh the input triangles as they are; by default each\n"
"                             planar piece of a surface (a flat box wall, say) is first\n"
"                             re-triangulated (Delaunay, same polygon)\n"
"  --planar-angle-bound D     planar pieces in an axis plane (x, y or z constant) get\n"
"                             new points until their triangles' angles reach D degrees\n"
"                             and their edges the median input edge or --size (finer next\n"
"                             to finer points on their border) where other surfaces allow\n"
"                             (default 10; 0: re-triangulate with the input points only);\n"
"                             other pieces and curved surfaces' triangles with no angle\n"
"                             under 20 degrees get new points where over 1.5 times as wide\n"
"  --axis-planes-only         give new points to axis-plane pieces only (not to tilted\n"
"                             pieces and curved surfaces' triangles)\n"
"  --tilted-size-factor F     tilted pieces and curved surfaces' triangles get new points\n"
"                             where over F times as wide as the size wanted (default 1.5);\n"
"                             larger: fewer tetrahedra, worse ones (modelA2 at 2: 394 k\n"
"                             instead of 872 k tets, 22.5 instead of 10.7 % under 10\n"
"                             degrees). If the surface recovery fails, the mesh is made\n"
"                             again at 2, then with the axis planes only\n"
"  --size S                   target edge length of the re-meshed surfaces (with\n"
"                             --remesh-surfaces), or else the largest edge of the new\n"
"                             points on planar pieces: in model units, or with a % sign,\n"
"                             of the bounding-box diagonal (e.g. 2%); default: the median\n"
"                             input edge length. Thin layers get finer (see below). With\n"
"                             the surfaces kept, a size above the median keeps the box\n"
"                             walls coarse where a small, finely triangulated body (an\n"
"                             ore lens, a tunnel) makes the median small. Re-meshed, a\n"
"                             size whose mesh cannot fit in memory is refused at once\n"
"  --layer-elements N         with --remesh-surfaces: edges wanted across the thickness\n"
"                             of a thin layer, or between a fault tip and a horizon\n"
"                             (default 1.63: about two tetrahedra across; 1 gives fewer\n"
"                             tetrahedra and a faster run; 0 turns the rule off). If\n"
"                             the surfaces it refined cannot be recovered (a pinch-out),\n"
"                             they are re-meshed with N/2, then 0\n"
"  --min-size S               with --remesh-surfaces: the shortest edge the thickness rule\n"
"                             may ask for, in model units or S% of the diagonal (default\n"
"                             a tenth of the smallest surface size). Where surfaces come\n"
"                             closer than that (a layer squeezed thin, a fault passing\n"
"                             just by a horizon) tetrahedra are flat across the gap; a\n"
"                             smaller S resolves the gap, with many more tetrahedra\n"
"  --size-grading G           with --remesh-surfaces: largest ratio between the sizes of\n"
"                             neighbouring edges (default 1.5, above 1). Nearer 1 the\n"
"                             sizes change more slowly away from thin layers and small\n"
"                             features: better-shaped tetrahedra, more of them\n"
"  --interior-grading G       largest ratio between the radii of touching bubbles as they\n"
"                             grow away from the surfaces (above 1; default 1.25 with\n"
"                             --remesh-surfaces, 3 with the surfaces kept). Nearer 1 a\n"
"                             body beside a thin layer keeps small tetrahedra further in:\n"
"                             better-shaped there, more of them. Beside kept input\n"
"                             needles a ratio near 1 only adds small tetrahedra\n"
"  --curvature-angle D        with --remesh-surfaces: largest turn, in degrees, of a curved\n"
"                             surface along one new edge (default 22.5: 16 edges around a\n"
"                             tunnel; smaller keeps curved bodies' volumes closer, with\n"
"                             more tetrahedra there; 0 turns the rule off)\n"
"  --feature-angle D          with --remesh-surfaces: a bend of over D degrees between two\n"
"                             triangles of one surface is kept as a crease, and a turn of\n"
"                             over D degrees along a contact curve as a corner (default 30)\n"
"  --refine-ribbons           with --remesh-surfaces: size a ribbon (a patch between two\n"
"                             curves meeting at under 10 degrees, e.g. a fault strip\n"
"                             between two horizon cut lines; --check lists their corners)\n"
"                             by its width instead of spanning it with needles. Better\n"
"                             elements there, many more of them (modelA5: tetrahedra\n"
"                             under 10 degrees 395 -> 221, run time 241 -> 564 s)\n"
"  --no-balance-volumes       with --remesh-surfaces: leave the region volumes as the new\n"
"                             triangles make them. By default (--balance-volumes) the new\n"
"                             points slide along the input surfaces until every region has\n"
"                             its input volume again: the new triangles are chords across\n"
"                             the bends of curved surfaces, which change a region's volume\n"
"                             by about 1e-4 on real horizons. A convex body faceted coarsely\n"
"                             (a tunnel) cannot be balanced so: its surfaces are re-meshed\n"
"                             again with every crease kept (about twice the tetrahedra there)\n"
"  --population-rounds N      most rounds of population control (bubbles deleted where\n"
"                             crowded, inserted in gaps), each followed by a relaxation\n"
"                             (default 12). Fewer is faster: 5 shortened the relaxation by\n"
"                             30-40 % on the models tried, for an aspect-ratio median up\n"
"                             to 0.02 higher; 0 keeps the crowded initial bubbles (poor)\n"
"  --population-tolerance P   a region's population has settled when a round inserts and\n"
"                             deletes at most this share of its bubbles (default 0.005);\n"
"                             then one relaxation to the full tolerance and one last pass\n"
"                             end it. Larger is faster where big regions go on trading\n"
"                             bubbles round after round, smaller slower: CloudSpin\n"
"                             re-meshed's relaxation takes 123 s at 0.01, 150 s at 0.005\n"
"                             and 170-186 s at 0.002 (the default until session 55), for\n"
"                             aspect-ratio medians of 1.640, 1.640 and 1.638\n"
"  --region-size-factor R=F   sizes in region R (its name, or its number as --check lists\n"
"                             it) times F, from 0.05 to 20 (0.5: edges half as long, 4 to 5\n"
"                             times the tetrahedra there); may be given for several\n"
"                             regions. With --remesh-surfaces the region's surfaces are\n"
"                             re-meshed at that size (a surface between two regions takes\n"
"                             the smaller) and its inside follows them; with the surfaces\n"
"                             kept only the bubbles inside it get smaller (its surfaces\n"
"                             stay as given: the tetrahedra against them are graded)\n"
"  --surface-size-factor S=F  with --remesh-surfaces: the target size on surface S times F\n"
"                             (a surface's name, as --check lists them, takes all its parts\n"
"                             NAME_1, NAME_2...; a part's own name takes that part); where\n"
"                             a thin layer or a bend asks for smaller edges, they stay\n"
"                             smaller\n"
"  --regions FILE             for a .ts input of open surfaces (horizons, faults, box\n"
"                             walls): the regions on either side of each TSurf object,\n"
"                             one line 'OBJECT POSITIVE_REGION NEGATIVE_REGION' each\n"
"                             ('outside' for the outside; the same region twice for a\n"
"                             fault ending inside it). Without it each object is a body\n"
"  --summary-json FILE        also write the model summary as JSON to FILE\n"
"  --merge-tolerance T        merge points closer than T times the bounding-box\n"
"                             diagonal (default 0: merge exactly coincident points only)\n"
"  -q, --quiet                print errors only\n"
"\n"
"Exit status: 0 on success; 1 when the input is invalid (the error names the file,\n"
"line and element); 2 on a usage error. No output file is written on failure.\n";

struct Options
{
  std::string input;
  std::vector<std::string> outputs;
  std::string quality_json;
  std::string quality_svg;
  std::string section_svg;
  Section_choice section;
  bool section_given = false;
  long threads = 0;
  unsigned seed = 0;
  bool check = false;
  bool quiet = false;
  std::string summary_json;
  std::string regions;
  double merge_tolerance = 0.;
  bool sliver_removal = true;
  bool collapse_steiner_points = true;
  std::size_t smoothing_passes = 0;
  double sliver_bound = 15.;
  bool remesh_surfaces = false;
  bool repulsive_force = false;
  bool paper_overlap_ratio = false;
  bool paper_dynamics = false;
  bool keep_input_triangles = false;
  double planar_angle_bound = 10.;
  bool refine_tilted_pieces = true;
  double tilted_size_factor = BM::default_tilted_size_factor;
  bool tilted_size_factor_given = false;
  double size = 0.;          // absolute target edge length (0: not given)
  double relative_size = 0.; // fraction of the bounding-box diagonal (0: not given)
  double min_size = 0., relative_min_size = 0.; // --min-size, as --size (0: not given)
  // edges across a thin layer: Remeshing_sizing_field's elements_across_thickness
  double layer_elements = BM::Remeshing_sizing_field<K>::default_elements_across_thickness;
  bool layer_elements_given = false;
  // relax_bubbles()'s number_of_population_rounds
  std::size_t population_rounds = BM::default_number_of_population_rounds;
  // relax_bubbles()'s population_tolerance
  double population_tolerance = BM::default_population_tolerance;
  // Remeshing_sizing_field's size_grading
  double size_grading = BM::Remeshing_sizing_field<K>::default_size_grading;
  bool size_grading_given = false;
  // Surface_bubble_sizing_field's size_gradation g, given as the ratio (1 + g) / (1 - g)
  // (0: not given, the field's default_size_gradation_for() the run)
  double interior_grading = 0.;
  // Remeshing_sizing_field's curvature_angle
  double curvature_angle = BM::Remeshing_sizing_field<K>::default_curvature_angle;
  bool curvature_angle_given = false;
  // detect_model_features()'s feature_angle
  double feature_angle = 30.;
  bool feature_angle_given = false;
  bool refine_ribbons = false;
  bool balance_volumes = true;
  std::string balance_flag; // the last of --balance-volumes / --no-balance-volumes given
  // --region-size-factor and --surface-size-factor as given: name or number, factor
  std::vector<std::pair<std::string, double> > region_size_factors;
  std::vector<std::pair<std::string, double> > surface_size_factors;
};

bool is_gocad_model3d(const std::string& f) { return BM::IO::internal::file_extension(f) == "ml"; }

bool is_tsurf_file(const std::string& f) { return BM::IO::internal::file_extension(f) == "ts"; }

[[noreturn]] void usage_error(const std::string& msg)
{
  std::cerr << "bubble_mesh_3: " << msg << "\n(run 'bubble_mesh_3 --help' for usage)\n";
  std::exit(2);
}

double parse_double(const std::string& opt, const std::string& s)
{
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if(s.empty() || *end != '\0' || !(v == v))
    usage_error("option " + opt + " expects a number, got '" + s + "'");
  return v;
}

// a count of passes or rounds: a whole number from 0 to `most`
std::size_t parse_count(const std::string& opt, const std::string& s, const std::string& what, double most)
{
  const double n = parse_double(opt, s);
  if(!(n >= 0.) || n != std::floor(n) || n > most)
    usage_error(opt + " takes a number of " + what + " from 0 to " + std::to_string(long(most)) + ", got '" + s + "'");
  return std::size_t(n);
}

// a length of --size and --min-size: in model units, or "S%" of the bounding-box
// diagonal, stored as a fraction in `relative` (the other one stays 0)
void parse_length(const std::string& opt, std::string s, double& absolute, double& relative)
{
  const std::string given = s;
  const bool percent = !s.empty() && s.back() == '%';
  if(percent) s.pop_back();
  const double x = parse_double(opt, s);
  if(!(x > 0.) || !std::isfinite(x)) usage_error(opt + " must be a positive number, got '" + given + "'");
  (percent ? relative : absolute) = percent ? x / 100. : x;
}

// NAME=F of --region-size-factor and --surface-size-factor (the name may hold '=': split at the last)
std::pair<std::string, double> parse_name_factor(const std::string& opt, const std::string& s)
{
  const std::size_t eq = s.rfind('=');
  if(eq == std::string::npos || eq == 0 || eq + 1 == s.size())
    usage_error(opt + " takes NAME=FACTOR (e.g. 'Slide_mass=0.5'), got '" + s + "'");
  const double f = parse_double(opt, s.substr(eq + 1));
  if(!(f >= 0.05 && f <= 20.)) usage_error(opt + " takes a factor from 0.05 to 20, got '" + s.substr(eq + 1) + "'");
  return std::make_pair(s.substr(0, eq), f);
}

Options parse_options(int argc, char** argv)
{
  Options o;
  std::vector<std::string> args(argv + 1, argv + argc);
  for(std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    auto value = [&](const std::string& opt) -> std::string {
      if(i + 1 >= args.size()) usage_error("option " + opt + " expects a value");
      return args[++i];
    };
    if(a == "-h" || a == "--help") { std::cout << usage_text; std::exit(0); }
    else if(a == "--check") o.check = true;
    else if(a == "-o" || a == "--output") o.outputs.push_back(value(a));
    else if(a == "--quality-json") o.quality_json = value(a);
    else if(a == "--quality-svg") o.quality_svg = value(a);
    else if(a == "--section-svg") o.section_svg = value(a);
    else if(a == "--section")
    {
      const std::string v = value(a);
      if(!parse_section_choice(v, o.section))
        usage_error(std::string("--section takes ") + section_choice_syntax() + ", got '" + v + "'");
      o.section_given = true;
    }
    else if(a == "--threads") o.threads = long(parse_double(a, value(a)));
    else if(a == "--seed") o.seed = unsigned(parse_double(a, value(a)));
    else if(a == "-q" || a == "--quiet") o.quiet = true;
    else if(a == "--summary-json") o.summary_json = value(a);
    else if(a == "--regions") o.regions = value(a);
    else if(a == "--merge-tolerance") o.merge_tolerance = parse_double(a, value(a));
    else if(a == "--no-sliver-removal") o.sliver_removal = false;
    else if(a == "--keep-steiner-points") o.collapse_steiner_points = false;
    else if(a == "--smooth") o.smoothing_passes = parse_count(a, value(a), "passes", 1000.);
    else if(a == "--sliver-bound") o.sliver_bound = parse_double(a, value(a));
    else if(a == "--remesh-surfaces") o.remesh_surfaces = true;
    else if(a == "--force-law")
    {
      const std::string v = value(a);
      if(v == "repulsive") o.repulsive_force = true;
      else if(v != "cubic") usage_error("--force-law takes cubic or repulsive, not '" + v + "'");
    }
    else if(a == "--paper-overlap-ratio") o.paper_overlap_ratio = true;
    else if(a == "--paper-dynamics") o.paper_dynamics = true;
    else if(a == "--keep-input-triangles") o.keep_input_triangles = true;
    else if(a == "--planar-angle-bound") o.planar_angle_bound = parse_double(a, value(a));
    else if(a == "--axis-planes-only") o.refine_tilted_pieces = false;
    else if(a == "--tilted-size-factor")
    {
      o.tilted_size_factor = parse_double(a, value(a));
      o.tilted_size_factor_given = true;
    }
    else if(a == "--size") parse_length(a, value(a), o.size, o.relative_size);
    else if(a == "--min-size") parse_length(a, value(a), o.min_size, o.relative_min_size);
    else if(a == "--layer-elements")
    {
      const double n = parse_double(a, value(a));
      if(!(n >= 0.) || !(n <= 100.)) usage_error("--layer-elements takes a number from 0 to 100, got '" + args[i] + "'");
      o.layer_elements = n;
      o.layer_elements_given = true;
    }
    else if(a == "--refine-ribbons") o.refine_ribbons = true;
    else if(a == "--balance-volumes" || a == "--no-balance-volumes")
    {
      o.balance_volumes = a == "--balance-volumes";
      o.balance_flag = a;
    }
    else if(a == "--region-size-factor") o.region_size_factors.push_back(parse_name_factor(a, value(a)));
    else if(a == "--surface-size-factor") o.surface_size_factors.push_back(parse_name_factor(a, value(a)));
    else if(a == "--population-rounds") o.population_rounds = parse_count(a, value(a), "rounds", 1000.);
    else if(a == "--population-tolerance")
    {
      const double t = parse_double(a, value(a));
      if(!(t > 0.) || !(t <= 0.1))
        usage_error("--population-tolerance takes a share above 0 and at most 0.1, got '" + args[i] + "'");
      o.population_tolerance = t;
    }
    else if(a == "--size-grading")
    {
      const double g = parse_double(a, value(a));
      if(!(g > 1.) || !(g <= 10.)) usage_error("--size-grading takes a ratio above 1 and at most 10, got '" + args[i] + "'");
      o.size_grading = g;
      o.size_grading_given = true;
    }
    else if(a == "--interior-grading")
    {
      const double g = parse_double(a, value(a));
      if(!(g > 1.) || !(g <= 100.))
        usage_error("--interior-grading takes a ratio above 1 and at most 100, got '" + args[i] + "'");
      o.interior_grading = g;
    }
    else if(a == "--curvature-angle")
    {
      const double d = parse_double(a, value(a));
      if(!(d >= 0.) || !(d <= 90.)) usage_error("--curvature-angle takes degrees from 0 to 90, got '" + args[i] + "'");
      o.curvature_angle = d;
      o.curvature_angle_given = true;
    }
    else if(a == "--feature-angle")
    {
      const double d = parse_double(a, value(a));
      if(!(d > 0.) || !(d < 180.)) usage_error("--feature-angle takes degrees above 0 and under 180, got '" + args[i] + "'");
      o.feature_angle = d;
      o.feature_angle_given = true;
    }
    else if(!a.empty() && a[0] == '-' && a != "-") usage_error("unknown option '" + a + "'");
    else if(o.input.empty()) o.input = a;
    else usage_error("more than one input file ('" + o.input + "' and '" + a + "')");
  }
  if(o.input.empty()) usage_error("no input file given");
  if(o.merge_tolerance < 0) usage_error("--merge-tolerance must not be negative");
  if(!o.regions.empty() && !is_tsurf_file(o.input))
    usage_error("--regions assigns regions to the objects of a GOCAD TSurf (.ts) file, and '" + o.input +
                "' is not one (a .ml file lists its regions itself; an .obj file has one body per group)");
  if((o.size > 0. || o.relative_size > 0.) && !o.remesh_surfaces && (o.keep_input_triangles || !(o.planar_angle_bound > 0.)))
    usage_error("--size sets the size of the re-meshed surfaces, or of the new points on planar pieces: it does "
                "nothing with " + std::string(o.keep_input_triangles ? "--keep-input-triangles" : "--planar-angle-bound 0"));
  if(o.layer_elements_given && !o.remesh_surfaces)
    usage_error("--layer-elements is a rule of --remesh-surfaces: give both");
  if((o.min_size > 0. || o.relative_min_size > 0.) && !o.remesh_surfaces)
    usage_error("--min-size is the floor of a rule of --remesh-surfaces: give both");
  if(o.size_grading_given && !o.remesh_surfaces)
    usage_error("--size-grading is a rule of --remesh-surfaces: give both");
  if(o.curvature_angle_given && !o.remesh_surfaces)
    usage_error("--curvature-angle is a rule of --remesh-surfaces: give both");
  if(o.feature_angle_given && !o.remesh_surfaces)
    usage_error("--feature-angle is a rule of --remesh-surfaces: give both");
  if(o.refine_ribbons && !o.remesh_surfaces)
    usage_error("--refine-ribbons is a rule of --remesh-surfaces: give both");
  if(!o.balance_flag.empty() && !o.remesh_surfaces)
    usage_error(o.balance_flag + " is a rule of --remesh-surfaces (without it the surfaces and volumes are kept "
                "exactly): give both");
  if(!o.surface_size_factors.empty() && !o.remesh_surfaces)
    usage_error("--surface-size-factor sizes the re-meshed surfaces: give --remesh-surfaces too (without it the "
                "input surfaces are kept as they are)");
  if(!o.refine_tilted_pieces && (o.remesh_surfaces || o.keep_input_triangles))
    usage_error("--axis-planes-only chooses which planar pieces get new points: it does nothing with " +
                std::string(o.remesh_surfaces ? "--remesh-surfaces" : "--keep-input-triangles"));
  if(o.tilted_size_factor_given && (!o.refine_tilted_pieces || o.remesh_surfaces || o.keep_input_triangles))
    usage_error("--tilted-size-factor sets which tilted pieces get new points: it does nothing with " +
                std::string(!o.refine_tilted_pieces ? "--axis-planes-only"
                            : o.remesh_surfaces     ? "--remesh-surfaces"
                                                    : "--keep-input-triangles"));
  if(!(o.tilted_size_factor >= 1. && o.tilted_size_factor <= 100.))
    usage_error("--tilted-size-factor must be in [1, 100]");
  if(o.section_given && o.section_svg.empty())
    usage_error("--section chooses the plane of --section-svg: give both");
  if(o.threads < 0) usage_error("--threads must not be negative");
  if(!(o.planar_angle_bound >= 0. && o.planar_angle_bound <= 30.))
    usage_error("--planar-angle-bound must be in [0, 30] degrees");
  if(!(o.sliver_bound > 0. && o.sliver_bound < 70.))
    usage_error("--sliver-bound must be in (0, 70) degrees (a regular tetrahedron has 70.53)");
  for(const std::string& out : o.outputs)
  {
    try { BM::IO::check_mesh_file_name(out); }
    catch(const std::exception& e) { usage_error(e.what()); }
  }
  return o;
}

// The factors of --region-size-factor by region (entry 0, the outside, unused) and
// of --surface-size-factor by patch; empty when none was given. A name that
// matches nothing is a usage error that lists what the model has.
std::vector<double> factors_by_region(const BM::Geological_model_3<K>& model, const Options& o, std::ostream& log)
{
  std::vector<double> f;
  if(o.region_size_factors.empty()) return f;
  f.assign(model.number_of_regions() + 1, 1.);
  for(const auto& given : o.region_size_factors)
  {
    std::size_t matched = 0;
    for(std::size_t r = 1; r <= model.number_of_regions(); ++r)
      if(model.region(r).name == given.first || std::to_string(r) == given.first)
      {
        f[r] = given.second;
        ++matched;
        log << "size factor " << given.second << " in region " << r << " '" << model.region(r).name << "'\n";
        // kept surfaces do not grow with the bubbles (bundled model, region 5 at 2: aspect-ratio
        // median 1.98 -> 3.51 there)
        if(given.second > 1. && !o.remesh_surfaces)
          log << "note: with the surfaces kept, the triangles around region " << r
              << " stay as they are and only its bubbles grow: the tetrahedra between them get poor; "
                 "--remesh-surfaces makes its surfaces coarser too\n";
      }
    if(matched == 0)
    {
      std::string names;
      for(std::size_t r = 1; r <= model.number_of_regions() && r <= 30; ++r)
        names += (r == 1 ? "" : ", ") + std::to_string(r) + " '" + model.region(r).name + "'";
      usage_error("--region-size-factor: " + o.input + " has no region '" + given.first + "'; its regions are " +
                  names + (model.number_of_regions() > 30 ? ", ..." : ""));
    }
  }
  return f;
}

// the surface a patch is a part of: 'F1_2' is part 2 of 'F1' (the readers name the parts
// of a surface cut in several so); a name without such a suffix is its own surface
std::string surface_of(const std::string& patch)
{
  const std::size_t u = patch.rfind('_');
  if(u == std::string::npos || u == 0 || u + 1 == patch.size() ||
     patch.find_first_not_of("0123456789", u + 1) != std::string::npos)
    return patch;
  return patch.substr(0, u);
}

// a patch belongs to surface NAME when it is named NAME, or NAME_k (one part of a surface)
bool is_part_of(const std::string& patch, const std::string& surface)
{
  return patch == surface || surface_of(patch) == surface;
}

// the surfaces' names with their numbers of parts: 'F1_1', 'F1_2' are 'F1' (2 parts)
std::map<std::string, std::size_t> surface_names(const BM::Geological_model_3<K>& model)
{
  std::map<std::string, std::size_t> surfaces;
  for(const auto& patch : model.patches()) ++surfaces[surface_of(patch.name)];
  return surfaces;
}

// 'A', 'B' (3 parts), ... : at most `most` names
std::string list_surfaces(const std::map<std::string, std::size_t>& surfaces, std::size_t most)
{
  std::string names;
  std::size_t k = 0;
  for(const auto& s : surfaces)
  {
    if(k++ == most) return names + ", ...";
    names += (k == 1 ? "'" : ", '") + s.first + "'" +
             (s.second > 1 ? " (" + std::to_string(s.second) + " parts)" : std::string());
  }
  return names;
}

std::vector<double> factors_by_patch(const BM::Geological_model_3<K>& model, const Options& o, std::ostream& log)
{
  std::vector<double> f;
  if(o.surface_size_factors.empty()) return f;
  f.assign(model.number_of_patches(), 1.);
  for(const auto& given : o.surface_size_factors)
  {
    std::size_t matched = 0;
    for(std::size_t p = 0; p < model.number_of_patches(); ++p)
      if(is_part_of(model.patch(p).name, given.first))
      {
        f[p] = given.second;
        ++matched;
      }
    if(matched == 0)
      usage_error("--surface-size-factor: " + o.input + " has no surface '" + given.first + "'; its surfaces are " +
                  list_surfaces(surface_names(model), 30));
    log << "size factor " << given.second << " on surface '" << given.first << "' (" << matched
        << (matched == 1 ? " patch" : " patches") << ")\n";
  }
  return f;
}

// the thickness rule's floor that --min-size gives, in model units (0: not given)
double given_min_size(const Options& o, const BM::Geological_model_3<K>& model)
{
  return o.min_size > 0. ? o.min_size : o.relative_min_size > 0. ? o.relative_min_size * BM::bbox_diagonal(model) : 0.;
}

// The mesh has at least about V / (0.118 h^3) tetrahedra for a region of volume V
// at size h (re-meshed, the re-meshing size; kept, the region's median edge; times
// its --region-size-factor) (regular ones of edge h fill it; a uniform packing gives
// about as many), several times more where thin layers and small features make
// the sizes smaller (12 times on the bundled model re-meshed at the default size;
// 14-16 on it and modelA2 with the defaults before session 56), about 0.5 KB each
// at the peak. A size far too small for the model (a
// typo, a size in the wrong unit) would run for hours and then be killed:
// refuse when even the bound does not fit in the machine's memory, warn when a
// quarter of it does not.
void check_mesh_size(const BM::Geological_model_3<K>& model, const BM::Geological_model_summary& summary,
                     const Options& o, const std::vector<double>& region_factors)
{
  const double diagonal = BM::bbox_diagonal(model);
  const double h = o.size > 0. ? o.size : o.relative_size > 0. ? o.relative_size * diagonal : summary.median_edge_length;
  if(!(h > 0.) || !(diagonal > 0.)) return;
  double at_least = 0.;
  for(const auto& r : summary.regions)
  {
    // kept surfaces: the bubbles inside follow the region's own edges
    const double f = r.index < region_factors.size() ? region_factors[r.index] : 1.;
    const double hr = f * (o.remesh_surfaces ? h : r.median_edge_length);
    if(hr > 0.) at_least += std::abs(r.volume) / (0.1179 * CGAL::square(hr) * hr);
  }
  const double bytes_per_tet = 500.;
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if(pages <= 0 || page <= 0) return;
  const double memory = double(pages) * double(page);
  const bool factors = !region_factors.empty();
  std::ostringstream what;
  what << std::setprecision(3);
  if(o.remesh_surfaces)
    what << "a re-meshing size of " << h << " (" << 100. * h / diagonal << " % of the model's diagonal"
         << (o.size > 0. || o.relative_size > 0. ? "" : ", the median input edge") << ")"
         << (factors ? " with --region-size-factor" : "");
  else
    what << "--region-size-factor";
  what << " asks for at least " << at_least / 1e6 << " million tetrahedra (about " << at_least * bytes_per_tet / 1e9
       << " GB; thin layers make it several times more), and this machine has " << memory / 1e9 << " GB";
  if(at_least * bytes_per_tet > memory)
    usage_error(what.str() + (!factors ? ": give a larger --size (in model units, or e.g. --size 2% of the diagonal)"
                              : o.remesh_surfaces ? ": give larger factors or a larger --size"
                                                  : ": give larger factors"));
  if(4. * at_least * bytes_per_tet > memory && !o.quiet)
    std::cout << "warning: " << what.str() << ": the run may not fit in memory\n";
}

// the points make_bubble_mesh_3() gives a box wall's coordinate back (or, with
// --check, will)
void print_axis_plane_snap(const BM::Axis_plane_snap_report& snap, bool done)
{
  if(snap.number_of_points == 0) return;
  std::cout << std::setprecision(3) << "note: " << snap.number_of_points << " points l" << (done ? "ay" : "ie")
            << " a hair off the axis plane of a box wall they are on (by up to " << snap.largest_move << "): "
            << (done ? "they were given" : "meshing gives them") << " its coordinate, so that the wall is one plane\n"
            << std::defaultfloat;
}

} // namespace

int main(int argc, char** argv)
{
  const Options opt = parse_options(argc, argv);
  BM::Geological_model_3<K> model;
  CGAL::Real_timer timer;
  BM::Patch_side_repair repair;
  try
  {
    timer.start();
    if(opt.regions.empty())
      BM::IO::read_geological_model(opt.input, model, BM::parameters::merge_tolerance(opt.merge_tolerance));
    else
      BM::IO::read_geological_model(opt.input, model,
                                    BM::parameters::region_assignment_file(
                                      opt.regions, BM::parameters::merge_tolerance(opt.merge_tolerance)));
    // a file whose region sides contradict its triangles is mended from the geometry
    repair = BM::orient_patch_sides(model);
    BM::validate_geological_model(model);
    timer.stop();
  }
  catch(const BM::Geological_model_error& e)
  {
    std::cerr << "bubble_mesh_3: invalid input: " << e.what() << "\n";
    if(is_tsurf_file(opt.input) && opt.regions.empty() && std::string(e.what()).find("not closed") != std::string::npos)
      std::cerr << "hint: each TSurf object was taken as the closed surface of a body; for open surfaces "
                   "(horizons, faults, box walls) give --regions FILE with a line 'OBJECT POSITIVE_REGION "
                   "NEGATIVE_REGION' per object\n";
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "bubble_mesh_3: error: " << e.what() << "\n";
    return 1;
  }

  const auto summary = BM::summarize_geological_model(model);
  if(!opt.quiet)
  {
    std::cout << "read and validated " << opt.input << " in " << timer.time() << " s\n";
    for(const std::string& note : model.notes()) std::cout << "note: " << note << "\n";
    if(!repair.swapped_patches.empty())
    {
      const std::vector<std::size_t>& p = repair.swapped_patches;
      std::cout << "note: " << (opt.regions.empty() ? std::string("the file") : "the regions file '" + opt.regions + "'")
                << " puts the regions on the wrong sides of " << p.size()
                << (p.size() == 1 ? " patch" : " patches") << " (";
      for(std::size_t i = 0; i < p.size() && i < 5; ++i)
        std::cout << (i == 0 ? "" : ", ") << "'" << model.patch(p[i]).name << "'";
      std::cout << (p.size() > 5 ? ", ...)" : ")") << ", against their triangles; the sides were taken "
                << "from the geometry (each region's boundary faces out of it)";
      std::size_t between_regions = 0;
      for(const auto& patch : model.patches()) between_regions += patch.is_inside_region() ? 0 : 1;
      if(p.size() == between_regions && is_gocad_model3d(opt.input))
        std::cout << "; as every patch was, the file's ZPOSITIVE (Elevation or Depth) is likely the wrong one";
      std::cout << "\n";
    }
    if(!repair.flipped_triangles.empty())
    {
      const std::vector<std::size_t>& t = repair.flipped_triangles;
      std::cout << "note: " << t.size() << (t.size() == 1 ? " triangle faces against the rest of its patch and "
                                                    : " triangles face against the rest of their patch and ")
                << (t.size() == 1 ? "was" : "were") << " turned over (";
      for(std::size_t i = 0; i < t.size() && i < 3; ++i)
        std::cout << (i == 0 ? "" : ", ") << model.where(model.triangle_source(t[i])) << "triangle " << t[i]
                  << " of " << model.patch_label(model.patch_of_triangle(t[i]));
      std::cout << (t.size() > 3 ? ", ...)" : ")") << "\n";
    }
    BM::write_summary_text(std::cout, summary);
  }
  try
  {
    if(!opt.summary_json.empty())
      BM::IO::internal::write_atomically(opt.summary_json, [&](std::ostream& os) { BM::write_summary_json(os, summary); });
  }
  catch(const std::exception& e)
  {
    std::cerr << "bubble_mesh_3: error: " << e.what() << "\n";
    return 1;
  }
  // names checked before --check returns, so that a check also checks them
  std::ostringstream factor_log;
  const std::vector<double> region_factors = factors_by_region(model, opt, factor_log);
  const std::vector<double> patch_factors = factors_by_patch(model, opt, factor_log);
  if(!opt.quiet) std::cout << factor_log.str();
  if(opt.check && !opt.quiet)
  {
    std::cout << "surfaces (the names --surface-size-factor takes): " << list_surfaces(surface_names(model), 200) << "\n";
    BM::Geological_model_3<K> snapped = model;
    print_axis_plane_snap(BM::snap_points_to_axis_planes(snapped), false);
  }
  if(opt.check) return 0;
  if(opt.remesh_surfaces || !region_factors.empty()) check_mesh_size(model, summary, opt, region_factors);

  // the section's plane, checked against the model before the (long) meshing
  K::Plane_3 cut_plane;
  std::string section_title;
  if(!opt.section_svg.empty())
  {
    std::string description, error;
    if(!section_plane(BM::bbox(model), opt.section, cut_plane, description, error)) usage_error(error);
    section_title = BM::IO::internal::file_name_part(opt.input) + ": " + description;
  }

#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> threads;
  if(opt.threads > 0)
    threads.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, std::size_t(opt.threads)));
#endif

  BM::Mesh_complex_3<K> c3t3;
  BM::Bubble_mesh_report report;
  CGAL::Real_timer stage_timer;
  try
  {
    // Relaxation is the longest stage and can take minutes: a progress line, rewritten
    // in place on a terminal (a few times a second), a line every 30 s in a log.
    const bool terminal = isatty(fileno(stdout)) != 0;
    double last_line = -1e30;
    bool open_line = false;
    std::size_t width = 0;
    auto relaxation_progress = [&](const BM::Relaxation_progress& p) {
      const double now = stage_timer.time();
      if(opt.quiet || now - last_line < (terminal ? 0.25 : 30.)) return;
      last_line = now;
      std::ostringstream line;
      line << "  region " << p.region << ", round " << p.round << ", step " << p.step << ": " << p.population
           << " bubbles (+" << p.added << " -" << p.removed << "), " << p.moving << " moving, largest move "
           << std::setprecision(2)
           << p.max_displacement << " r, " << std::fixed << std::setprecision(0) << now << " s";
      std::string text = line.str();
      // on a terminal, blank what is left of a longer previous line
      if(terminal) { width = (std::max)(width, text.size()); text.resize(width, ' '); }
      std::cout << (terminal ? "\r" : "") << text << (terminal ? "" : "\n") << std::flush;
      open_line = terminal;
    };
    auto progress = [&](const std::string& stage) {
      if(opt.quiet) return;
      if(open_line) std::cout << "\n";
      open_line = false;
      // the re-meshed surfaces' size tells early how long the rest will take (a thin
      // layer across a large model makes its horizons millions of triangles)
      const BM::Surface_remeshing_report& rr = report.surface_remeshing;
      if(stage == "surface bubbles" && report.surfaces_remeshed)
      {
        std::cout << std::setprecision(4) << "  surfaces re-meshed: " << rr.number_of_triangles << " triangles, edges ";
        if(rr.smallest_thickness_size > 0. && rr.smallest_thickness_size < rr.target_size)
          std::cout << "from " << rr.smallest_thickness_size << " (across thin layers and at fault tips) to ";
        std::cout << "the target " << rr.target_size << "\n" << std::defaultfloat;
      }
      std::cout << "[" << std::fixed << std::setprecision(1) << stage_timer.time() << " s] " << stage << "...\n"
                << std::defaultfloat << std::flush;
    };
    stage_timer.start();
    // the ratio G between touching bubbles is the field's g = (G - 1) / (G + 1)
    // (unless given, the library's default for the run: gentler on re-meshed surfaces)
    const double interior_gradation =
      opt.interior_grading > 0. ? (opt.interior_grading - 1.) / (opt.interior_grading + 1.)
                                : BM::Surface_bubble_sizing_field<K>::default_size_gradation_for(opt.remesh_surfaces);
    const auto np = BM::parameters::stage_callback(progress,
                    BM::parameters::bubble_mesh_report(&report,
                    BM::parameters::perturb_interior_vertices(opt.sliver_removal,
                    BM::parameters::collapse_steiner_points(opt.sliver_removal && opt.collapse_steiner_points,
                    BM::parameters::number_of_smoothing_passes(opt.sliver_removal ? opt.smoothing_passes : 0,
                    BM::parameters::sliver_bound(opt.sliver_bound,
                    BM::parameters::keep_input_triangles(opt.keep_input_triangles,
                    BM::parameters::planar_angle_bound(opt.planar_angle_bound,
                    BM::parameters::refine_tilted_pieces(opt.refine_tilted_pieces,
                    BM::parameters::tilted_size_factor(opt.tilted_size_factor,
                    BM::parameters::remesh_input_surfaces(opt.remesh_surfaces,
                    BM::parameters::elements_across_thickness(opt.layer_elements,
                    BM::parameters::size_grading(opt.size_grading,
                    BM::parameters::size_gradation(interior_gradation,
                    BM::parameters::curvature_angle(opt.curvature_angle,
                    BM::parameters::refine_ribbons(opt.refine_ribbons,
                    BM::parameters::feature_angle(opt.feature_angle,
                    BM::parameters::keep_region_volumes(opt.balance_volumes,
                    // re-meshed, a region's factor sizes its surfaces and its inside follows
                    // them; kept, it scales the bubbles inside it only
                    BM::parameters::region_size_factors(opt.remesh_surfaces ? region_factors : std::vector<double>(),
                    BM::parameters::region_scale_factors(opt.remesh_surfaces ? std::vector<double>() : region_factors,
                    BM::parameters::patch_size_factors(patch_factors,
                    BM::parameters::number_of_population_rounds(opt.population_rounds,
                    BM::parameters::population_tolerance(opt.population_tolerance,
                    BM::parameters::solid_angle_overlap_ratio(!opt.paper_overlap_ratio,
                    BM::parameters::wall_overlap_ratio(!opt.paper_overlap_ratio,
                    BM::parameters::inertial_relaxation(!opt.paper_dynamics,
                    CGAL::parameters::random_seed(opt.seed).visitor(std::ref(relaxation_progress))))))))))))))))))))))))))));
    // the size is a named parameter only when given: its absence selects the default
    auto mesh = [&](const auto& with_law) {
      if(opt.size > 0.) BM::make_bubble_mesh_3(model, c3t3, BM::parameters::edge_length(opt.size, with_law));
      else if(opt.relative_size > 0.)
        BM::make_bubble_mesh_3(model, c3t3, BM::parameters::relative_edge_length(opt.relative_size, with_law));
      else BM::make_bubble_mesh_3(model, c3t3, with_law);
    };
    // so is the thickness rule's floor (its default is a tenth of the smallest patch size)
    const double floor = given_min_size(opt, model);
    auto mesh_with_floor = [&](const auto& with_law) {
      if(floor > 0.) mesh(BM::parameters::minimum_edge_length(floor, with_law));
      else mesh(with_law);
    };
    if(opt.repulsive_force) mesh_with_floor(BM::parameters::force_law(BM::Repulsive_bubble_force(), np));
    else mesh_with_floor(np);
    stage_timer.stop();
  }
  catch(const std::exception& e)
  {
    std::cerr << "bubble_mesh_3: meshing failed: " << e.what() << "\n";
    // the surface recovery gave up on a triangle as given: re-meshing replaces those triangles
    if(!opt.remesh_surfaces && dynamic_cast<const BM::Tetrahedralization_error*>(&e))
      std::cerr << "hint: the input triangles could not all be kept as they are (needles on a wall "
                   "that is not an axis plane, say); --remesh-surfaces re-meshes the surfaces first, "
                   "keeping their geometry, contact curves and labels\n";
    return 1;
  }

  const auto& tr = report.tetrahedralization;
  const auto& rr = report.surface_remeshing;
  // the triangles the tetrahedralization saw: the re-meshed ones if re-meshed
  const auto& pr = report.planar_retriangulation;
  const std::size_t meshed_triangles =
    report.surfaces_remeshed ? rr.number_of_triangles
                             : model.number_of_triangles() - pr.number_of_triangles_before + pr.number_of_triangles_after;
  // the sliver removal may have collapsed Steiner points, making triangles whole again
  const auto& sr = report.sliver_removal;
  const std::size_t steiner_points = sr.collapses_done ? sr.number_of_steiner_points_left : tr.number_of_steiner_points();
  const std::size_t kept_whole =
    sr.collapses_done ? meshed_triangles - sr.number_of_triangles_split : tr.number_of_triangles_kept_whole;
  // on re-meshed surfaces, a facet that an input corner forces thin counts with the corner's angle
  const auto quality_np = BM::parameters::number_of_steiner_points(steiner_points,
                            BM::parameters::number_of_input_triangles(meshed_triangles,
                            BM::parameters::number_of_input_triangles_kept_whole(kept_whole)));
  BM::Mesh_quality_report quality;
  if(report.surfaces_remeshed)
  {
    quality = BM::compute_c3t3_quality(c3t3, BM::parameters::facet_input_min_angle(
                                               BM::Corner_forced_facet_angle<BM::Mesh_complex_3<K> >(rr),
                                               BM::parameters::surface_angle_source(
                                                 "boundary facets, or the input corner forcing them", quality_np)));
  }
  else
    quality = BM::compute_c3t3_quality(c3t3, quality_np);
  for(auto& rq : quality.regions)
    if(rq.region >= 1 && std::size_t(rq.region) <= model.number_of_regions())
      rq.name = model.region(std::size_t(rq.region)).name;

  if(!opt.quiet)
  {
    if(report.surfaces_remeshed)
    {
      std::cout << std::setprecision(4) << "surface remeshing: " << model.number_of_triangles() << " -> " << rr.number_of_triangles
                << " triangles, min angle " << rr.input_min_angle << " -> " << rr.min_angle << " deg ("
                << rr.number_of_small_angle_triangles << " triangles under " << rr.angle_bound << " deg, "
                << rr.number_of_forced_small_angle_triangles << " of them forced by input corners, "
                << rr.number_of_small_angle_triangles_in_sharp_wedges << " in the wedges of input corners under "
                << rr.angle_bound << " deg, "
                << rr.number_of_small_angle_triangles_between_curve_points << " between three curve points), edges within "
                << "[0.5, 1.5] of the target " << 100. * rr.input_share_of_edges_within_size
                << " -> " << 100. * rr.share_of_edges_within_size << " %, largest region volume change "
                << rr.max_relative_volume_error;
      if(rr.number_of_volume_balancing_steps > 0)
        std::cout << " (" << rr.volume_error_before_balancing << " before " << rr.number_of_volume_balancing_points
                  << " points slid along the input surfaces)";
      if(!rr.regions_not_balanced.empty() && opt.balance_volumes)
      {
        // what the balance gave the others: the largest change alone would read as if it failed everywhere
        double others = 0.;
        for(std::size_t r = 1; r < rr.input_volumes.size(); ++r)
          if(!std::binary_search(rr.regions_not_balanced.begin(), rr.regions_not_balanced.end(), r))
            others = (std::max)(others, std::abs(rr.relative_volume_change(r)));
        const std::size_t left = rr.regions_not_balanced.size();
        std::cout << " (" << left << (left == 1 ? " region" : " regions") << " left out of the volume balance";
        if(left + 1 < rr.input_volumes.size()) std::cout << "; the others changed by at most " << others;
        std::cout << ")";
      }
      if(rr.number_of_faceted_patches > 0)
        std::cout << " (" << rr.number_of_faceted_patches << " surfaces of convex, coarsely faceted bodies re-meshed "
                  << "with every crease kept, as slides could not give those bodies their volume back)";
      std::cout << ", curve distance " << rr.max_curve_distance << " of the diagonal\n" << std::defaultfloat;
    }
    // a user who asked for a size should know where the mesh is finer, and why
    const double across = report.thickness_rule_relaxed ? report.elements_across_thickness_used : opt.layer_elements;
    if(report.surfaces_remeshed && rr.smallest_thickness_size > 0. && rr.smallest_thickness_size < rr.target_size)
      std::cout << std::setprecision(4) << "note: thin layers or fault tips (thickness down to "
                << rr.smallest_thickness << ") make edges as short as " << rr.smallest_thickness_size
                << " there, under the target size " << rr.target_size << "; --layer-elements (now "
                << across << ") is the number of edges across them: with half as many they are twice as long, "
                   "with 0 the rule is off\n"
                << std::defaultfloat;
    // well below the rule's floor a layer is crossed by one flat tetrahedron: say where that starts
    if(report.surfaces_remeshed && rr.smallest_thickness_size > 0. && rr.smallest_thickness_size < rr.target_size &&
       rr.smallest_thickness_size > 2. * rr.smallest_thickness)
      std::cout << std::setprecision(4) << "note: edges stop at " << rr.smallest_thickness_size
                << " (the thickness rule's floor): where a layer is thinner than " << across * rr.smallest_thickness_size
                << " (here down to " << rr.smallest_thickness
                << ": a pinch-out's tip, or a layer thinner than that all along), its tetrahedra are flat (at the thinnest, "
                << rr.smallest_thickness_size / rr.smallest_thickness
                << " times wider than thick); --min-size lowers the floor everywhere, --region-size-factor for that "
                   "layer lowers it and the layer's size (many more tetrahedra)\n"
                << std::defaultfloat;
    // a floor at the target or above leaves the rule nothing to refine: the user meant a finer floor
    const double min_size = given_min_size(opt, model);
    if(report.surfaces_remeshed && min_size >= rr.target_size)
      std::cout << std::setprecision(4) << "note: --min-size " << min_size
                << " is not under the target size " << rr.target_size
                << ": the thickness rule makes no edge shorter than the target, so thin layers and fault tips are "
                   "not refined; a --min-size under the target lets it\n"
                << std::defaultfloat;
    // new triangles are chords across the input's creases: on a curved, coarsely
    // faceted surface (a tunnel of 16 facets) that changes a region's volume by
    // percents, unless the balance gave it back
    if(report.surfaces_remeshed)
    {
      std::vector<std::pair<double, std::size_t> > changed;
      for(std::size_t r = 1; r < rr.input_volumes.size(); ++r)
        if(std::abs(rr.relative_volume_change(r)) > 0.01) changed.push_back(std::make_pair(rr.relative_volume_change(r), r));
      std::sort(changed.begin(), changed.end(), [](const std::pair<double, std::size_t>& a,
                                                  const std::pair<double, std::size_t>& b) {
        return std::abs(a.first) > std::abs(b.first);
      });
      if(!changed.empty())
      {
        const std::streamsize precision = std::cout.precision(3);
        std::cout << "note: re-meshing changed the volume of";
        for(std::size_t i = 0; i < changed.size() && i < 3; ++i)
          std::cout << (i ? "," : "") << " region " << changed[i].second << " '"
                    << model.region(changed[i].second).name << "' by " << std::showpos << 100. * changed[i].first
                    << std::noshowpos << " %";
        if(changed.size() > 3) std::cout << " and " << changed.size() - 3 << " more";
        if(opt.balance_volumes)
          std::cout << ": the new triangles cut across bends that all turn one way there (a convex body faceted "
                       "coarsely, or the rock around one), so sliding the new points along the input surfaces cannot "
                       "give it back, and its surfaces were not re-meshed with their creases kept (not tried where "
                       "a surface has input angles under 5 degrees, not kept where more triangles came out under 20 "
                       "degrees); a smaller --curvature-angle or --size shrinks the change, and without "
                       "--remesh-surfaces the surfaces and volumes are kept exactly\n";
        else
          std::cout << ": the new triangles cut across the bends of curved surfaces; without --no-balance-volumes "
                       "the new points slide along the input surfaces until every region has its volume back, and "
                       "where the bends all turn one way (a convex body faceted coarsely) the body's surfaces are "
                       "re-meshed with their creases kept; a smaller --curvature-angle shrinks the change\n";
        std::cout.precision(precision);
      }
    }
    print_axis_plane_snap(report.axis_plane_snap, true);
    if(report.thickness_rule_relaxed)
      std::cout << "note: the surface recovery failed on the re-meshed surfaces: " << report.thickness_rule_relaxed_because
                << "; they were re-meshed again with --layer-elements " << report.elements_across_thickness_used
                << (report.elements_across_thickness_used > 0. ? " (fewer edges across thin layers and pinch-outs)"
                                                               : " (the rule off: edges of the target size across thin "
                                                                 "layers and down to pinch-outs)")
                << "; giving it skips the failed attempt\n";
    if(report.planar_patches_retriangulated)
    {
      std::cout << std::setprecision(4) << "planar pieces: " << pr << "\n" << std::defaultfloat;
      // walls refined to a median set by a small fine body make the whole box that fine
      // (the real models of ../shared get at most 2.9 times their points)
      if(!(opt.size > 0. || opt.relative_size > 0.) && pr.number_of_points_added > 5 * model.number_of_points())
        std::cout << std::setprecision(4) << "note: the planar pieces got " << pr.number_of_points_added
                  << " new points, over five times the input's " << model.number_of_points()
                  << ", with edges up to the median input edge " << summary.median_edge_length
                  << ", and the volume beside them is meshed as finely; where a small, finely triangulated body "
                     "(an ore lens, a tunnel) makes that median small, --size S above it keeps them coarser\n"
                  << std::defaultfloat;
      if(report.tilted_refinement_undone)
        std::cout << "note: the surface recovery failed with new points on tilted pieces (curved surfaces' "
                     "triangles): "
                  << report.tilted_refinement_undone_because
                  << "; the mesh was made again with only the axis-plane pieces refined (--axis-planes-only "
                     "skips the failed attempt)\n";
      else if(report.tilted_refinement_coarsened)
        std::cout << "note: the surface recovery failed with --tilted-size-factor " << opt.tilted_size_factor
                  << ": " << report.tilted_refinement_undone_because
                  << "; the mesh was made again with --tilted-size-factor " << BM::fallback_tilted_size_factor
                  << " (giving it skips the failed attempt)\n";
    }
    // sliver removal may add interior vertices: count them too, so that the total is the mesh's
    std::cout << "mesh: " << c3t3.number_of_cells_in_complex() << " tetrahedra, " << quality.all.number_of_vertices
              << " vertices (" << report.number_of_surface_bubbles << " surface points, "
              << tr.number_of_interior_points_inserted << " bubbles, " << steiner_points
              << " Steiner points (" << sr.number_of_steiner_points_collapsed << " others collapsed by sliver removal), "
              << report.sliver_removal.number_of_vertices_inserted
              << " added by sliver removal)\n"
              << (report.surfaces_remeshed ? "re-meshed" : "input") << " triangles kept whole: "
              << kept_whole << " of " << meshed_triangles << " (" << std::setprecision(4)
              << 100. * double(kept_whole) / double((std::max)(meshed_triangles, std::size_t(1))) << " %"
              << (report.planar_patches_retriangulated ? "; planar pieces counted re-triangulated" : "") << ")\n"
              << std::defaultfloat
              << "time: " << (report.surfaces_remeshed ? "surface remeshing " + std::to_string(report.time_surface_remeshing) + " s, " : std::string())
              << "surface bubbles " << report.time_surface_bubbles << " s, placement "
              << report.time_placement << " s, relaxation " << report.time_relaxation
              << " s, tetrahedralization " << report.time_tetrahedralization << " s, sliver removal "
              << report.time_sliver_removal << " s\n";
    if(tr.number_of_guard_points > 0)
      std::cout << "note: the surface recovery failed at first on a tilted outer wall (planar only up to the "
                   "rounding of its points) and was run again with "
                << tr.number_of_guard_points << " guard points mirrored beyond such walls (removed from the mesh)\n";
    // also when no cell was under the bound at first: smoothing and flips may still have run
    if(opt.sliver_removal)
      std::cout << "sliver removal: tetrahedra with a dihedral angle under " << sr.sliver_bound << " degrees "
                << sr.number_of_slivers_before << " -> " << sr.number_of_slivers_after << ", smallest dihedral "
                << sr.min_dihedral_angle_before << " -> " << sr.min_dihedral_angle_after << " degrees ("
                << sr.min_dihedral_angle_after_perturbation << " after the bubble moves; "
                << sr.number_of_vertices_moved << " bubbles moved, "
                << (sr.number_of_smoothing_passes ? std::to_string(sr.number_of_smoothing_moves) + " smoothing moves in " +
                                                      std::to_string(sr.number_of_smoothing_passes) + " passes (" +
                                                      std::to_string(sr.time_smoothing) + " s), "
                                                  : std::string())
                << sr.number_of_steiner_points_collapsed
                << " Steiner points collapsed, " << sr.number_of_2_3_flips + sr.number_of_edge_removals << " flips, "
                << sr.number_of_vertices_inserted << " vertices inserted; " << sr.time_perturbation << " s, "
                << sr.time_collapses << " s, " << sr.time_flips << " s, " << sr.time_insertion << " s)\n";
    // A region no thicker than its surface triangles are wide (a thin layer, a small body
    // given by a few triangles) gets no bubble inside: its tetrahedra join surface points. Say so, and what gives a
    // finer mesh (the input's own size is the default, as in the paper).
    {
      std::vector<std::size_t> population(model.number_of_regions() + 1, 0);
      for(const auto& rr : report.relaxation.regions)
        if(rr.region < population.size()) population[rr.region] = rr.population;
      std::vector<std::size_t> bare;
      for(std::size_t r = 1; r <= model.number_of_regions(); ++r)
        if(population[r] == 0) bare.push_back(r);
      if(!bare.empty())
      {
        std::cout << "note: " << bare.size() << " of " << model.number_of_regions() << " regions got no bubble inside (";
        for(std::size_t k = 0; k < bare.size() && k < 5; ++k)
          std::cout << (k ? ", " : "") << "'" << model.region(bare[k]).name << "'";
        std::cout << (bare.size() > 5 ? ", ..." : "") << "): they are no thicker than their surface triangles are wide, "
                  << "so their tetrahedra join surface points only; for a finer mesh, "
                  << (report.surfaces_remeshed
                        // the thickness rule stops at its floor, a tenth of the smallest patch size:
                        // a region factor lowers both there without refining the rest of the model
                        ? "give that region a size factor under 1 (e.g. --region-size-factor '" +
                            model.region(bare[0]).name + "=0.3': its surfaces get finer, and so does the floor of the "
                            "thickness rule, a tenth of the smallest surface size; many more tetrahedra), a --min-size under that "
                            "floor, or a smaller --size"
                        : std::string("re-mesh the surfaces at a smaller size (--remesh-surfaces --size S, e.g. --size 2% for edges of 2 % of the model's diagonal)"))
                  << "\n";
      }
    }
    BM::IO::write_quality_report_text(std::cout, quality);
  }

  try
  {
    for(const std::string& out : opt.outputs)
    {
      BM::IO::write_mesh(out, c3t3, model);
      if(!opt.quiet) std::cout << "wrote " << out << "\n";
    }
    if(!opt.quality_json.empty())
      BM::IO::internal::write_atomically(opt.quality_json,
                                         [&](std::ostream& os) { BM::IO::write_quality_report_json(os, quality); });
    if(!opt.quality_svg.empty())
      BM::IO::internal::write_atomically(opt.quality_svg,
                                         [&](std::ostream& os) { BM::IO::write_svg_histograms(os, quality); });
    if(!opt.section_svg.empty())
    {
      std::vector<std::string> names(model.number_of_regions() + 1);
      for(std::size_t r = 1; r <= model.number_of_regions(); ++r) names[r] = model.region(r).name;
      BM::IO::internal::write_atomically(opt.section_svg, [&](std::ostream& os) {
        BM::IO::write_svg_section(os, c3t3, cut_plane,
                                  BM::parameters::region_names(names, BM::parameters::svg_title(section_title,
                                  BM::parameters::highlight_dihedral_below(10.))));
      });
      if(!opt.quiet) std::cout << "wrote " << opt.section_svg << "\n";
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "bubble_mesh_3: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
