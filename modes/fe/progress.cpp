#include "progress.hpp"

#include <fmt/format.h>

namespace rc::modes {
namespace {

Progress* installed = nullptr;

std::string duration(double s) {
  if (s < 90) return fmt::format("{:.0f} s", s);
  if (s < 5400) return fmt::format("{:.0f} min", s / 60);
  return fmt::format("{:.1f} h", s / 3600);
}

}  // namespace

Progress::Progress(Sink sink, double interval_seconds)
    : previous_(installed), sink_(std::move(sink)), interval_(interval_seconds) {
  installed = this;
}

Progress::~Progress() { installed = previous_; }

double Progress::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

std::string Progress::line(const std::string& state) const {
  std::string s = fmt::format("[{:7.1f} s] {}{}", elapsed(), what_, state);
  if (total_ > 0 && done_ > 0 && done_ < total_) {
    // At the rate of the count so far, less the time already spent on the current item.
    const double per_item = (last_step_ - count_start_) / static_cast<double>(done_);
    const double left = per_item * static_cast<double>(total_ - done_) - (elapsed() - last_step_);
    if (left >= 1) s += fmt::format(", about {} left{}", duration(left), left_of_);
  }
  return s;
}

void Progress::emit(const std::string& text) {
  last_line_ = elapsed();
  if (sink_) sink_(text);
}

void Progress::step(const std::string& what, std::size_t done, std::size_t total, const std::string& left_of) {
  const double now = elapsed();
  // A new count starts when the total changes or the count goes back: its rate is measured from the previous step.
  if (total > 0 && (total != total_ || done < done_)) count_start_ = last_step_;
  what_ = what;
  left_of_ = left_of;
  done_ = done;
  total_ = total;
  last_step_ = now;
  if (now >= 1.0 && now - last_line_ >= 1.0) emit(line(""));
}

void Progress::note(const std::string& what) {
  what_ = what;
  left_of_.clear();
  done_ = total_ = 0;
  last_step_ = elapsed();
  emit(line(""));
}

void Progress::tick() {
  if (elapsed() - last_line_ >= interval_) emit(line(what_.empty() ? "working" : " (working)"));
}

void progress_tick() {
  if (installed) installed->tick();
}

}  // namespace rc::modes
