#version 330 core
// Grid lines as thin quads in world mm, with the signed pixel distance from the line's centre.
layout(location = 0) in vec2 a_world_mm;
layout(location = 1) in float a_edge_px;
layout(location = 2) in vec4 a_colour;

uniform vec4 u_ndc;  // xy: scale, zw: offset (world mm -> normalised device coordinates)

out float v_edge_px;
out vec4 v_colour;

void main() {
  gl_Position = vec4(a_world_mm * u_ndc.xy + u_ndc.zw, 0.0, 1.0);
  v_edge_px = a_edge_px;
  v_colour = a_colour;
}
