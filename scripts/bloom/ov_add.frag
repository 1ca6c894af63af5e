#version 330 compatibility

// "Overflow light" composite: the colour output plus the blurred overflow, added.
// The screen is 8-bit, so the sum is clamped to 1 there.
uniform sampler2D ColorUnit;
uniform sampler2D BloomUnit;

in vec2 vST;

void main( )
{
    vec3 rgb = texture( ColorUnit, vST ).rgb + texture( BloomUnit, vST ).rgb;
    gl_FragColor = vec4( rgb, 1. );
}
