// What every plugin's creation shares (include/snell/toolkit/effect_factory.hpp).
#include <snell/toolkit/effect_factory.hpp>

#include <string>

namespace snell {

Result<void> check_create_info(const EffectCreateInfo& info, std::string_view effect) {
  const std::string name(effect);
  if (info.context == nullptr) {
    return fail(ErrorCode::invalid_argument, name + ": EffectCreateInfo::context is required");
  }
  if (info.frames_in_flight < 1 || info.frames_in_flight > 16) {
    return fail(ErrorCode::invalid_argument, name + ": EffectCreateInfo::frames_in_flight = " +
                                                 std::to_string(info.frames_in_flight) +
                                                 " is outside [1, 16]");
  }
  return {};
}

} // namespace snell
