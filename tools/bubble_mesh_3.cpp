// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bubble_mesh_3: the command-line program. It only parses options and calls the
// package; every stage it runs is a free function of the library.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>
#include <CGAL/Bubble_mesh_3/geological_model_summary.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>
#include <CGAL/Real_timer.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
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
"INPUT  a GOCAD Model3d (.ml), GOCAD TSurf (.ts) or multi-body OBJ (.obj) file.\n"
"\n"
"Options:\n"
"  -h, --help                 show this help and exit\n"
"  --check                    read and validate the model, print its summary, do not mesh\n"
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
  bool check = false;
  bool quiet = false;
  std::string summary_json;
  double merge_tolerance = 0.;
};

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
    else if(a == "-q" || a == "--quiet") o.quiet = true;
    else if(a == "--summary-json") o.summary_json = value(a);
    else if(a == "--merge-tolerance") o.merge_tolerance = parse_double(a, value(a));
    else if(!a.empty() && a[0] == '-' && a != "-") usage_error("unknown option '" + a + "'");
    else if(o.input.empty()) o.input = a;
    else usage_error("more than one input file ('" + o.input + "' and '" + a + "')");
  }
  if(o.input.empty()) usage_error("no input file given");
  if(o.merge_tolerance < 0) usage_error("--merge-tolerance must not be negative");
  return o;
}

} // namespace

int main(int argc, char** argv)
{
  const Options opt = parse_options(argc, argv);
  BM::Geological_model_3<K> model;
  CGAL::Real_timer timer;
  try
  {
    timer.start();
    BM::IO::read_geological_model(opt.input, model,
                                  BM::parameters::merge_tolerance(opt.merge_tolerance));
    BM::validate_geological_model(model);
    timer.stop();
  }
  catch(const BM::Geological_model_error& e)
  {
    std::cerr << "bubble_mesh_3: invalid input: " << e.what() << "\n";
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
  if(opt.check) return 0;
  if(!opt.quiet)
    std::cout << "meshing is not available yet in this version: stopping after validation\n";
  return 0;
}
