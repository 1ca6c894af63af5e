#version 330 compatibility

// The bright pass: texels whose Rec. 709 luma is above uThreshold keep their
// colour, the rest become black.
uniform sampler2D ImageUnit;
uniform float uThreshold;

in vec2 vST;

void main( )
{
    vec3 c = texture( ImageUnit, vST ).rgb;
    float luma = dot( c, vec3( 0.2126, 0.7152, 0.0722 ) );
    gl_FragColor = vec4( luma > uThreshold ? c : vec3( 0. ), 1. );
}
