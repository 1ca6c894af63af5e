#version 400 compatibility
void main() { gl_FragColor = vec4(1., .5, 0., 1.); }
