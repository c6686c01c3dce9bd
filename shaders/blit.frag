#version 460
layout(set = 0, binding = 0) uniform sampler2D source;
layout(push_constant) uniform Rect {
  vec4 rect;
  vec4 params;
} pc;
layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;
void main() {
  vec4 c = textureLod(source, in_uv, pc.params.y); // y: the mip level shown
  if (pc.params.x > 0.5) {
    c = vec4(vec3(pow(c.r, 32.0)), 1.0); // depth: stretch the near range into view
  }
  out_color = vec4(c.rgb, 1.0);
}
