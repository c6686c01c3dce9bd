#version 460
// Shows a debug target as the runtime's own overlay does (shaders/blit.frag): colour as stored
// (linear values, encoded by the sRGB swapchain), depth stretched so the near range shows.
layout(set = 0, binding = 0) uniform sampler2D source;
layout(push_constant) uniform Thumb {
  vec4 rect;
  vec4 params;
} pc;
layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;
void main() {
  vec4 c = textureLod(source, in_uv, pc.params.y);
  if (pc.params.x > 0.5) {
    c = vec4(vec3(pow(c.r, 32.0)), 1.0);
  }
  out_color = vec4(clamp(c.rgb, 0.0, 1.0), 1.0);
}
