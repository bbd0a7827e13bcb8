// Label fragment shader, premultiplied alpha out. u_mode 0: the glyph atlas (R: glyph coverage,
// G: halo coverage), text colour over halo colour. u_mode 1: an icon (premultiplied RGBA) times
// the vertex colour. Texel coordinates are in texels, so the atlas may grow between frames.
#version 330 core
in vec2 v_texel;
in vec4 v_rgba;
in vec4 v_haloRgba;
uniform sampler2D u_texture;
uniform int u_mode;
out vec4 fragColor;
void main() {
  vec2 uv = v_texel / vec2(textureSize(u_texture, 0));
  if (u_mode == 1) {
    fragColor = texture(u_texture, uv) * vec4(v_rgba.rgb * v_rgba.a, v_rgba.a);
    return;
  }
  vec2 coverage = texture(u_texture, uv).rg;
  vec4 text = vec4(v_rgba.rgb * v_rgba.a, v_rgba.a) * coverage.r;
  vec4 halo = vec4(v_haloRgba.rgb * v_haloRgba.a, v_haloRgba.a) * max(coverage.g, coverage.r);
  fragColor = text + halo * (1.0 - text.a);
}
