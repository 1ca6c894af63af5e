#version 330 compatibility
// A local const set from a uniform: NVIDIA accepts it in any version, GLSL
// 4.20 allows it (tests/cli/nvidia_leniency_test.cpp).
uniform float uK;
void main( )
{
    const float k2 = uK * 2.;
    gl_FragColor = vec4( k2, .5, 0., 1. );
}
