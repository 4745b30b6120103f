// Progress of long cavity-modes work: a line at least every 5 s, with an estimate of the time left where the work
// is counted (cluster 3/26). A driver installs one Progress for its run; the steps it counts report through it,
// and inner loops that can run for long (Lanczos steps, SLEPc iterations) call progress_tick(), which prints only
// when the interval has passed since the last line. Without an installed Progress, ticks do nothing.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace rc::modes {

class Progress {
 public:
  using Sink = std::function<void(const std::string&)>;
  // Installs itself as the run's progress until destroyed (the one it replaces is restored then); `sink` receives
  // each line.
  explicit Progress(Sink sink, double interval_seconds = 5.0);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // A step of the work: printed if a second has passed since the last line. With total > 0, `done` of `total`
  // items are finished, and the line (and later ticks) carry the time left at the rate since this count began;
  // `left_of` says what that time is of when the count is not the whole run (" in this round": more may follow).
  void step(const std::string& what, std::size_t done = 0, std::size_t total = 0, const std::string& left_of = "");
  // A result the user should see (a round's outcome): always printed, on the run's clock; ends the current count.
  void note(const std::string& what);
  // From an inner loop: a line if the interval has passed since the last one.
  void tick();
  double elapsed() const;

 private:
  std::string line(const std::string& state) const;
  void emit(const std::string& text);

  using Clock = std::chrono::steady_clock;
  Progress* previous_;
  Sink sink_;
  double interval_;
  Clock::time_point start_ = Clock::now();
  double last_line_ = 0, last_step_ = 0, count_start_ = 0;
  std::string what_, left_of_;
  std::size_t done_ = 0, total_ = 0;
};

// The installed Progress's tick(), or nothing.
void progress_tick();

}  // namespace rc::modes
