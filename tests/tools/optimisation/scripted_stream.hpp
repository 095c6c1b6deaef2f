#pragma once

#include <deque>
#include <stdexcept>

#include "tools/optimisation/random_stream.hpp"

namespace mrd::test {

// A random stream that plays back given numbers, so an operator can be checked by hand.
class ScriptedStream final : public tools::RandomStream {
 public:
  ScriptedStream(std::deque<double> uniforms, std::deque<double> cauchies = {})
      : uniforms_(std::move(uniforms)), cauchies_(std::move(cauchies)) {}
  double uniform() override { return next(uniforms_); }
  double cauchy() override { return next(cauchies_); }
  [[nodiscard]] bool exhausted() const { return uniforms_.empty() && cauchies_.empty(); }

 private:
  static double next(std::deque<double>& q) {
    if (q.empty()) throw std::logic_error("scripted stream ran out of numbers");
    const double x = q.front();
    q.pop_front();
    return x;
  }
  std::deque<double> uniforms_, cauchies_;
};

}  // namespace mrd::test
