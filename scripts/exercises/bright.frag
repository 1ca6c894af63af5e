#version 330 compatibility

// Exercise 2: the brightness threshold. Texels whose Rec. 709 luminance is above
// uThreshold keep their colour, the rest become black: only they will glow.
uniform sampler2D ImageUnit;
uniform float uThreshold;

in vec2 vST;

void main( )
{
    vec3 c = texture( ImageUnit, vST ).rgb;
    float luminance = dot( c, vec3( 0.2126, 0.7152, 0.0722 ) );
    gl_FragColor = vec4( luminance > uThreshold ? c : vec3( 0. ), 1. );
}
