#pragma once
// `stride run <scene> --ensemble N`: each member's walk and the ensemble's spread, as text.
#include <iosfwd>
#include <vector>

#include "console/ensemble/ensemble_run.hpp"

namespace stride::ensemble {

void print_ensemble(const EnsembleRequest& r, const std::vector<MemberOutcome>& members,
                    std::ostream& out);

}  // namespace stride::ensemble
