#include "mesh_study_options.hpp"

#include <string>

namespace rc::rom::app {

void add_mesh_study_options(CLI::App* cmd, MeshStudy& study, const std::string& when) {
  cmd->add_option("--refine", study.refine,
                  when + "mesh study: the roots again on this many finer meshes, each with every size of the one before "
                         "halved, and each growth rate with its measured mesh error; 2 or more: the observed order and "
                         "Richardson's extrapolation; 0: the table's mesh only, no error measured (default 1)")
      ->check(CLI::Range(0, 3));
  cmd->add_option("--mesh-size", study.base.mesh_size,
                  when + "mesh study: the forced solves' interior element size in place of the tables' (a study of "
                         "your own; the roots are then not the tables')")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--order", study.base.order,
                  when + "mesh study: the forced solves' Taylor-Hood order (2..6) in place of the tables'")
      ->check(CLI::Range(2, 6));
  cmd->add_option_function<std::string>(
         "--refine-by", [&study](const std::string& by) { study.by_order = by == "order"; },
         when + "mesh study: 'size' (each level halves every element size) or 'order' (each level raises the "
                "Taylor-Hood order by one, up to 6: where a halved mesh would not fit in memory) (default size)")
      ->check(CLI::IsMember({"size", "order"}));
  cmd->add_option("--mesh-tolerance", study.tolerance,
                  when + "mesh study: a growth rate whose measured mesh error exceeds this fraction of it is NOT "
                         "CONVERGED (default 0.02)")
      ->check(CLI::PositiveNumber);
}

}  // namespace rc::rom::app
