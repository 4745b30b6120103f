#include "window_fit.hpp"

#include "passivity_scan.hpp"
#include "petsc_handles.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <limits>

namespace rc::modes {
namespace {

constexpr int kMaxRefinements = 6;
constexpr int kMaxPassivityRounds = 8;  // rounds that add samples where the fit dips below Im R = 0 (or errs after that)
constexpr std::size_t kMaxSamplesFactor = 4;

struct HeldOutFit {
  RationalFit fit;
  double error = 0;                 // max |fit − R| over the held-out samples / max |R| on the window
  std::vector<std::size_t> erring;  // window samples (held out) where the fit errs by more than the allowed error
};

// AAA on the even window samples and the tail; judged on the odd window samples.
HeldOutFit fit_window(const std::vector<double>& s, const std::vector<std::complex<double>>& R,
                      const std::vector<double>& tail, const std::vector<std::complex<double>>& tail_R,
                      double max_error) {
  std::vector<double> z;
  std::vector<std::complex<double>> f;
  for (std::size_t k = 0; k < s.size(); k += 2) {
    z.push_back(s[k]);
    f.push_back(R[k]);
  }
  z.insert(z.end(), tail.begin(), tail.end());
  f.insert(f.end(), tail_R.begin(), tail_R.end());
  HeldOutFit w{fit_response(z, f, 1e-10), 0.0, {}};
  double scale = 0;
  for (const auto& r : R) scale = std::max(scale, std::abs(r));
  for (std::size_t k = 1; k < s.size(); k += 2) {
    const double e = std::abs(w.fit(s[k]) - R[k]) / scale;
    w.error = std::max(w.error, e);
    if (!(e <= max_error)) w.erring.push_back(k);
  }
  return w;
}

// Adds samples (s, R) to the sorted window, keeping it sorted.
void merge_samples(std::vector<double>& s, std::vector<std::complex<double>>& R, const std::vector<double>& more_s,
                   const std::vector<std::complex<double>>& more_R) {
  std::vector<std::pair<double, std::complex<double>>> all;
  for (std::size_t k = 0; k < s.size(); ++k) all.emplace_back(s[k], R[k]);
  for (std::size_t k = 0; k < more_s.size(); ++k) all.emplace_back(more_s[k], more_R[k]);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  s.clear();
  R.clear();
  for (const auto& [x, r] : all) {
    s.push_back(x);
    R.push_back(r);
  }
}

// The refinement rounds of window_fit.hpp on one window.
class WindowRefinement {
 public:
  WindowRefinement(const ResponseSampler& sample, std::vector<double> window,
                   std::vector<std::complex<double>> window_R, const std::vector<double>& tail,
                   std::vector<std::complex<double>> tail_R, double max_error,
                   const std::function<void(const std::string&)>& note)
      : window_s(std::move(window)), window_R(std::move(window_R)), sample_(sample), tail_(tail),
        tail_R_(std::move(tail_R)), max_error_(max_error),
        cap_(std::max<std::size_t>(kMaxSamplesFactor * window_s.size(), 400)), lo_(window_s.front()),
        hi_(window_s.back()), note_(note) {
    w = fit_window(window_s, this->window_R, tail_, tail_R_, max_error_);
  }

  void refine_by_error() {
    while (!(w.error <= max_error_) && refinements < kMaxRefinements && window_s.size() < cap_ && !w.erring.empty())
      refine(around_erring(), "error");
  }

  // A fit that is passive after the error's refinement is left as it is; if the rounds end with the error above the
  // allowed one, the last fit within it is taken back (its dip is then reported by the caller).
  void refine_for_passivity() {
    if (!(w.error <= max_error_)) return;
    State passing{window_s, window_R, w};
    for (int round = 0; round < kMaxPassivityRounds && window_s.size() < cap_; ++round) {
      if (w.error <= max_error_) {
        passing = State{window_s, window_R, w};
        const PassivityScan scan = scan_passivity(w.fit.poles, w.fit.residues, lo_, hi_);
        if (scan.passive()) break;
        refine(around(scan.at), "passivity");
      } else {
        if (w.erring.empty()) break;
        refine(around_erring(), "error");
      }
    }
    if (!(w.error <= max_error_)) {
      window_s = std::move(passing.s);
      window_R = std::move(passing.R);
      w = std::move(passing.w);
    }
  }

  std::vector<double> window_s;
  std::vector<std::complex<double>> window_R;
  HeldOutFit w;
  int refinements = 0;

 private:
  struct State {
    std::vector<double> s;
    std::vector<std::complex<double>> R;
    HeldOutFit w;
  };

  // Solves R at `added` (sorted, unique, cut to the cap), merges the samples and fits again.
  void refine(std::vector<double> added, const char* why) {
    std::sort(added.begin(), added.end());
    added.erase(std::unique(added.begin(), added.end()), added.end());
    if (window_s.size() + added.size() > cap_) added.resize(cap_ - window_s.size());
    const std::vector<std::complex<double>> extra = sample_(added, fmt::format("refinement {} ({})", refinements + 1, why));
    merge_samples(window_s, window_R, added, extra);
    ++refinements;
    w = fit_window(window_s, window_R, tail_, tail_R_, max_error_);
    note_(fmt::format("response fit: refinement {} ({}): {} samples on the window, error between them {:.2g}",
                      refinements, why, window_s.size(), w.error));
  }
  void halfway_around(std::size_t k, std::vector<double>& added) const {
    if (k > 0) added.push_back(0.5 * (window_s[k - 1] + window_s[k]));
    if (k + 1 < window_s.size()) added.push_back(0.5 * (window_s[k] + window_s[k + 1]));
  }
  std::vector<double> around_erring() const {
    std::vector<double> added;
    for (const std::size_t k : w.erring) halfway_around(k, added);
    return added;
  }
  // s itself (unless a sample) and halfway to its neighbouring samples.
  std::vector<double> around(double s) const {
    std::vector<double> added;
    const auto k = static_cast<std::size_t>(std::lower_bound(window_s.begin(), window_s.end(), s) - window_s.begin());
    if (k == window_s.size() || window_s[k] != s) added.push_back(s);
    if (k > 0) added.push_back(0.5 * (window_s[k - 1] + s));
    if (k < window_s.size()) added.push_back(0.5 * (s + window_s[k]));
    return added;
  }

  const ResponseSampler& sample_;
  const std::vector<double>& tail_;
  std::vector<std::complex<double>> tail_R_;
  const double max_error_;
  const std::size_t cap_;
  const double lo_, hi_;
  const std::function<void(const std::string&)>& note_;
};

}  // namespace

std::vector<double> response_tail(double lo, double hi) {
  const double reach = std::max({std::abs(lo), std::abs(hi), 1.0});
  std::vector<double> tail;
  for (double t = 1.5 * reach; t <= 1000 * reach; t *= 1.5) {
    if (t > hi) tail.push_back(t);
    if (-t < lo) tail.push_back(-t);
  }
  return tail;
}

WindowedFit fit_on_window(const ResponseSampler& sample, const std::vector<double>& window,
                          const std::vector<double>& tail, double max_error,
                          const std::function<void(const std::string&)>& note) {
  std::vector<double> all = window;
  all.insert(all.end(), tail.begin(), tail.end());
  const std::vector<std::complex<double>> first = sample(all, "first samples");
  const auto n = static_cast<long>(window.size());
  WindowRefinement refinement(sample, window, {first.begin(), first.begin() + n}, tail, {first.begin() + n, first.end()},
                              max_error, note);
  refinement.refine_by_error();
  refinement.refine_for_passivity();
  WindowedFit out;
  out.fit = refinement.w.fit;
  out.error = refinement.w.error;
  out.refinements = refinement.refinements;
  out.samples = refinement.window_s.size();
  out.tail_R = first.back();
  return out;
}

std::complex<double> add_pseudo_modes(ModeTable& t, const RationalFit& fit, double err) {
  std::complex<double> sum = 0;
  for (std::size_t j = 0; j < fit.poles.size(); ++j) {
    const auto p = fit.poles[j], r = fit.residues[j];
    const std::complex<double> a = std::sqrt(r / 2.0);
    t.lambda.push_back(p.real());
    t.kappa.push_back(2 / p.real());
    t.decay.push_back(p.imag());
    t.E.push_back(r.real());
    t.E_imag.push_back(r.imag());
    t.a.push_back(a.real());
    t.a_imag.push_back(a.imag());
    t.N2.push_back(1.0);
    t.residual.push_back(std::max(err, std::numeric_limits<double>::epsilon()));  // the fit's error stands for it
    sum += r;
  }
  return sum;
}

std::string passivity_phrase(const RationalFit& fit, double lo, double hi) {
  const PassivityScan passivity = scan_passivity(fit.poles, fit.residues, lo, hi);
  const std::string passive =
      passivity.passive()
          ? fmt::format("passive on the window (min Im R = {:.2g} max|R|)", passivity.min_im)
          : fmt::format("NOT passive on the window: Im R = {:.2g} max|R| at s = {:.6g}", passivity.min_im, passivity.at);
  if (!passivity.passive() && is_root_rank())
    std::cerr << "cavity-modes: warning: the fit is " << passive
              << " (R itself has Im R >= 0): more samples there (--sigma) or a smaller --max-fit-error\n";
  return passive;
}

}  // namespace rc::modes
