// Snell plugin toolkit: one pipeline description, many specialization-constant variants, each
// built the first time it is asked for. On a CPU device (lavapipe) every branch of a shader
// costs whether it is taken or not, so effects compile out what a surface does not use (glass's
// features, the probe's surface mode, the mirror's roughness and Fresnel) instead of branching on
// uniforms; this keeps the variants of one effect in one place.
#pragma once

#include <snell/pipeline.hpp>
#include <snell/result.hpp>

#include <cstdint>
#include <map>
#include <vector>

namespace snell {

class Context;

/// The variants of `desc` (RAII, move-only; must not outlive the Context). Not thread-safe.
class PipelineVariants {
public:
  PipelineVariants() = default;
  /// `desc`: everything but GraphicsPipelineDesc::constants, which each variant sets.
  explicit PipelineVariants(GraphicsPipelineDesc desc) : desc_(std::move(desc)) {}

  /// The pipeline with specialization constants `constants` (constant_id i = constants[i]),
  /// built on the first call with these values (a shader compile: call it in update(), not per
  /// draw, where a frame may wait for it). The pointer stays valid while this object lives.
  /// Errors: those of Pipeline::create (naming the description's label).
  [[nodiscard]] Result<const Pipeline*> get(const Context& ctx,
                                            const std::vector<std::uint32_t>& constants);
  /// How many variants are built.
  [[nodiscard]] std::size_t size() const { return built_.size(); }

private:
  GraphicsPipelineDesc desc_{};
  std::map<std::vector<std::uint32_t>, Pipeline> built_{};
};

} // namespace snell
