#include "console/target/robot_target.hpp"

#include <algorithm>

namespace stride::console {

std::string RobotTarget::Providers::provider_of(const std::string& representation) const {
  const auto it = std::find(representations.begin(), representations.end(), representation);
  return it == representations.end()
             ? ""
             : providers[static_cast<std::size_t>(it - representations.begin())];
}

RobotTarget::Providers RobotTarget::providers() {
  Providers p;
  p.representations = representations();
  for (const std::string& r : p.representations) {
    p.providers.push_back(provider_of(r));
    p.available.push_back(providers_available(r));
  }
  return p;
}

}  // namespace stride::console
