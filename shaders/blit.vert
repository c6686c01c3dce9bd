#version 460
// Textured rectangle in normalised device coordinates (debug thumbnails, seed 004).
layout(push_constant) uniform Rect {
  vec4 rect; // x0, y0, x1, y1 in NDC
  vec4 params; // x: 1 = depth visualisation
} pc;
layout(location = 0) out vec2 out_uv;
void main() {
  vec2 corner = vec2(gl_VertexIndex & 1, (gl_VertexIndex >> 1) & 1);
  out_uv = corner;
  gl_Position = vec4(mix(pc.rect.xy, pc.rect.zw, corner), 0.0, 1.0);
}
