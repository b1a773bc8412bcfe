#version 330 core
// One vertex per sprite: world position in mm, an RGBA8 colour and, for a sprite standing for
// several points of one pixel (ui/view/scene/pixel_merge.h), how much shows through it where it
// covers half a pixel.
layout(location = 0) in vec2 a_world_mm;
layout(location = 1) in vec4 a_colour;
layout(location = 2) in float a_half_clear;

uniform vec4 u_ndc;          // xy: scale, zw: offset (world mm -> normalised device coordinates)
uniform float u_point_size;  // diameter in pixels

out vec4 v_colour;
// Alpha by coverage c is c * (x + y * c): exact at c = 0, 1/2 and 1 for a stack of points, and
// a * c for a lone one, without a power per pixel (which cost llvmpipe a third more per point).
flat out vec2 v_rim;

void main() {
  gl_Position = vec4(a_world_mm * u_ndc.xy + u_ndc.zw, 0.0, 1.0);
  gl_PointSize = u_point_size;
  v_colour = a_colour;
  float alpha = a_colour.a;
  float blocked_at_half = 1.0 - (a_half_clear < 0.0 ? 1.0 - 0.5 * alpha : a_half_clear);
  v_rim = vec2(4.0 * blocked_at_half - alpha, 2.0 * alpha - 4.0 * blocked_at_half);
}
