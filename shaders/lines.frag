#version 330 core
// Antialiased line: full inside half the line width, fading to nothing over the next pixel.
in float v_edge_px;
in vec4 v_colour;
uniform float u_half_width_px;
out vec4 frag_colour;

void main() {
  float coverage = clamp(u_half_width_px + 0.5 - abs(v_edge_px), 0.0, 1.0);
  if (coverage <= 0.0) discard;
  frag_colour = vec4(v_colour.rgb, v_colour.a * coverage);
}
