// Snell plugin-authoring API: everything a plugin needs besides its own shading. A host that
// only creates and runs effects includes snell/effect.hpp (and its plugins' headers) instead.
// See docs/plugins.md.
//
//   snell/effect.hpp                    Effect, FrameInfo, EffectCreateInfo, ParamSchema, registry
//   snell/param_table.hpp               parameters declared once: schema, set, get, validation
//   snell/toolkit/vk_check.hpp          SNELL_VK_TRY, vk_struct, vk_error (VkResult kept in Error)
//   snell/toolkit/descriptors.hpp       DescriptorSets: layout + one set per frame in flight
//   snell/toolkit/effect_factory.hpp    check_create_info, effect_factory: create / register
//   snell/toolkit/uniform_ring.hpp      UniformRing: aligned per-frame uniform blocks
//   snell/pipeline.hpp                  Pipeline: RAII graphics / compute pipelines from SPIR-V
//   snell/toolkit/deferred_release.hpp  DeferredRelease: destruction past the frames in flight
//   snell/toolkit/scaled_target.hpp     ScaledTarget: a target following the output at a scale
//   snell/toolkit/scene_pass.hpp        mirrored / clipped views, scene passes, cube captures
//   snell/toolkit/cube_prefilter.hpp    CubePrefilter: GGX prefiltered cube levels (compute)
//   snell/toolkit/pipeline_variants.hpp PipelineVariants: specialization-constant variants
//   snell/toolkit/screen_rect.hpp       screen_rect: the pixels a world box covers (scissors)
//   snell/toolkit/surfaces.hpp          Surfaces: meshes from scene nodes, arrays or shapes
//   snell/snapshot.hpp                  SceneSnapshot: the frame's opaque colour + depth copy
//   snell/context.hpp, images.hpp, buffer.hpp, gpu_timer.hpp: the runtime's resources
#pragma once

#include <snell/buffer.hpp>
#include <snell/context.hpp>
#include <snell/effect.hpp>
#include <snell/gpu_timer.hpp>
#include <snell/images.hpp>
#include <snell/pipeline.hpp>
#include <snell/snapshot.hpp>
#include <snell/toolkit/cube_prefilter.hpp>
#include <snell/toolkit/deferred_release.hpp>
#include <snell/toolkit/descriptors.hpp>
#include <snell/toolkit/effect_factory.hpp>
#include <snell/toolkit/pipeline_variants.hpp>
#include <snell/toolkit/scaled_target.hpp>
#include <snell/toolkit/scene_pass.hpp>
#include <snell/toolkit/screen_rect.hpp>
#include <snell/toolkit/surfaces.hpp>
#include <snell/toolkit/uniform_ring.hpp>
#include <snell/toolkit/vk_check.hpp>
