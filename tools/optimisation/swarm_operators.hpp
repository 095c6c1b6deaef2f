#pragma once

#include <cstddef>

#include "tools/optimisation/optimiser.hpp"
#include "tools/optimisation/random_stream.hpp"

// The update rules of Section 3 as pure functions of their inputs and a random stream, so each
// one is checked against a hand-worked case.
namespace mrd::tools::swarm {

// Eq. 16: inertia falls linearly from w_max at iteration 0 to w_min at iteration d_max.
double inertia_weight(int d, int d_max, double w_max, double w_min);

// Eq. 14, velocity half: v <- w v + c1 r1 (p - x) + c2 r2 (g - x), with fresh r1, r2 per
// component (drawn r1 then r2 for each j). Each component is limited to +-v_max_j.
Point velocity_update(const Point& v, const Point& x, const Point& personal_best,
                      const Point& global_best, double w, double c1, double c2,
                      const Point& v_max, RandomStream& random);

// Eq. 14, position half, kept inside the bounds: a component that would leave stops on the
// bound and loses its velocity, so the particle does not keep pushing against a wall.
void move_particle(Point& x, Point& v, const Bounds& bounds);

// Three mutually distinct indices in [0, n), all different from `exclude` (n >= 4).
struct DonorIndices {
  std::size_t p1, p2, p3;
};
DonorIndices pick_donors(std::size_t n, std::size_t exclude, RandomStream& random);

// Eq. 18: h = q_p1 + F (q_p2 - q_p3).
Point de_mutant(const Point& q_p1, const Point& q_p2, const Point& q_p3, double F);

// Eq. 19: u_j = h_j where rand <= CR, else x_j. One uniform per component, in order; then one
// index j_rand whose component always comes from h (the usual guard, so u != x).
Point de_crossover(const Point& mutant, const Point& x, double CR, RandomStream& random);

// Eq. 20: the trial replaces the parent when it is no worse. Returns true when it did.
bool de_select(Point& x, double& fitness_x, const Point& trial, double fitness_trial);

// Eq. 22: x + x (*) cauchy(0,1), scaled by `scale` (1 is the paper's literal step), one draw
// per component, then clamped to the bounds.
Point cauchy_mutation(const Point& global_best, double scale, const Bounds& bounds,
                      RandomStream& random);

}  // namespace mrd::tools::swarm
