#version 120
// Uniforms that start at values of their own (GLSL 1.20 on); WebGL 2 has
// no such initialisers, so the page sets them itself (issue 31).
uniform float uY0 = 1.;
uniform float uSlope = .25f;  // a suffix, as GLSL 1.20 allows
uniform vec3 uTint = vec3(0., .5, 1.);
uniform float uSet;
varying vec2 vST;
void main() { gl_FragColor = vec4(uTint.r + uY0 * uSlope * vST.s, uTint.g, uTint.b * uSet, 1.); }
