#pragma once
// `stride converge`: one scene's walk outcome over solver settings, each an ensemble of perturbed
// starts; prints each setting's figures with their spread, whether it agrees with the reference
// setting, and the cheapest setting that does (the study setting for that scene).
#include <iosfwd>
#include <string>
#include <vector>

#include "console/ensemble/convergence.hpp"
#include "console/experiments/experiment_options.hpp"
#include "simulator/scene/start_perturbation.hpp"

namespace stride::ensemble {

struct ConvergeOptions {
  std::string scene;
  std::vector<std::string> settings;  // "iterations=40,sor=1.0", ...; "scene": as written
  int reference = -1;                 // index into settings; -1: the last
  sim::EnsembleSpec spec;
  double seconds = 17.05;
  Tolerance tolerance;
  int jobs = 1;
  experiments::ExperimentOptions files;  // out_dir, plots
};

// The settings the study sweeps when none are given: iterations at ODE's SOR 1.3 and at 1.0,
// then the exact solver at 1 ms and at 0.5 ms (the reference).
std::vector<std::string> default_settings();

// Runs the study and prints its table; returns the index of the cheapest agreeing setting, -1
// when none agrees. A study where no setting keeps a walk is a completed study (exit 0): it says
// so and writes every table, leaving out only the distance plot, which would have no point.
int run_convergence_study(const ConvergeOptions& o, std::ostream& out);

}  // namespace stride::ensemble
