#include "console/tune/optimiser.hpp"

#include <stdexcept>
#include <utility>

#include <pagmo/algorithms/pso_gen.hpp>
#include <pagmo/bfe.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include "robot/core/error.hpp"

namespace stride::tune {
namespace {

// pagmo's user problem: the bounds only; fitness comes in batches (Batch below), never one by one.
struct Bounds {
  std::vector<double> lower, upper;
  pagmo::vector_double fitness(const pagmo::vector_double&) const {
    throw std::logic_error("tune: candidates are evaluated as whole generations only");
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {lower, upper};
  }
};

// pagmo's user batch evaluator: a generation's decision vectors, concatenated, to one call.
struct Batch {
  const BatchObjective* evaluate = nullptr;
  pagmo::vector_double operator()(const pagmo::problem& p, const pagmo::vector_double& dvs) const {
    const std::size_t n = p.get_nx();
    std::vector<std::vector<double>> candidates;
    for (std::size_t at = 0; at + n <= dvs.size(); at += n)
      candidates.emplace_back(dvs.begin() + static_cast<std::ptrdiff_t>(at),
                              dvs.begin() + static_cast<std::ptrdiff_t>(at + n));
    const std::vector<double> objective = (*evaluate)(candidates);
    if (objective.size() != candidates.size()) throw Error("tune: an objective per candidate");
    pagmo::vector_double fitness(objective.size());
    for (std::size_t i = 0; i < objective.size(); ++i)
      fitness[i] = -objective[i];  // pagmo minimises
    return fitness;
  }
};

}  // namespace

void run_search(const SearchSettings& s, const BatchObjective& evaluate) {
  // pso_gen, not cmaes: pagmo 2.18's cmaes has no batch evaluator; a generation must be one sweep.
  const Batch batch{&evaluate};
  const pagmo::problem problem{Bounds{s.lower, s.upper}};
  const auto seed = static_cast<unsigned>(s.seed);
  pagmo::population population(problem, batch,
                               static_cast<pagmo::population::size_type>(s.population), seed);
  pagmo::pso_gen algorithm(static_cast<unsigned>(s.generations), 0.7298, 2.05, 2.05, 0.5, 5u, 2u,
                           4u, false, seed);
  algorithm.set_bfe(pagmo::bfe{batch});
  algorithm.evolve(population);
}

}  // namespace stride::tune
