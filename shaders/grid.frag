#version 330 core
// Range rings and angle spokes drawn analytically per pixel: exact circles at any zoom, antialiased,
// in one draw call. Also a faint radial glow around the lidar for the dark background.
uniform vec2 u_centre_px;       // viewport centre in window pixels (GL's bottom-up y)
uniform vec2 u_centre_world;    // world mm at that pixel
uniform float u_px_per_mm;
uniform float u_ring_step_mm;
uniform float u_spoke_step_deg;
uniform float u_max_ring_mm;    // no rings beyond the outermost labelled one
uniform vec4 u_ring_colour;
uniform vec4 u_spoke_colour;
uniform vec4 u_glow_colour;
out vec4 frag_colour;

const float kPi = 3.14159265358979;

void main() {
  vec2 world = u_centre_world + (gl_FragCoord.xy - u_centre_px) / u_px_per_mm;
  float r_mm = length(world);
  float r_px = r_mm * u_px_per_mm;

  // Distance in pixels to the nearest ring; every fifth ring is a little stronger.
  float ring_index = floor(r_mm / u_ring_step_mm + 0.5);
  float ring_px = abs(r_mm - ring_index * u_ring_step_mm) * u_px_per_mm;
  float ring = (1.0 - smoothstep(0.4, 1.3, ring_px)) * step(0.5, ring_index) * step(r_mm, u_max_ring_mm + 0.5 * u_ring_step_mm);
  float major = mod(ring_index, 5.0) < 0.5 ? 1.6 : 1.0;

  // Distance in pixels to the nearest spoke, measured across it (arc length at this radius).
  float angle = degrees(atan(world.x, world.y));
  float spoke_delta = abs(angle / u_spoke_step_deg - floor(angle / u_spoke_step_deg + 0.5)) * u_spoke_step_deg;
  float spoke_px = r_px * sin(radians(min(spoke_delta, 45.0)));
  float spoke = (1.0 - smoothstep(0.3, 1.1, spoke_px)) * smoothstep(14.0, 40.0, r_px);

  float glow = exp(-r_px / 260.0) * u_glow_colour.a;

  vec4 c = vec4(u_glow_colour.rgb, glow);
  c = mix(c, vec4(u_spoke_colour.rgb, 1.0), spoke * u_spoke_colour.a);
  c = mix(c, vec4(u_ring_colour.rgb, 1.0), min(ring * u_ring_colour.a * major, 1.0));
  frag_colour = c;
}
