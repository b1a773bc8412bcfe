#version 330 core
// One vertex per sprite: world position in mm, an RGBA8 colour and how many points of one pixel
// it stands for (merged on the CPU, ui/view/scene/pixel_merge.h).
layout(location = 0) in vec2 a_world_mm;
layout(location = 1) in vec4 a_colour;
layout(location = 2) in float a_stack;

uniform vec4 u_ndc;          // xy: scale, zw: offset (world mm -> normalised device coordinates)
uniform float u_point_size;  // diameter in pixels

out vec4 v_colour;
out float v_stack;

void main() {
  gl_Position = vec4(a_world_mm * u_ndc.xy + u_ndc.zw, 0.0, 1.0);
  gl_PointSize = u_point_size;
  v_colour = a_colour;
  v_stack = a_stack;
}
