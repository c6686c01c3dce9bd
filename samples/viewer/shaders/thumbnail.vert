#version 460
// A debug target's thumbnail inside the viewer's UI pass: a rectangle given in normalised
// device coordinates (the UI pass's viewport covers the whole window).
layout(push_constant) uniform Thumb {
  vec4 rect;   // x0, y0, x1, y1 in NDC
  vec4 params; // x: 1 = depth (contrast curve), y: mip level shown
} pc;
layout(location = 0) out vec2 out_uv;
void main() {
  vec2 corner = vec2(gl_VertexIndex & 1, (gl_VertexIndex >> 1) & 1);
  out_uv = corner;
  gl_Position = vec4(mix(pc.rect.xy, pc.rect.zw, corner), 0.0, 1.0);
}
