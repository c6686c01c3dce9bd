// Specialization-constant variants of one pipeline description, built on first use
// (include/snell/toolkit/pipeline_variants.hpp).
#include <snell/toolkit/pipeline_variants.hpp>

namespace snell {

Result<const Pipeline*> PipelineVariants::get(const Context& ctx,
                                              const std::vector<std::uint32_t>& constants) {
  auto found = built_.find(constants);
  if (found == built_.end()) {
    GraphicsPipelineDesc desc = desc_;
    desc.constants = constants;
    Pipeline made;
    SNELL_ASSIGN_OR_RETURN(made, Pipeline::create(ctx, desc));
    found = built_.emplace(constants, std::move(made)).first;
  }
  return &found->second;
}

} // namespace snell
