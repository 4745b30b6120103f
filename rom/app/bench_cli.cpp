// `chain-rom bench`: error against run time (docs/rom.md, "Benchmark").
#include "commands.hpp"

#include "bench.hpp"
#include "external_programs.hpp"
#include "load_scene.hpp"
#include "scene.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace rc::rom::app {

Command add_bench_command(CLI::App& app) {
  struct Options {
    std::string scene, out, png;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "bench", "error against run time: the state at run.t_end by exact, gauss (step sweep) and rk45 (tolerance "
               "sweep) against an extended-precision reference, and the roots' error against the number of kept "
               "modes with and without static_correction (docs/rom.md, \"Benchmark\")");
  cmd->add_option("SCENE", o->scene, "scene file (TOML) with a [run] section (t_end, initial state)")->required();
  cmd->add_option("-o,--output", o->out, "CSV: part,method,parameter,value,steps,body,static_correction,"
                                         "spin_factor,coverage,wall_seconds,cpu_seconds,error");
  cmd->add_option("--png", o->png, "also draw it (scripts/plot_bench.py with /usr/bin/python3 + matplotlib); needs -o");
  return {cmd, [o] {
            if (!o->png.empty() && o->out.empty()) throw std::runtime_error("--png: needs -o (the CSV it is drawn from)");
            const std::filesystem::path out(o->out);
            if (!o->out.empty() && out.has_parent_path() && !std::filesystem::is_directory(out.parent_path()))
              throw std::runtime_error(o->out + ": the output folder does not exist");
            if (!o->png.empty()) check_plot_tools(RC_PLOT_BENCH_SCRIPT, "figure");  // before the benchmark
            const BenchResult r = run_bench(load_scene(o->scene), {}, [](const BenchRow& row) {
              std::printf("%s\n", format_bench_row(row).c_str());
              std::fflush(stdout);
            });
            if (r.reference_mantissa_bits > 0)
              std::printf("t_end = %g s, first-order dimension %d, fastest root |sigma| = %.4g rad/s, reference: long "
                          "double (%d-bit mantissa)\n", r.t_end, r.dimension, r.spectral_radius, r.reference_mantissa_bits);
            else  // two spins: periodic coefficients (docs/rom.md, "Bodies at different spins")
              std::printf("t_end = %g s, first-order dimension %d, fastest root |sigma| = %.4g rad/s, reference: Magnus "
                          "steps in double, four times as many a period as the roots settled with\n", r.t_end,
                          r.dimension, r.spectral_radius);
            if (!o->out.empty()) {
              write_bench_csv(r, out);
              std::printf("wrote %s: %zu rows\n", o->out.c_str(), r.rows.size());
            }
            if (!o->png.empty()) draw_plot(RC_PLOT_BENCH_SCRIPT, o->out, o->png);
            return 0;
          }};
}

}  // namespace rc::rom::app
