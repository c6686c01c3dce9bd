// tests/buildsys: library a's blit.frag (same file name as library b's and the runtime's).
// Its colour 0.3125 is its marker; shader_lib_a.cpp's marker() returns the same number.
#version 450
layout(location = 0) out vec4 out_color;
void main() {
  out_color = vec4(0.3125, 0.3125, 0.3125, 1.0);
}
