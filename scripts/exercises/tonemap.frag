#version 330 compatibility

// Exercises 4 and 5: HDR picture + uAdd * blur, then exposure tone mapping
// 1 - exp(-c) and gamma 2.2, as LearnOpenGL's "Bloom" chapter ends.
uniform sampler2D BlurUnit;
uniform sampler2D ImageUnit;
uniform float uAdd;

in vec2 vST;

void main( )
{
    vec3 hdr = texture( ImageUnit, vST ).rgb + uAdd * texture( BlurUnit, vST ).rgb;
    vec3 mapped = vec3( 1. ) - exp( -hdr );
    gl_FragColor = vec4( pow( mapped, vec3( 1. / 2.2 ) ), 1. );
}
