#version 330 core
// Round point sprites with an antialiased rim and a slightly brighter core, so dense scans read as
// glowing dots rather than squares.
in vec4 v_colour;
flat in vec2 v_rim;
uniform float u_point_size;
out vec4 frag_colour;

void main() {
  vec2 p = gl_PointCoord * 2.0 - 1.0;
  float r = length(p);
  // The rim fades over about one pixel whatever the point size.
  float rim = 2.0 / max(u_point_size, 1.0);
  float coverage = 1.0 - smoothstep(1.0 - rim, 1.0, r);
  if (coverage <= 0.0) discard;
  vec3 core = mix(v_colour.rgb, vec3(1.0), 0.35 * (1.0 - smoothstep(0.0, 0.6, r)));
  // A sprite standing for a stack of points covers what their layers would have, rim included.
  float alpha = clamp(coverage * (v_rim.x + v_rim.y * coverage), 0.0, 1.0);
  frag_colour = vec4(core, alpha);
}
