#version 330 core
// One quad over the whole viewport; the fragment shader does all the work.
layout(location = 0) in vec2 aPos;
void main() { gl_Position = vec4(aPos, 0.0, 1.0); }
