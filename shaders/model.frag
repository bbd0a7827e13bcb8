// 3D models: their colour (glTF's base colour, times its texture) lit by the frame's light
// (Lambert, both faces, with an ambient share so a wall in shadow still reads), the terrain's
// logarithmic depth.
#version 330 core

in vec3 v_normal;
in vec2 v_uv;
in float v_logDepth;

uniform vec4 u_rgba;
uniform bool u_textured;
uniform sampler2D u_texture;
uniform float u_alphaCutoff;  // glTF's MASK (BLEND drawn as MASK at 0.5); 0: opaque
uniform vec3 u_sunDirection;  // unit, ECEF, towards the light
uniform float u_logDepthScale;

out vec4 fragColor;

void main() {
  gl_FragDepth = log2(v_logDepth) * u_logDepthScale;
  vec4 color = u_rgba;
  if (u_textured) {
    // Texels are stored premultiplied (render/model_renderer.cpp), so mipmaps weigh each colour
    // by its alpha: a leaf's colour, not the black around it.
    vec4 texel = texture(u_texture, v_uv);
    color *= vec4(texel.rgb / max(texel.a, 1.0 / 255.0), texel.a);
    // Mipmaps average a leaf's alpha with the gaps around it: foliage would fade to nothing
    // with distance. Alpha scaled up with the mip level keeps its coverage (Castaño's fix).
    vec2 texels = v_uv * vec2(textureSize(u_texture, 0));
    float level = 0.5 * log2(max(dot(dFdx(texels), dFdx(texels)), dot(dFdy(texels), dFdy(texels))));
    color.a *= 1.0 + max(level, 0.0) * 0.25;
  }
  if (color.a < u_alphaCutoff) discard;
  float lit = abs(dot(normalize(v_normal), u_sunDirection));
  fragColor = vec4(color.rgb * (0.35 + 0.65 * lit), 1.0);
}
