// Re-meshes the surfaces of a geological model with bubbles and writes the
// result as a multi-body OBJ; prints the quality before and after.
//
// usage: remesh_surfaces model.ml|.ts|.obj [out.obj] [--isotropic] [--size L] [--relative-size f]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/IO/write_multibody_obj.h>
#include <CGAL/Bubble_mesh_3/remesh_surfaces.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>

#include <cstdlib>
#include <exception>
#include <iomanip>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K> Model;
namespace BM = CGAL::Bubble_mesh_3;

int main(int argc, char** argv)
{
  std::string in_file, out_file = "remeshed.obj";
  BM::Surface_remeshing_method method = BM::Surface_remeshing_method::BUBBLES;
  double size = 0., relative = 0.;
  int positional = 0;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--isotropic") method = BM::Surface_remeshing_method::ISOTROPIC;
    else if(a == "--size" && i + 1 < argc) size = std::atof(argv[++i]);
    else if(a == "--relative-size" && i + 1 < argc) relative = std::atof(argv[++i]);
    else if(positional == 0) { in_file = a; ++positional; }
    else { out_file = a; ++positional; }
  }

  if(in_file.empty())
  {
    std::cout << "usage: remesh_surfaces model.ml|.ts|.obj [out.obj] [--isotropic] [--size L] [--relative-size f]\n";
    return EXIT_SUCCESS;
  }
  Model input;
  try
  {
    BM::IO::read_geological_model(in_file, input);
    BM::validate_geological_model(input);
  }
  catch(const std::exception& e)
  {
    // the reader and the validation name the file and the element
    std::cerr << "remesh_surfaces: " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  Model output;
  BM::Surface_remeshing_report r;
  if(size > 0.)
    r = BM::remesh_surfaces(input, output, BM::parameters::surface_remeshing_method(method, BM::parameters::edge_length(size)));
  else if(relative > 0.)
    r = BM::remesh_surfaces(input, output,
                            BM::parameters::surface_remeshing_method(method, BM::parameters::relative_edge_length(relative)));
  else
    r = BM::remesh_surfaces(input, output, BM::parameters::surface_remeshing_method(method));

  bool valid = true;
  try { BM::validate_geological_model(output); }
  catch(const std::exception& e)
  {
    valid = false;
    std::cout << "output does not validate: " << e.what() << "\n";
  }
  BM::IO::write_multibody_obj(out_file, output);

  std::cout << std::setprecision(4);
  std::cout << in_file << " ("
            << (method == BM::Surface_remeshing_method::BUBBLES ? "bubbles" : "isotropic") << ")\n"
            << "  features: " << r.number_of_corners << " corners, " << r.number_of_curves << " curves, "
            << r.number_of_charts << " charts (" << r.number_of_chart_cuts << " cuts)\n"
            << "  triangles " << input.number_of_triangles() << " -> " << r.number_of_triangles << ", points "
            << input.number_of_points() << " -> " << r.number_of_points << "\n"
            << "  min angle " << r.input_min_angle << " -> " << r.min_angle << " deg; triangles under "
            << r.angle_bound << " deg: " << 100. * r.input_share_of_small_angle_triangles << " % -> "
            << 100. * r.share_of_small_angle_triangles << " % (" << r.number_of_small_angle_triangles << ", of which "
            << r.number_of_forced_small_angle_triangles << " forced by input corners)\n"
            << "  edges within [0.5,1.5] of target: " << 100. * r.input_share_of_edges_within_size << " % -> "
            << 100. * r.share_of_edges_within_size << " %; edge length " << r.min_edge_length << " .. "
            << r.max_edge_length << "\n"
            << "  max volume error " << r.max_relative_volume_error << " (relative), curve Hausdorff "
            << r.max_curve_distance << " (of diagonal), point distance " << r.max_point_distance
            << ", triangle distance " << r.max_triangle_distance << " of local size ("
            << 100. * r.share_of_triangles_beyond_distance << " % beyond " << r.surface_distance << ")\n"
            << "  time " << r.time << " s (features " << r.time_features << ", sizing " << r.time_sizing
            << ", curves " << r.time_curves << ", patches " << r.time_patches << ", measures " << r.time_measures
            << ")\n"
            << "  output " << (valid ? "validates" : "DOES NOT validate") << "; written to " << out_file << "\n";
  return valid ? EXIT_SUCCESS : EXIT_FAILURE;
}
