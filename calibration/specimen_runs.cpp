#include "calibration/specimen_runs.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <stdexcept>
#include <thread>
#include <vector>

namespace ffp {

SpecimenRuns::SpecimenRuns(NumericalTriaxial triaxial, int concurrency)
    : triaxial_(std::move(triaxial)), concurrency_(concurrency) {
  if (!triaxial_) throw std::invalid_argument("SpecimenRuns: no numerical triaxial");
  if (concurrency_ < 1) throw std::invalid_argument("SpecimenRuns: concurrency must be ≥ 1");
}

const SpecimenCurve& SpecimenRuns::at(double eta) {
  if (const auto found = curves_.find(eta); found != curves_.end()) {
    ++reuses_;
    return found->second;
  }
  SpecimenCurve curve = triaxial_(eta);
  ++runs_;
  return curves_.emplace(eta, std::move(curve)).first->second;
}

void SpecimenRuns::run_all(std::span<const double> etas) {
  std::vector<double> missing;
  for (double eta : etas)
    if (!has(eta) && std::find(missing.begin(), missing.end(), eta) == missing.end()) missing.push_back(eta);
  if (missing.empty()) return;
  const std::size_t workers = std::min(missing.size(), static_cast<std::size_t>(concurrency_));
  if (workers == 1) {
    for (double eta : missing) at(eta);
    return;
  }
  // Each worker takes the next η; results and failures land in η's own slot, so
  // no two threads write the same element.
  std::vector<SpecimenCurve> results(missing.size());
  std::vector<std::exception_ptr> failures(missing.size());
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k = next++; k < missing.size(); k = next++) {
      try {
        results[k] = triaxial_(missing[k]);
      } catch (...) {
        failures[k] = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
    work();
  }  // joined
  for (std::size_t k = 0; k < missing.size(); ++k) {
    if (failures[k]) continue;
    curves_.emplace(missing[k], std::move(results[k]));
    ++runs_;
  }
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace ffp
