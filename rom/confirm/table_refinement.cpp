#include "table_refinement.hpp"

#include "recorded_command.hpp"

#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

namespace rc::rom {
namespace fs = std::filesystem;
namespace {
using cd = std::complex<double>;

// The options whose value the remade table's request replaces: the output and the exact frequencies always, the Ekman
// number when it is given anew, the mesh level when it is raised.
bool is_replaced(const std::string& name, const ResponseRemake& remake) {
  return name == "-o" || name == "--output" || name == "--exact-at" || (remake.ekman > 0 && name == "--ekman") ||
         (remake.finer > 0 && name == "--mesh-level");
}

}  // namespace

std::vector<cd> tank_frequencies(double omega, const std::vector<cd>& roots) {
  std::vector<cd> out;
  for (const cd& sigma : roots) {
    const cd s0 = (sigma + omega) / omega;
    const cd s = omega > 0 ? s0 : std::conj(s0);
    bool repeat = false;
    for (const cd& t : out) repeat = repeat || std::abs(t - s) <= 1e-12 * std::max(1.0, std::abs(s));
    if (!repeat) out.push_back(s);
  }
  return out;
}

bool is_krylov_table(const rc::ModeTable& t) {
  return t.viscous() && t.normalisation.find("rational Krylov space") != std::string::npos;
}

std::vector<std::string> remake_response_arguments(const rc::ModeTable& t, const ResponseRemake& remake,
                                                   const fs::path& output, const fs::path& scratch) {
  if (!is_krylov_table(t))
    throw std::runtime_error("it is not a Krylov response table (remake it with cavity-modes response ... -o FILE.h5 "
                             "without --fit or --galerkin to refine it)");
  if (t.command_line.empty()) throw std::runtime_error("it records no command line (made before provenance)");
  const std::vector<std::string> w = shell_words(t.command_line);
  if (w.size() < 3 || w[1] != "response" || !is_shape(w[2]))
    throw std::runtime_error("its recorded command line is not 'cavity-modes response SHAPE ...': " + t.command_line);
  std::vector<std::string> args{"response", w[2]};
  const bool section = w[2] == "section";
  bool have_file = false;
  int level = 0;
  for (std::size_t i = 3; i < w.size(); ++i) {
    const std::string& word = w[i];
    if (word.size() < 2 || word[0] != '-') {  // positional: the section's file
      args.push_back(section && !have_file ? section_file(t, word, scratch).string() : word);
      have_file = have_file || section;
      continue;
    }
    const auto eq = word.find('=');
    const std::string name = word.substr(0, eq);
    if (!is_replaced(name, remake)) {
      args.push_back(word);
      continue;
    }
    const std::string value = eq != std::string::npos ? word.substr(eq + 1) : i + 1 < w.size() ? w[i + 1] : "";
    if (name == "--mesh-level") level = std::stoi(value);
    if (eq == std::string::npos) ++i;  // its value is the next word
  }
  if (section && !have_file) throw std::runtime_error("its recorded command line names no section file");
  if (remake.ekman > 0) args.insert(args.end(), {"--ekman", number_text(remake.ekman)});
  if (remake.finer > 0) args.insert(args.end(), {"--mesh-level", std::to_string(level + remake.finer)});
  if (!remake.exact_at.empty()) args.insert(args.end(), {"--exact-at", complex_list(remake.exact_at)});
  args.insert(args.end(), {"-o", output.string()});
  return args;
}

std::vector<std::string> refine_arguments(const rc::ModeTable& t, const std::vector<cd>& exact_at,
                                          const fs::path& output, const fs::path& scratch) {
  return remake_response_arguments(t, {exact_at, 0, 0}, output, scratch);
}

fs::path refining_name(const fs::path& file) { return file.parent_path() / (file.stem().string() + ".refining.h5"); }

void run_and_replace(const std::vector<std::string>& args, const fs::path& file, const fs::path& output,
                     const fs::path& scratch, const ProgramRunner& run) {
  const int status = run(args, (scratch / "refine.log").string());
  if (status != 0) {
    std::error_code gone;
    fs::remove(output, gone);
    throw std::runtime_error("refining " + file.string() + ": cavity-modes " +
                             (status < 0 ? "did not start" : "exited with status " + std::to_string(status)) +
                             " (the table is unchanged)");
  }
  fs::rename(output, file);
}

void check_refinable(const Scene& scene, const ChainModel& m) {
  for (int k = 0; k < m.n; ++k) {
    if (m.bodies[k].ekman <= 0) continue;
    const fs::path& file = scene.bodies[k].cavity->table;
    const rc::ModeTable t = rc::read_mode_table(file);
    if (!is_krylov_table(t))
      throw SceneError("body[" + std::to_string(k + 1) + "].cavity.table " + file.string() +
                       ": --refine-tables remakes Krylov response tables only, and this is not one (remake it with "
                       "cavity-modes response ... -o FILE.h5 without --fit or --galerkin)");
  }
}

std::vector<RefinedTable> refine_tables(const Scene& scene, const ChainModel& m, const std::vector<cd>& roots,
                                        const std::string& binary, const fs::path& scratch, const ProgramRunner& run,
                                        std::ostream& log) {
  // One run per table file, with the frequencies of every body that uses it (bodies of other spins add their own).
  std::map<std::string, std::vector<cd>> frequencies;
  for (int k = 0; k < m.n; ++k) {
    if (m.bodies[k].ekman <= 0) continue;
    auto& f = frequencies[scene.bodies[k].cavity->table.string()];
    for (const cd& s : tank_frequencies(m.bodies[k].omega, roots)) f.push_back(s);
  }
  std::vector<RefinedTable> out;
  for (const auto& [name, exact_at] : frequencies) {
    const auto t0 = std::chrono::steady_clock::now();
    const fs::path file = name;
    const fs::path tmp = refining_name(file);
    std::vector<std::string> args{binary};
    for (auto& a : refine_arguments(rc::read_mode_table(file), exact_at, tmp, scratch)) args.push_back(std::move(a));
    log << "  " << file.string() << ": R made exact at " << exact_at.size() << " frequencies:";
    for (const auto& a : args) log << " " << a;
    log << std::endl;
    run_and_replace(args, file, tmp, scratch, run);
    out.push_back({file, static_cast<int>(exact_at.size()),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()});
  }
  return out;
}

}  // namespace rc::rom
