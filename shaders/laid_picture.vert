#version 330 core
// A box of the viewport in its pixels, bottom-left origin (two triangles a box: ui/render/picture_layer.h).
layout(location = 0) in vec2 a_pixel;
uniform vec2 u_framebuffer_size;  // the viewport's size

void main() {
  gl_Position = vec4(a_pixel / u_framebuffer_size * 2.0 - 1.0, 0.0, 1.0);
}
