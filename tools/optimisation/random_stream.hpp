#pragma once

#include <cstddef>
#include <cstdint>
#include <random>

namespace mrd::tools {

// The optimisers draw every random number through this interface, so a test can script the
// stream and check an operator against a hand-worked case.
class RandomStream {
 public:
  virtual ~RandomStream() = default;
  virtual double uniform() = 0;  // [0, 1)
  virtual double cauchy() = 0;   // standard Cauchy(0, 1), density Eq. 21
  // Uniform integer in [0, n).
  std::size_t index(std::size_t n);
};

// mt19937_64 with our own conversions (the standard distributions differ between library
// implementations), so a seed gives the same run on every machine.
class SeededStream final : public RandomStream {
 public:
  explicit SeededStream(std::uint64_t seed) : engine_(seed) {}
  double uniform() override;
  double cauchy() override;

 private:
  std::mt19937_64 engine_;
};

}  // namespace mrd::tools
