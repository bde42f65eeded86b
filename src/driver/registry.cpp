#include "driver/registry.hpp"

#include "common/error.hpp"

namespace skein {

void Registry::add(std::unique_ptr<Target> target) {
  std::string name = target->name();
  SKEIN_ASSERT(!targets_.contains(name), "each target registers once");
  targets_.emplace(std::move(name), std::move(target));
}

void Registry::add(std::unique_ptr<Simulator> simulator) {
  std::string name = simulator->target();
  SKEIN_ASSERT(!simulators_.contains(name), "one simulator per target");
  simulators_.emplace(std::move(name), std::move(simulator));
}

const Target* Registry::target(const std::string& name) const {
  auto it = targets_.find(name);
  return it == targets_.end() ? nullptr : it->second.get();
}

const Simulator* Registry::simulator_for(const std::string& target_name) const {
  auto it = simulators_.find(target_name);
  return it == simulators_.end() ? nullptr : it->second.get();
}

std::vector<const Target*> Registry::targets() const {
  std::vector<const Target*> out;
  for (const auto& [name, t] : targets_) out.push_back(t.get());
  return out;
}

std::vector<const Simulator*> Registry::simulators() const {
  std::vector<const Simulator*> out;
  for (const auto& [name, s] : simulators_) out.push_back(s.get());
  return out;
}

}  // namespace skein
