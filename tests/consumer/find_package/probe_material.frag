#version 460
// A host material compiled against the installed Snell GLSL (consumer.find_package): the
// include must resolve from ${snell_GLSL_INCLUDE_DIR} alone.
#extension GL_GOOGLE_include_directive : require
#include "snell/probe.glsl"

layout(set = 0, binding = 0) uniform samplerCube probe;
layout(location = 0) in vec3 in_normal;
layout(location = 1) in vec3 in_view;
layout(location = 0) out vec4 out_color;

void main() {
  out_color = vec4(probe_reflect(probe, normalize(in_view), normalize(in_normal), 0.0, 1.0), 1.0);
}
