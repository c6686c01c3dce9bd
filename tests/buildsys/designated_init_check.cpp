// Compiled (not run) with -Wall -Wextra -Werror as C++20: every public description struct can be
// built with a designated initializer that names only one field. GCC 12's
// -Wmissing-field-initializers fires on every omitted member that has no default member
// initializer, so a field declared `std::vector<T> x;` instead of `std::vector<T> x{};` breaks
// the build of any host that writes `Desc{.field = ...}` with -Wextra -Werror (it broke the
// out-of-tree plugin template once). Add a line here for each new public struct.
#include <snell/buffer.hpp>
#include <snell/builtin_scenes.hpp>
#include <snell/context.hpp>
#include <snell/effect.hpp>
#include <snell/frame.hpp>
#include <snell/glass.hpp>
#include <snell/gpu_timer.hpp>
#include <snell/images.hpp>
#include <snell/pipeline.hpp>
#include <snell/readback.hpp>
#include <snell/result.hpp>
#include <snell/scene.hpp>
#include <snell/scene_source.hpp>
#include <snell/scene_types.hpp>
#include <snell/snapshot.hpp>
#include <snell/toolkit/cube_prefilter.hpp>
#include <snell/toolkit/descriptors.hpp>
#include <snell/toolkit/scaled_target.hpp>
#include <snell/toolkit/scene_pass.hpp>
#include <snell/toolkit/surfaces.hpp>
#include <snell/toolkit/uniform_ring.hpp>
#include <snell/water.hpp>

namespace snell::build_check {

// Each function body only has to compile; nothing calls them.
[[maybe_unused]] void descs() {
  [[maybe_unused]] const BufferDesc buffer{.size = 4};
  [[maybe_unused]] const BrickPattern bricks{.columns = 4};
  [[maybe_unused]] const DeviceInfo device{.name = "x"};
  [[maybe_unused]] const ContextDesc context{.validation = true};
  [[maybe_unused]] const AdoptInfo adopt{.instance = VK_NULL_HANDLE};
  [[maybe_unused]] const DebugTarget debug{.name = "x"};
  [[maybe_unused]] const ParamSpec spec{.name = "x"};
  [[maybe_unused]] const ParamSchema schema{.effect = "x"};
  [[maybe_unused]] const FrameInfo frame_info{.time = 1.0f};
  [[maybe_unused]] const EffectCreateInfo create{.context = nullptr};
  [[maybe_unused]] const FrameDesc frame{.width = 8};
  [[maybe_unused]] const FrameStats stats{.passes = {}};
  [[maybe_unused]] const PassTime pass_time{.name = "x"};
  [[maybe_unused]] const RenderTargetDesc target{.width = 8};
  [[maybe_unused]] const CubeTargetDesc cube{.size = 8};
  [[maybe_unused]] const SamplerDesc sampler{.linear = false};
  [[maybe_unused]] const RasterState raster{.color_formats = {}};
  [[maybe_unused]] const GraphicsPipelineDesc graphics{.label = "x"};
  [[maybe_unused]] const ComputePipelineDesc compute{.label = "x"};
  [[maybe_unused]] const FloatImage float_image{.width = 1};
  [[maybe_unused]] const Error error{.code = ErrorCode::invalid_argument};
  [[maybe_unused]] const Vertex vertex{.position = glm::vec3(0.0f)};
  [[maybe_unused]] const Image image{.name = "x"};
  [[maybe_unused]] const Material material{.name = "x"};
  [[maybe_unused]] const Mesh mesh{.name = "x"};
  [[maybe_unused]] const Object object{.name = "x"};
  [[maybe_unused]] const CameraDesc camera{.name = "x"};
  [[maybe_unused]] const Sky sky{.zenith = glm::vec3(0.0f)};
  [[maybe_unused]] const Anchor anchor{.name = "x"};
  [[maybe_unused]] const Scene scene{.name = "x"};
  [[maybe_unused]] const GltfLimits limits{.max_file_bytes = 1};
  [[maybe_unused]] const SceneView view{.view = glm::mat4(1.0f)};
  [[maybe_unused]] const DirectionalLight light{.direction = glm::vec3(0, -1, 0)};
  [[maybe_unused]] const SnapshotSource source{.color = VK_NULL_HANDLE};
  [[maybe_unused]] const SnapshotDesc snapshot{.color = ColorFormat::rgba8_unorm};
  [[maybe_unused]] const ScaledTargetDesc scaled{.scale = 0.5f};
  [[maybe_unused]] const ScenePass scene_pass{.name = "x"};
  [[maybe_unused]] const CubeCapture capture{.name = "x"};
  [[maybe_unused]] const CubePrefilterDesc prefilter{.samples = 16};
  [[maybe_unused]] const UniformRingDesc ring{.block_size = 16};
  [[maybe_unused]] const DescriptorBinding binding{.binding = 0};
  [[maybe_unused]] const DescriptorSetDesc sets{.bindings = {}};
  [[maybe_unused]] const Surface surface{.vertices = {}};
  [[maybe_unused]] const WaterParams water{.height = 1.0f};
  [[maybe_unused]] const GlassParams glass{.pane = false};
  [[maybe_unused]] const SurfaceBindingsDesc surface_bindings{.block_size = 16};
}

} // namespace snell::build_check
