// tests/buildsys: library b's blit.frag (same file name as library a's and the runtime's).
// Its colour 0.6875 is its marker; shader_lib_b.cpp's marker() returns the same number.
#version 450
layout(location = 0) out vec4 out_color;
void main() {
  out_color = vec4(0.6875, 0.6875, 0.6875, 1.0);
}
