#version 330 core
// A picture kept in a texture (the backdrop, or the sprites drawn on the CPU), laid pixel for pixel:
// its pixel (0, 0) at framebuffer pixel `u_origin`, so no filtering. How it mixes with what lies
// under is the blend state's.
uniform sampler2D u_picture;
uniform ivec2 u_origin;
out vec4 frag_colour;

void main() {
  frag_colour = texelFetch(u_picture, ivec2(gl_FragCoord.xy) - u_origin, 0);
}
