#version 330 core
// The backdrop picture's own pixel, as it was drawn: same size as the window, so no filtering.
uniform sampler2D u_picture;
out vec4 frag_colour;

void main() {
  frag_colour = texelFetch(u_picture, ivec2(gl_FragCoord.xy), 0);
}
