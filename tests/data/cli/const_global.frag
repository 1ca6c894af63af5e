#version 330 compatibility
// A const outside any function set from a uniform: an error in every GLSL
// version, accepted by NVIDIA (tests/cli/nvidia_leniency_test.cpp).
uniform float uK;
const float k2 = uK * 2.;
void main( )
{
    gl_FragColor = vec4( k2, .5, 0., 1. );
}
