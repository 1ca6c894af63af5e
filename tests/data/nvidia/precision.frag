#version 120
// Written against NVIDIA's driver, which takes OpenGL ES precision statements
// in any version; Mesa refuses them before GLSL 1.30.
precision highp float;
varying mediump vec2 vST;
void main() { gl_FragColor = vec4(vST, 0.0, 1.0); }
