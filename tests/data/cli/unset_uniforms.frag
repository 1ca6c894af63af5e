#version 330 compatibility
// Diffuse lighting whose coefficients come from the script: uKa is set on
// the Program line, uKd and uColor are not (tests/cli/unset_uniforms_test.cpp).
uniform float uKa;
uniform float uKd;
uniform vec3  uColor;
in vec2 vST;
void main( )
{
    gl_FragColor = vec4( (uKa + uKd * vST.s) * uColor, 1. );
}
