// HUD fragment shader: the vertex colour (blended over the frame by the renderer).
#version 330 core
in vec4 v_rgba;
out vec4 fragColor;
void main() { fragColor = v_rgba; }
