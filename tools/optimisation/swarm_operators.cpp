#include "tools/optimisation/swarm_operators.hpp"

#include <algorithm>
#include <cmath>

namespace mrd::tools::swarm {

double inertia_weight(int d, int d_max, double w_max, double w_min) {
  if (d_max <= 0) return w_min;
  const double progress = std::clamp(static_cast<double>(d) / d_max, 0.0, 1.0);
  return w_max - (w_max - w_min) * progress;  // Eq. 16
}

Point velocity_update(const Point& v, const Point& x, const Point& personal_best,
                      const Point& global_best, double w, double c1, double c2,
                      const Point& v_max, RandomStream& random) {
  Point next(v.size());
  for (Eigen::Index j = 0; j < v.size(); ++j) {
    const double r1 = random.uniform();
    const double r2 = random.uniform();
    const double vj = w * v[j] + c1 * r1 * (personal_best[j] - x[j]) +
                      c2 * r2 * (global_best[j] - x[j]);  // Eq. 14
    next[j] = std::clamp(vj, -v_max[j], v_max[j]);
  }
  return next;
}

void move_particle(Point& x, Point& v, const Bounds& bounds) {
  x += v;  // Eq. 14
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    if (x[j] < bounds.lower[j] || x[j] > bounds.upper[j]) {
      x[j] = std::clamp(x[j], bounds.lower[j], bounds.upper[j]);
      v[j] = 0.0;
    }
  }
}

DonorIndices pick_donors(std::size_t n, std::size_t exclude, RandomStream& random) {
  // Draw from the n - 1 candidates other than `exclude`, then skip the ones already taken.
  auto draw = [&](std::initializer_list<std::size_t> taken) {
    while (true) {
      std::size_t i = random.index(n - 1);
      if (i >= exclude) ++i;
      if (std::find(taken.begin(), taken.end(), i) == taken.end()) return i;
    }
  };
  const std::size_t p1 = draw({});
  const std::size_t p2 = draw({p1});
  const std::size_t p3 = draw({p1, p2});
  return {p1, p2, p3};
}

Point de_mutant(const Point& q_p1, const Point& q_p2, const Point& q_p3, double F) {
  return q_p1 + F * (q_p2 - q_p3);  // Eq. 18
}

Point de_crossover(const Point& mutant, const Point& x, double CR, RandomStream& random) {
  Point trial = x;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    if (random.uniform() <= CR) trial[j] = mutant[j];  // Eq. 19
  }
  const auto j_rand = static_cast<Eigen::Index>(random.index(static_cast<std::size_t>(x.size())));
  trial[j_rand] = mutant[j_rand];
  return trial;
}

bool de_select(Point& x, double& fitness_x, const Point& trial, double fitness_trial) {
  if (!(fitness_trial <= fitness_x)) return false;  // Eq. 20; a NaN trial never wins
  x = trial;
  fitness_x = fitness_trial;
  return true;
}

Point cauchy_mutation(const Point& global_best, double scale, const Bounds& bounds,
                      RandomStream& random) {
  Point next = global_best;
  for (Eigen::Index j = 0; j < next.size(); ++j) {
    next[j] += scale * global_best[j] * random.cauchy();  // Eq. 22
  }
  return bounds.clamp(next);
}

}  // namespace mrd::tools::swarm
