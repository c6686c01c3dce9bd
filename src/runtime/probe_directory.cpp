// The host's list of published probes (include/snell/probe_directory.hpp).
#include <snell/probe_directory.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace snell {

void ProbeDirectory::publish(const void* owner, const ProbeView& view) {
  for (Entry& e : entries_) {
    if (e.owner == owner) {
      e.view = view;
      return;
    }
  }
  entries_.push_back(Entry{owner, view});
}

void ProbeDirectory::withdraw(const void* owner) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [owner](const Entry& e) { return e.owner == owner; }),
                 entries_.end());
}

void ProbeDirectory::want_levels(const ProbeView* view) {
  for (Entry& e : entries_) {
    if (&e.view == view) {
      e.levels_wanted = true;
    }
  }
}

bool ProbeDirectory::take_levels_wanted(const void* owner) {
  for (Entry& e : entries_) {
    if (e.owner == owner) {
      const bool wanted = e.levels_wanted;
      e.levels_wanted = false;
      return wanted;
    }
  }
  return false;
}

const ProbeView* ProbeDirectory::nearest(const glm::vec3& position) const {
  const ProbeView* best = nullptr;
  float best_distance = std::numeric_limits<float>::infinity();
  for (const Entry& e : entries_) {
    const float d = glm::distance(e.view.center, position);
    if (e.view.publications > 0 && e.view.cube != VK_NULL_HANDLE && d < best_distance) {
      best = &e.view;
      best_distance = d;
    }
  }
  return best;
}

} // namespace snell
