#include "tools/optimisation/particle_swarm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tools/optimisation/random_stream.hpp"
#include "tools/optimisation/swarm_operators.hpp"

namespace mrd::tools {

namespace {

// The state both swarms share: positions, velocities, personal and global bests.
struct Swarm {
  std::vector<Point> x, v, personal_best;
  std::vector<double> fitness, personal_best_fitness;
  std::size_t best = 0;  // index into personal_best
  std::int64_t evaluations = 0;

  [[nodiscard]] const Point& global_best() const { return personal_best[best]; }
  [[nodiscard]] double global_best_fitness() const { return personal_best_fitness[best]; }

  // Eq. 17: uniform initial positions inside the bounds, zero velocity.
  Swarm(BatchObjective& objective, const Bounds& bounds, int population, RandomStream& random) {
    const auto n = static_cast<std::size_t>(population);
    const Eigen::Index dim = bounds.dimension();
    for (std::size_t i = 0; i < n; ++i) {
      Point p(dim);
      for (Eigen::Index j = 0; j < dim; ++j) {
        p[j] = random.uniform() * (bounds.upper[j] - bounds.lower[j]) + bounds.lower[j];
      }
      x.push_back(p);
      v.push_back(Point::Zero(dim));
    }
    objective.evaluate(x, fitness);
    evaluations += population;
    personal_best = x;
    personal_best_fitness = fitness;
    refresh_best();
  }

  void offer_personal_best(std::size_t i, const Point& p, double f) {
    if (f <= personal_best_fitness[i]) {
      personal_best[i] = p;
      personal_best_fitness[i] = f;
    }
  }

  void refresh_best() {
    for (std::size_t i = 0; i < personal_best.size(); ++i) {
      if (personal_best_fitness[i] < personal_best_fitness[best]) best = i;
    }
  }

  void record(OptimisationResult& result) const {
    result.convergence.push_back({evaluations, global_best_fitness()});
  }

  void finish(OptimisationResult& result) const {
    result.best = global_best();
    result.fitness = global_best_fitness();
    result.evaluations = evaluations;
  }
};

Point velocity_limits(const Bounds& bounds, double fraction) {
  return fraction * (bounds.upper - bounds.lower);
}

}  // namespace

OptimisationResult run_classical_pso(BatchObjective& objective, const Bounds& bounds,
                                     const Budget& budget, const ClassicalPsoSettings& settings,
                                     std::uint64_t seed) {
  SeededStream random(seed);
  Swarm swarm(objective, bounds, budget.population, random);
  OptimisationResult result;
  swarm.record(result);
  const Point v_max = velocity_limits(bounds, settings.velocity_limit);
  while (swarm.evaluations + budget.population <= budget.evaluations) {
    for (std::size_t i = 0; i < swarm.x.size(); ++i) {
      swarm.v[i] = swarm::velocity_update(swarm.v[i], swarm.x[i], swarm.personal_best[i],
                                          swarm.global_best(), settings.w, settings.c1,
                                          settings.c2, v_max, random);
      swarm::move_particle(swarm.x[i], swarm.v[i], bounds);
    }
    objective.evaluate(swarm.x, swarm.fitness, &swarm.personal_best_fitness);
    swarm.evaluations += budget.population;
    for (std::size_t i = 0; i < swarm.x.size(); ++i) {
      swarm.offer_personal_best(i, swarm.x[i], swarm.fitness[i]);
    }
    swarm.refresh_best();
    swarm.record(result);
  }
  swarm.finish(result);
  return result;
}

OptimisationResult run_improved_pso(BatchObjective& objective, const Bounds& bounds,
                                    const Budget& budget, const ImprovedPsoSettings& settings,
                                    std::uint64_t seed) {
  SeededStream random(seed);
  Swarm swarm(objective, bounds, budget.population, random);
  OptimisationResult result;
  swarm.record(result);
  const Point v_max = velocity_limits(bounds, settings.velocity_limit);
  const auto n = swarm.x.size();
  const int planned_iterations =
      static_cast<int>((budget.evaluations - budget.population) / budget.population);

  std::vector<Point> trials(n);
  std::vector<double> trial_fitness(n);
  int stalled = 0;
  for (int d = 0; swarm.evaluations + budget.population <= budget.evaluations; ++d) {
    const double w = swarm::inertia_weight(d, planned_iterations, settings.w_max, settings.w_min);
    for (std::size_t i = 0; i < n; ++i) {
      // The PSO move (Eq. 14, 16) proposes; DE (Eq. 18-19) recombines it with a mutant of
      // the personal bests. One evaluation per particle per iteration.
      swarm.v[i] = swarm::velocity_update(swarm.v[i], swarm.x[i], swarm.personal_best[i],
                                          swarm.global_best(), w, settings.c1, settings.c2,
                                          v_max, random);
      Point moved = swarm.x[i];
      swarm::move_particle(moved, swarm.v[i], bounds);
      const auto donors = swarm::pick_donors(n, i, random);
      const double F =
          settings.F_spread > 0.0 ? settings.F + settings.F_spread * random.uniform() : settings.F;
      const Point mutant = swarm::de_mutant(swarm.personal_best[donors.p1],
                                            swarm.personal_best[donors.p2],
                                            swarm.personal_best[donors.p3], F);
      trials[i] = bounds.clamp(swarm::de_crossover(mutant, moved, settings.CR, random));
    }
    objective.evaluate(trials, trial_fitness, &swarm.fitness);  // Eq. 20 compares with x_i
    swarm.evaluations += budget.population;
    const double previous_best = swarm.global_best_fitness();
    for (std::size_t i = 0; i < n; ++i) {
      swarm::de_select(swarm.x[i], swarm.fitness[i], trials[i], trial_fitness[i]);  // Eq. 20
      swarm.offer_personal_best(i, trials[i], trial_fitness[i]);
    }
    swarm.refresh_best();

    const double gain = previous_best - swarm.global_best_fitness();
    stalled = gain > settings.stall_tolerance * std::fabs(previous_best) ? 0 : stalled + 1;
    if (stalled >= settings.stall_iterations &&
        swarm.evaluations + settings.cauchy_trials + budget.population <= budget.evaluations) {
      // Eq. 21-22 around the global best. A better point takes the place of the worst
      // particle, so the swarm follows it.
      std::vector<Point> jumps;
      for (int t = 0; t < settings.cauchy_trials; ++t) {
        jumps.push_back(swarm::cauchy_mutation(swarm.global_best(), settings.cauchy_scale,
                                               bounds, random));
      }
      std::vector<double> jump_fitness;
      const std::vector<double> to_beat(jumps.size(), swarm.global_best_fitness());
      objective.evaluate(jumps, jump_fitness, &to_beat);
      swarm.evaluations += settings.cauchy_trials;
      result.cauchy_trials += settings.cauchy_trials;
      const auto best_jump = static_cast<std::size_t>(
          std::min_element(jump_fitness.begin(), jump_fitness.end()) - jump_fitness.begin());
      if (jump_fitness[best_jump] < swarm.global_best_fitness()) {
        const auto worst = static_cast<std::size_t>(
            std::max_element(swarm.personal_best_fitness.begin(),
                             swarm.personal_best_fitness.end()) -
            swarm.personal_best_fitness.begin());
        swarm.x[worst] = swarm.personal_best[worst] = jumps[best_jump];
        swarm.fitness[worst] = swarm.personal_best_fitness[worst] = jump_fitness[best_jump];
        swarm.v[worst].setZero();
        swarm.best = worst;
        ++result.cauchy_accepted;
      }
      stalled = 0;
    }
    swarm.record(result);
  }
  swarm.finish(result);
  return result;
}

}  // namespace mrd::tools
