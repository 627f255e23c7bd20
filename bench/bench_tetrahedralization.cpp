// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// bench_tetrahedralization (issue 6): our tetrahedralization stage
// (tetrahedralize_bubbles: filtering + Delaunay insertion + surface recovery +
// labelling) against TetGen -p and -pY on the same surface points and the same
// interior points (TetGen's -i switch). A benchmark, not a test.

#include "peer_inputs.h"

#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/IO/internal/write_atomically.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>
#include <CGAL/Bubble_mesh_3/Surface_bubble_sizing_field.h>

#if __has_include(<CGAL/Bubble_mesh_3/tetrahedralize_bubbles.h>)
#include <CGAL/Bubble_mesh_3/tetrahedralize_bubbles.h>
#define BUBBLE_MESH_3_BENCH_HAS_TETRAHEDRALIZE 1
#endif
#if __has_include(<CGAL/Bubble_mesh_3/relax_bubbles.h>)
#include <CGAL/Bubble_mesh_3/relax_bubbles.h>
#define BUBBLE_MESH_3_BENCH_HAS_RELAX 1
#endif

#include <CGAL/Real_timer.h>

#include <sys/wait.h>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace BM = CGAL::Bubble_mesh_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;

namespace {

const char* usage =
  "Usage: bench_tetrahedralization [MODEL ...] [--out-dir DIR] [--timeout S] [--repeat N]\n"
  "                                [--interior relaxed|initial] [--relax-seconds S] [--tetgen PATH]\n"
  "\n"
  "Issue 6's benchmark: for each model, the same surface points (the model's) and the\n"
  "same interior points - the bubble centres of our pipeline: surface bubbles, clustering,\n"
  "initial placement and, with --interior relaxed (the default when relax_bubbles.h is\n"
  "there), relaxation with default parameters - are meshed by\n"
  "  ours        tetrahedralize_bubbles() in process (filtering + Delaunay insertion +\n"
  "              surface recovery + labelling); CPU and wall time, the stage's own steps\n"
  "  TetGen -pAi  and  TetGen -pYAi   on DIR/NAME.poly + DIR/NAME.a.node (-A: region\n"
  "              labels, as ours; -NEF: no output files), CPU time as TetGen reports it\n"
  "              ('Total running seconds', clock() from after reading the input) and wall\n"
  "              time of the process; a crash, abort or timeout is recorded as the result\n"
  "and prints the ratios ours / TetGen per model (CPU and wall). With --repeat N each\n"
  "run is repeated and the fastest kept.\n"
  "\n"
  "Default models: the bundled examples/Bubble_mesh_3/data/layered_model.obj and every .ml\n"
  "in ../shared/data/geomodels (next to the checkout) when present.\n"
  "\n"
  "Options:\n"
  "  --out-dir DIR   where the TetGen inputs and logs go (default /tmp/bench_tetrahedralization)\n"
  "  --timeout S     time limit per TetGen run, seconds (default 120)\n"
  "  --repeat N      runs per mesher, the fastest is kept (default 1)\n"
  "  --interior K    relaxed (default if available) or initial (placement only)\n"
  "  --relax-seconds S  stop the relaxation after S seconds per model (default 60): the\n"
  "                  benchmark is about the tetrahedralization, the points only need to be\n"
  "                  the pipeline's kind of points\n"
  "  --tetgen PATH   the TetGen program (default: tetgen on PATH)\n"
  "\n"
  "Exit status: 0 when every model was read (whatever the meshers did), 1 otherwise, 2 on\n"
  "bad usage.\n";

int usage_error(const std::string& what)
{
  std::cerr << "bench_tetrahedralization: " << what << "\n(see bench_tetrahedralization --help)\n";
  return 2;
}

std::string dir_name(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

std::string shell_quote(const std::string& s)
{
  std::string r = "'";
  for(char c : s)
  {
    if(c == '\'') r += "'\\''";
    else r += c;
  }
  return r + "'";
}

bool file_exists(const std::string& f)
{
  std::ifstream is(f);
  return bool(is);
}

// the bundled model and ../shared/data/geomodels/*.ml, found from this source's path
std::vector<std::string> default_models()
{
  const std::string repo = dir_name(dir_name(__FILE__));
  std::vector<std::string> models;
  const std::string bundled = repo + "/examples/Bubble_mesh_3/data/layered_model.obj";
  if(file_exists(bundled)) models.push_back(bundled);
  const std::string shared = repo + "/../shared/data/geomodels";
  std::vector<std::string> ml;
  if(DIR* d = opendir(shared.c_str()))
  {
    while(dirent* e = readdir(d))
    {
      const std::string n = e->d_name;
      if(n.size() > 3 && n.compare(n.size() - 3, 3, ".ml") == 0) ml.push_back(shared + "/" + n);
    }
    closedir(d);
  }
  else
    std::cout << "(" << shared << " not found: only the bundled model)\n";
  std::sort(ml.begin(), ml.end());
  models.insert(models.end(), ml.begin(), ml.end());
  return models;
}

struct Run
{
  std::string status = "not run"; // ok, timeout, crash, error, not available
  std::string detail;
  double cpu = std::numeric_limits<double>::quiet_NaN();
  double wall = std::numeric_limits<double>::quiet_NaN();
  std::size_t tets = 0, vertices = 0, steiner = 0;
  std::string extra;
};

double number_after(const std::string& text, const std::string& key)
{
  const std::size_t at = text.rfind(key);
  if(at == std::string::npos) return std::numeric_limits<double>::quiet_NaN();
  return std::strtod(text.c_str() + at + key.size(), nullptr);
}

Run run_tetgen(const std::string& tetgen, const std::string& switches, const std::string& dir,
               const std::string& name, double timeout, int repeat)
{
  Run best;
  for(int k = 0; k < repeat; ++k)
  {
    const std::string log = dir + "/" + name + "." + switches.substr(1) + ".log";
    const std::string cmd = "cd " + shell_quote(dir) + " && exec timeout -s KILL " + std::to_string(timeout) + " " +
                            shell_quote(tetgen) + " " + switches + " " + shell_quote(name + ".poly") + " > " +
                            shell_quote(log) + " 2>&1";
    CGAL::Real_timer wall;
    wall.start();
    const int status = std::system(cmd.c_str());
    wall.stop();
    Run r;
    r.wall = wall.time();
    std::ifstream is(log);
    std::stringstream ss;
    ss << is.rdbuf();
    const std::string text = ss.str();
    // timeout(1) exits 124 when it killed TetGen; a TetGen killed by a signal (an
    // abort) makes timeout raise the same signal on itself, seen here as 128 + N
    int code = -1;
    if(status != -1 && WIFEXITED(status)) code = WEXITSTATUS(status);
    else if(status != -1 && WIFSIGNALED(status)) code = 128 + WTERMSIG(status);
    if(code == 0)
    {
      r.status = "ok";
      r.cpu = number_after(text, "Total running seconds:");
      r.tets = std::size_t(number_after(text, "Mesh tetrahedra:"));
      r.vertices = std::size_t(number_after(text, "Mesh points:"));
      const double s1 = number_after(text, "Steiner points inside domain:");
      const double s2 = number_after(text, "Steiner points on facets:");
      const double s3 = number_after(text, "Steiner points on segments:");
      r.steiner = std::size_t((s1 == s1 ? s1 : 0.) + (s2 == s2 ? s2 : 0.) + (s3 == s3 ? s3 : 0.));
    }
    else if(code == 124 || code == 137)
    {
      r.status = "timeout";
      r.detail = "killed after " + std::to_string(int(timeout)) + " s";
    }
    else if(code > 128)
    {
      r.status = "crash";
      r.detail = std::string(strsignal(code - 128)) + " (signal " + std::to_string(code - 128) + ")";
      const std::size_t a = text.find("Assertion");
      if(a != std::string::npos)
      {
        const std::size_t line_start = text.rfind('\n', a);
        const std::size_t line_end = text.find('\n', a);
        std::string line = text.substr(line_start == std::string::npos ? 0 : line_start + 1,
                                       line_end == std::string::npos ? std::string::npos : line_end - line_start - 1);
        const std::size_t cxx = line.find("tetgen.cxx");
        if(cxx != std::string::npos) line = line.substr(cxx);
        r.detail += ", " + line;
      }
    }
    else
    {
      r.status = "error";
      r.detail = "exit " + std::to_string(code);
    }
    if(k == 0 || (r.status == "ok" && (best.status != "ok" || r.wall < best.wall))) best = r;
    if(r.status != "ok") break; // a crash or timeout is not retried
  }
  return best;
}

std::string seconds(double s)
{
  if(!(s == s)) return "-";
  std::ostringstream os;
  os << std::fixed << std::setprecision(s < 10 ? 3 : 1) << s;
  return os.str();
}

std::string ratio(double a, double b)
{
  if(!(a == a) || !(b == b) || b <= 0.) return "-";
  std::ostringstream os;
  os << std::fixed << std::setprecision(2) << a / b;
  return os.str();
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> models;
  std::string out_dir = "/tmp/bench_tetrahedralization", tetgen = "tetgen";
#ifdef BUBBLE_MESH_3_BENCH_HAS_RELAX
  std::string interior = "relaxed";
#else
  std::string interior = "initial";
#endif
  double timeout = 120., relax_seconds = 60.;
  int repeat = 1;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if(i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    std::string v;
    if(a == "-h" || a == "--help")
    {
      std::cout << usage;
      return EXIT_SUCCESS;
    }
    else if(a == "--out-dir") { if(!value(out_dir)) return usage_error("--out-dir needs a directory"); }
    else if(a == "--tetgen") { if(!value(tetgen)) return usage_error("--tetgen needs a program"); }
    else if(a == "--interior")
    {
      if(!value(interior) || (interior != "relaxed" && interior != "initial"))
        return usage_error("--interior is relaxed or initial");
    }
    else if(a == "--timeout")
    {
      if(!value(v) || !(std::strtod(v.c_str(), nullptr) > 0.)) return usage_error("--timeout needs seconds > 0");
      timeout = std::strtod(v.c_str(), nullptr);
    }
    else if(a == "--relax-seconds")
    {
      if(!value(v) || !(std::strtod(v.c_str(), nullptr) > 0.)) return usage_error("--relax-seconds needs seconds > 0");
      relax_seconds = std::strtod(v.c_str(), nullptr);
    }
    else if(a == "--repeat")
    {
      if(!value(v) || std::atoi(v.c_str()) < 1) return usage_error("--repeat needs a count >= 1");
      repeat = std::atoi(v.c_str());
    }
    else if(a.size() > 1 && a[0] == '-') return usage_error("unknown option '" + a + "'");
    else models.push_back(a);
  }
#ifndef BUBBLE_MESH_3_BENCH_HAS_RELAX
  if(interior == "relaxed") return usage_error("--interior relaxed: this build has no relax_bubbles.h");
#endif
  if(models.empty()) models = default_models();
  if(models.empty()) return usage_error("no model given and the bundled model was not found");
  if(std::system(("mkdir -p " + shell_quote(out_dir)).c_str()) != 0)
  {
    std::cerr << "bench_tetrahedralization: cannot create '" << out_dir << "'\n";
    return EXIT_FAILURE;
  }
  const bool have_tetgen = std::system(("command -v " + shell_quote(tetgen) + " > /dev/null 2>&1").c_str()) == 0;

  std::ostringstream command;
  command << "bench_tetrahedralization";
  for(int i = 1; i < argc; ++i) command << ' ' << shell_quote(argv[i]);
  std::cout << "reproduce with: " << command.str() << "\n"
            << "interior points: " << interior << " bubble centres; TetGen: "
            << (have_tetgen ? tetgen : std::string("not found")) << "; time limit " << timeout << " s, repeat "
            << repeat << "\n";

  struct Line
  {
    std::string model;
    std::size_t points = 0, triangles = 0, interior = 0;
    Run ours, p, py;
  };
  std::vector<Line> lines;
  bool all_read = true;
  for(const std::string& file : models)
  {
    Line line;
    line.model = BM::bench::base_name(file);
    std::cout << "\n== " << file << std::endl;
    BM::Geological_model_3<K> model;
    try
    {
      BM::IO::read_geological_model(file, model);
    }
    catch(const std::exception& e)
    {
      std::cerr << "bench_tetrahedralization: error: " << e.what() << "\n";
      all_read = false;
      continue;
    }
    line.points = model.number_of_points();
    line.triangles = model.number_of_triangles();

    // the interior points: our pipeline's bubble centres
    std::vector<Point_3> points;
    try
    {
      CGAL::Real_timer t;
      t.start();
      const auto surface_bubbles = BM::place_surface_bubbles(model);
      const BM::Surface_bubble_sizing_field<K> sizing(model, surface_bubbles, CGAL::parameters::default_values());
      auto bubbles = BM::place_initial_bubbles(model, surface_bubbles, sizing);
#ifdef BUBBLE_MESH_3_BENCH_HAS_RELAX
      if(interior == "relaxed")
      {
        // stopped by its visitor once the budget is spent: the points are then less relaxed, not fewer
        CGAL::Real_timer relax_timer;
        relax_timer.start();
        auto within_budget = [&relax_timer, relax_seconds](const BM::Relaxation_progress&) {
          return relax_timer.time() < relax_seconds;
        };
        BM::relax_bubbles(model, surface_bubbles, bubbles, sizing, CGAL::parameters::visitor(within_budget));
        if(relax_timer.time() >= relax_seconds)
          std::cout << "relaxation stopped after its budget of " << relax_seconds << " s (--relax-seconds)\n";
      }
#endif
      for(const auto& b : bubbles) points.push_back(b.center);
      std::cout << points.size() << " interior points (" << interior << " bubbles, " << seconds(t.time())
                << " s to place)" << std::endl;
    }
    catch(const std::exception& e)
    {
      std::cerr << "bench_tetrahedralization: placement failed: " << e.what() << "\n";
      line.ours.status = line.p.status = line.py.status = "error";
      line.ours.detail = std::string("placement: ") + e.what();
      lines.push_back(line);
      continue;
    }
    line.interior = points.size();

    // TetGen's inputs: the PLC with region seeds, and the same interior points
    const std::string name = line.model;
    try
    {
      const auto seeds = BM::bench::region_seed_points(model);
      for(std::size_t r = 1; r < seeds.size(); ++r)
        if(!seeds[r].found) std::cout << "warning: no seed point in " << model.region_label(r) << "\n";
      BM::IO::internal::write_atomically(out_dir + "/" + name + ".poly", [&](std::ostream& os) {
        BM::bench::write_tetgen_poly(os, model, seeds);
      });
      BM::IO::internal::write_atomically(out_dir + "/" + name + ".a.node", [&](std::ostream& os) {
        BM::bench::write_tetgen_node(os, points);
      });
    }
    catch(const std::exception& e)
    {
      std::cerr << "bench_tetrahedralization: error: " << e.what() << "\n";
      return EXIT_FAILURE;
    }

    // ours
#ifdef BUBBLE_MESH_3_BENCH_HAS_TETRAHEDRALIZE
    for(int k = 0; k < repeat; ++k)
    {
      Run r;
      BM::Mesh_complex_3<K> c3t3;
      // process CPU time by clock(), as TetGen measures its own
      const std::clock_t cpu_start = std::clock();
      CGAL::Real_timer wall;
      try
      {
        wall.start();
        const BM::Tetrahedralization_report rep = BM::tetrahedralize_bubbles(model, points, c3t3);
        wall.stop();
        r.status = "ok";
        r.cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
        r.wall = wall.time();
        r.tets = rep.number_of_cells;
        r.vertices = rep.number_of_vertices;
        r.steiner = rep.number_of_steiner_points();
        std::ostringstream os;
        os << std::fixed << std::setprecision(3) << "filtering " << rep.time_filtering << " s, insertion "
           << rep.time_insertion << " s, recovery " << rep.time_recovery << " s, labelling " << rep.time_labelling
           << " s; " << rep.number_of_interior_points_inserted << " interior points kept; triangles kept whole "
           << std::setprecision(1) << 100. * rep.share_of_triangles_kept_whole() << " %";
        r.extra = os.str();
      }
      catch(const std::exception& e)
      {
        r.status = "error";
        r.detail = e.what();
        r.wall = wall.time();
        r.cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
      }
      if(k == 0 || (r.status == "ok" && r.wall < line.ours.wall)) line.ours = r;
      if(r.status != "ok") break;
    }
#else
    line.ours.status = "not available";
    line.ours.detail = "tetrahedralize_bubbles.h is not in this checkout";
#endif
    std::cout << "ours         " << line.ours.status << "  cpu " << seconds(line.ours.cpu) << " s, wall "
              << seconds(line.ours.wall) << " s, " << line.ours.tets << " tets, " << line.ours.vertices
              << " vertices, " << line.ours.steiner << " Steiner points" << (line.ours.detail.empty() ? "" : "; ")
              << line.ours.detail << "\n             " << line.ours.extra << std::endl;

    // TetGen, same points
    for(int which = 0; which < 2; ++which)
    {
      Run& r = which == 0 ? line.p : line.py;
      const std::string sw = which == 0 ? "-pAiNEF" : "-pYAiNEF";
      if(!have_tetgen)
      {
        r.status = "not available";
        r.detail = "TetGen not found";
      }
      else
        r = run_tetgen(tetgen, sw, out_dir, name, timeout, repeat);
      std::cout << "tetgen " << (which == 0 ? "-p   " : "-pY  ") << " " << r.status << "  cpu " << seconds(r.cpu)
                << " s, wall " << seconds(r.wall) << " s, " << r.tets << " tets, " << r.vertices << " vertices, "
                << r.steiner << " points added (Steiner + -i points)" << (r.detail.empty() ? "" : "; ") << r.detail
                << std::endl;
    }
    lines.push_back(line);
  }

  // the table of ratios
  std::cout << "\nTetrahedralization stage, ours / TetGen on the same points (lower is faster for us);\n"
            << "CPU: our process CPU time vs TetGen's own 'Total running seconds'; wall: in-process vs the whole\n"
            << "TetGen process (reading its input included)\n\n"
            << "| model | input points | input triangles | interior points | ours cpu / wall (s) | TetGen -p cpu / wall (s) "
               "| TetGen -pY cpu / wall (s) | ratio cpu vs -p | ratio cpu vs -pY | ratio wall vs -p | ratio wall vs -pY "
               "| tets ours / -p / -pY |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  auto cell = [](const Run& r) {
    if(r.status == "ok") return seconds(r.cpu) + " / " + seconds(r.wall);
    return r.status + (r.detail.empty() ? std::string() : " (" + r.detail + ")");
  };
  auto ok = [](const Run& r, double v) { return r.status == "ok" ? v : std::numeric_limits<double>::quiet_NaN(); };
  for(const Line& l : lines)
    std::cout << "| " << l.model << " | " << l.points << " | " << l.triangles << " | " << l.interior << " | "
              << cell(l.ours) << " | " << cell(l.p) << " | " << cell(l.py) << " | "
              << ratio(ok(l.ours, l.ours.cpu), ok(l.p, l.p.cpu)) << " | "
              << ratio(ok(l.ours, l.ours.cpu), ok(l.py, l.py.cpu)) << " | "
              << ratio(ok(l.ours, l.ours.wall), ok(l.p, l.p.wall)) << " | "
              << ratio(ok(l.ours, l.ours.wall), ok(l.py, l.py.wall)) << " | "
              << (l.ours.status == "ok" ? std::to_string(l.ours.tets) : "-") << " / "
              << (l.p.status == "ok" ? std::to_string(l.p.tets) : "-") << " / "
              << (l.py.status == "ok" ? std::to_string(l.py.tets) : "-") << " |\n";
  std::cout << "\nreproduce with: " << command.str() << std::endl;
  return all_read ? EXIT_SUCCESS : EXIT_FAILURE;
}
